/* swt_progress.h - what a long run tells its user before and while it works:
 * an estimate of its time before it starts and a progress line.
 *
 * Lifecycle: swt_pilot_cost (seconds per impact, measured on a few impacts
 * of the run's own grid), then swt_progress_alloc with the run's work in
 * impacts, swt_progress_add from any thread as impacts are done, and
 * swt_progress_free, which ends the line. Everything goes to stderr:
 *  - the estimate, once, when the run is expected to take at least
 *    SWT_PROGRESS_MIN_S seconds;
 *  - the progress line (percent, elapsed, time left), at most once a second,
 *    rewritten in place on a terminal; when stderr is not a terminal only
 *    with mode SWT_PROGRESS_ON (the commands' --progress), then as one line
 *    every 10 seconds;
 *  - with SWT_PROGRESS_ON, the estimate and the final line (impacts, time)
 *    whatever the length of the run.
 * Thread-safe: swt_progress_add counts with C11 atomics and one thread at a
 * time prints. */
#ifndef SWT_PROGRESS_H
#define SWT_PROGRESS_H

#include "swr_collide.h"
#include "swt_map.h"
#include "swt_vcrit.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A run expected to take less than this [s] prints neither estimate nor line. */
#define SWT_PROGRESS_MIN_S 2.0

typedef enum { SWT_PROGRESS_AUTO = 0, SWT_PROGRESS_ON, SWT_PROGRESS_OFF } swt_progress_mode;

typedef struct swt_progress swt_progress;

/* Wall time of one kernel impact [s], the mean over a few (d, v_n) of the
 * grid g (diameters and speeds spread over it; on a rough wall at impact
 * points of o's seed) with o's tangential speed and spin: the pilot of the
 * estimate (about 1 ms on a rough wall). 0 when the kernel refuses an impact
 * (the run itself then reports it). */
double swt_pilot_cost(const swr_model *m, const swt_grid *g, const swt_vcrit_opts *o);

/* Start the report of a run of `total` impacts expected to take `estimate`
 * seconds on `threads` threads. `what` names the command ("snowregime map")
 * and `unit` what is counted ("impacts"). Prints the estimate (when at least
 * SWT_PROGRESS_MIN_S). NULL when out of memory (the run goes on without). */
swt_progress *swt_progress_alloc(const char *what, const char *unit, double total,
                                 double estimate, int threads, swt_progress_mode mode);
/* Count `done` more units (thread-safe; NULL does nothing). */
void swt_progress_add(swt_progress *pg, long done);
/* End: when a line was printed, print the final one with the elapsed time. */
void swt_progress_free(swt_progress *pg);

/* "about 48 min" style text of a duration [s] into buf. */
const char *swt_duration_text(double seconds, char *buf, size_t len);

#ifdef __cplusplus
}
#endif
#endif
