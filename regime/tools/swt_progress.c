/* swt_progress.c - the estimate before a long run and its progress line (see
 * swt_progress.h). */
#include "swt_progress.h"

#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_rng.h>

#include "swt_io.h"

/* impacts of the pilot: a 4 x 4 lattice of cells of the grid, two impact
 * points each on a rough wall */
#define PILOT_SIDE 4

double swt_pilot_cost(const swr_model *m, const swt_grid *g, const swt_vcrit_opts *o)
{
    const int rough = swr_model_rough(m);
    double lx = 0.0, ly = 0.0;
    swr_model_sample_area(m, &lx, &ly);
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    if (!r)
        return 0.0;
    gsl_rng_set(r, o->seed);
    int n = 0;
    const double t0 = swt_now();
    for (int i = 0; i < PILOT_SIDE; i++) {
        for (int j = 0; j < PILOT_SIDE; j++) {
            const double fi = (i + 0.5) / PILOT_SIDE, fj = (j + 0.5) / PILOT_SIDE;
            const double d = g->dmin + fi * (g->dmax - g->dmin);
            const double vn = g->vlog ? g->vmin * pow(g->vmax / g->vmin, fj)
                                      : g->vmin + fj * (g->vmax - g->vmin);
            for (int k = 0; k < (rough ? 2 : 1); k++) {
                swr_impact in = { .d = d, .vn = vn,
                                  .vt = o->tan_angle > 0.0 ? vn * o->tan_angle : o->vt,
                                  .omega = o->omega };
                if (rough) {
                    in.x = lx * gsl_rng_uniform(r);
                    in.y = ly * gsl_rng_uniform(r);
                }
                swr_result res;
                memset(&res, 0, sizeof res);
                if (swr_collide(m, &in, &res, NULL) == SWR_EINVAL) {
                    gsl_rng_free(r);
                    return 0.0;
                }
                n++;
            }
        }
    }
    gsl_rng_free(r);
    return n > 0 ? (swt_now() - t0) / n : 0.0;
}

const char *swt_duration_text(double s, char *buf, size_t len)
{
    if (!(s < 1e12))
        snprintf(buf, len, "more than 30 000 years");
    else if (s < 90.0)
        snprintf(buf, len, "%.0f s", s);
    else if (s < 5400.0)
        snprintf(buf, len, "%.0f min", s / 60.0);
    else if (s < 2.0 * 86400.0)
        snprintf(buf, len, "%.1f h", s / 3600.0);
    else
        snprintf(buf, len, "%.0f days", s / 86400.0);
    return buf;
}

struct swt_progress {
    char what[64], unit[32];
    double total, estimate, t0;
    int show;                 /* progress lines at all */
    int tty;                  /* rewrite in place (\r) */
    int printed;              /* a line was printed */
    atomic_llong done;        /* units done */
    _Atomic double next;      /* time of the next line */
    atomic_flag busy;         /* one printer at a time */
};

swt_progress *swt_progress_alloc(const char *what, const char *unit, double total,
                                 double estimate, int threads, swt_progress_mode mode)
{
    swt_progress *pg = calloc(1, sizeof *pg);
    if (!pg)
        return NULL;
    snprintf(pg->what, sizeof pg->what, "%s", what);
    snprintf(pg->unit, sizeof pg->unit, "%s", unit);
    pg->total = total;
    pg->estimate = estimate;
    pg->t0 = swt_now();
    pg->tty = isatty(STDERR_FILENO);
    /* asked for (ON): the estimate and the last line whatever the length */
    const int long_run = estimate >= SWT_PROGRESS_MIN_S || mode == SWT_PROGRESS_ON;
    pg->show = long_run && mode != SWT_PROGRESS_OFF && (pg->tty || mode == SWT_PROGRESS_ON);
    pg->printed = mode == SWT_PROGRESS_ON;
    atomic_init(&pg->done, 0);
    atomic_init(&pg->next, pg->t0 + (pg->tty ? 1.0 : 10.0));
    atomic_flag_clear(&pg->busy);
    if (long_run && mode != SWT_PROGRESS_OFF) {
        char b[48];
        fprintf(stderr, "%s: about %s for %.3g %s on %d thread%s (estimated from a pilot of a few "
                "impacts)\n", what, swt_duration_text(estimate, b, sizeof b), total, unit, threads,
                threads == 1 ? "" : "s");
        fflush(stderr);
    }
    return pg;
}

void swt_progress_add(swt_progress *pg, long done)
{
    if (!pg)
        return;
    atomic_fetch_add(&pg->done, (long long)done);
    if (!pg->show)
        return;
    const double now = swt_now();
    if (now < atomic_load(&pg->next) || atomic_flag_test_and_set(&pg->busy))
        return;
    atomic_store(&pg->next, now + (pg->tty ? 1.0 : 10.0));
    const double d = (double)atomic_load(&pg->done), el = now - pg->t0;
    const double f = pg->total > 0.0 ? d / pg->total : 0.0;
    char be[48], bl[48];
    swt_duration_text(el, be, sizeof be);
    if (f > 0.0 && f < 1.0)
        swt_duration_text(el * (1.0 - f) / f, bl, sizeof bl);
    else
        snprintf(bl, sizeof bl, "?");
    fprintf(stderr, "%s%s: %3.0f %% (%.3g of %.3g %s), %s, about %s left%s", pg->tty ? "\r" : "",
            pg->what, 100.0 * (f < 1.0 ? f : 1.0), d, pg->total, pg->unit, be, bl,
            pg->tty ? "   " : "\n");
    fflush(stderr);
    pg->printed = 1;
    atomic_flag_clear(&pg->busy);
}

void swt_progress_free(swt_progress *pg)
{
    if (!pg)
        return;
    if (pg->printed) {
        char b[48];
        fprintf(stderr, "%s%s: done, %.3g %s in %s%s\n", pg->tty ? "\r" : "", pg->what,
                (double)atomic_load(&pg->done), pg->unit, swt_duration_text(swt_now() - pg->t0, b, sizeof b),
                pg->tty ? "                    " : "");
    }
    free(pg);
}
