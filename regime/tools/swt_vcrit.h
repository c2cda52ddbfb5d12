/* swt_vcrit.h - critical normal sticking velocity of one diameter.
 *
 * The outcome at normal speed v ("sticks": the normal contact is kept, or,
 * with full_stick, contact kept AND sliding and rolling arrested) is scanned
 * over [vmin, vmax] at log-spaced points (ratio scan_ratio) to find the first
 * stick -> bounce change and to detect a non-monotone outcome (more than one
 * change); the bracket is then bisected in log(v) until v_hi / v_lo <= 1 + rtol.
 * v_crit is the geometric mean of the final bracket: |v_crit - v*| / v* <= rtol / 2
 * for the first change v* (to the kernel's accuracy).
 */
#ifndef SWT_VCRIT_H
#define SWT_VCRIT_H

#include "swr_collide.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double vmin, vmax;    /* search range of the normal speed [m/s], 0 < vmin < vmax */
    double rtol;          /* relative bracket width at the end (default 1e-3) */
    double scan_ratio;    /* ratio of neighbouring scan points, > 1 (default 2) */
    int full_stick;       /* 1: outcome = full stick; 0: normal contact kept */
    double vt;            /* tangential speed [m/s] of every impact */
    double tan_angle;     /* if > 0: vt = vn * tan_angle instead (fixed impact angle) */
    double omega;         /* initial spin [rad/s] */
    double max_slide;     /* > 0: "sticks" = full stick AND the predicted travel along the
                             wall until rest (swr_result.s_rest) <= max_slide [m]; 0: off */
    /* rough wall (wall lattice): "sticks" at (d, v_n) = the stick fraction over
     * `points` impact points is >= level. The points are uniform over the
     * wall's sample area (swr_model_sample_area), drawn by GSL's mt19937 from
     * `seed`: the same points at every (d, v_n) (common random numbers, so the
     * fraction changes only where an impact point's outcome does). */
    int points;           /* impact points per (d, v_n) (default 64) */
    unsigned long seed;   /* seed of the impact points (default 1) */
    double level;         /* stick probability of the interface (default 0.5) */
} swt_vcrit_opts;

/* Stick fraction of one (d, v_n) on a rough wall. */
typedef struct {
    int points, sticks;   /* impact points, and how many stick */
    int bound;            /* impacts that ended on a bound (status SWR_STEP_BOUND) */
    double e_n;           /* mean normal COR of the bounces (0: none) */
    long steps;           /* integration steps */
    long contacts;        /* contacts made */
} swt_fraction;

typedef enum {
    SWT_VCRIT_FOUND = 0,     /* bracketed and bisected */
    SWT_VCRIT_NO_STICK,      /* bounces over the whole range: v_crit < vmin */
    SWT_VCRIT_ALL_STICK,     /* sticks over the whole range: v_crit > vmax */
    SWT_VCRIT_ERROR          /* kernel rejected the input (msg) */
} swt_vcrit_status;

typedef struct {
    swt_vcrit_status status;
    double vcrit;         /* FOUND: the estimate; NO_STICK: vmin; ALL_STICK: vmax */
    double v_lo, v_hi;    /* final bracket (sticks at v_lo, bounces at v_hi) */
    int changes;          /* stick/bounce changes seen in the scan (1 when monotone) */
    double v_restick;     /* first velocity above v_crit where it sticks again (0: none) */
    long collisions;      /* kernel calls */
    long steps;           /* total integration steps */
    long step_bound;      /* calls that ended on the step bound */
    double dt_min, dt_max;/* range of the time steps used [s] */
    char msg[200];        /* kernel warning (e.g. Tabor) or error */
} swt_vcrit_result;

void swt_vcrit_opts_default(swt_vcrit_opts *o);
/* The outcome of one kernel result under the options: 1 sticks, 0 not. */
int swt_outcome(const swt_vcrit_opts *o, const swr_result *res);
/* Does diameter d stick at normal speed vn? Returns 1/0, or -1 on a kernel
 * error (message copied to msg). Accumulates counters into r when not NULL.
 * On a rough wall: does the stick count over o->points impact points reach
 * o->level; the points run in their fixed order and the run stops as soon as
 * the points left cannot change the answer (the same answer as the whole
 * count, from fewer impacts). */
int swt_sticks(const swr_model *m, double d, double vn, const swt_vcrit_opts *o,
               swt_vcrit_result *r, char *msg, size_t msglen);
/* Rough wall: does a stick count of `sticks` of `points` reach the level?
 * The one criterion of the grid, the contours and the v_crit search. */
static inline int swt_fraction_sticks(int sticks, int points, double level)
{
    return sticks >= level * points;
}

/* Rough wall: the stick fraction at (d, vn) over o->points impact points.
 * 0, or -1 on a kernel error (message in msg). Accumulates r's counters. */
int swt_stick_fraction(const swr_model *m, double d, double vn, const swt_vcrit_opts *o,
                       swt_fraction *f, swt_vcrit_result *r, char *msg, size_t msglen);
/* The search for diameter d with the kernel. Returns r->status. */
swt_vcrit_status swt_vcrit(const swr_model *m, double d, const swt_vcrit_opts *o,
                           swt_vcrit_result *r);
/* The same search on any outcome function: sticks(ctx, v, r) returns 1 (sticks),
 * 0 (does not) or -1 (error, message in r->msg); it may update r's counters.
 * Uses o->vmin, vmax, rtol, scan_ratio only. */
swt_vcrit_status swt_vcrit_search(int (*sticks)(void *ctx, double v, swt_vcrit_result *r),
                                  void *ctx, const swt_vcrit_opts *o, swt_vcrit_result *r);

#ifdef __cplusplus
}
#endif
#endif
