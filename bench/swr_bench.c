/* swr_bench.c - timings of the regime kernel and tools (run by bench/regime.sh).
 *
 * Usage: swr_bench [--reps N] [--threads N] [--set KEY=VALUE]...
 * Prints medians over N repetitions (default 7) of:
 *   - one collision (mean over a batch of impacts around v_crit, d 10..100 um),
 *   - v_crit for 46 diameters (10..100 um, tolerance 1e-3),
 *   - the 46 x 50 map (grid + interface refinement, the speed range fixed
 *     beforehand as snowregime map chooses it),
 * the accuracy of v_crit at the accuracy setting used (against accuracy 30720),
 * and the lowest accuracy setting with v_crit within 0.1 % with its collision time.
 * Not a test: it prints figures, it asserts nothing.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sw_bench.h"
#include "swr_collide.h"
#include "swr_params.h"
#include "swt_io.h"
#include "swt_map.h"
#include "swt_vcrit.h"


typedef struct { const swr_model *m; const swt_vcrit_opts *o; const double *d; double *vc; } vc_ctx;
static void vc_one(void *p, int k)
{
    vc_ctx *c = p;
    swt_vcrit_result r;
    swt_vcrit(c->m, c->d[k], c->o, &r);
    c->vc[k] = r.vcrit;
}

#define REF_ACCURACY 30720.0   /* 16 x the largest setting tried */

/* mean wall time of one collision over impacts at 0.5, 0.9, 1.1, 2 x v_crit of
 * every diameter (repeated for at least 50 ms); median over reps */
static double time_collisions(const swr_model *m, const double *d, const double *vc, int nd,
                              int reps, double *steps_mean, double *cpu_median)
{
    static const double f[4] = { 0.5, 0.9, 1.1, 2.0 };
    double t[1000], tc[1000];
    long steps = 0, ncoll = 0;
    for (int r = 0; r < reps; r++) {
        int n = 0;
        double t0 = swt_now(), c0 = swt_thread_cpu();
        do {
            for (int i = 0; i < nd; i++)
                for (int k = 0; k < 4; k++) {
                    swr_impact in = { d[i], f[k] * vc[i], 0.0, 0.0, 0.0, 0.0 };
                    swr_result res;
                    swr_collide(m, &in, &res, NULL);
                    if (r == 0 && n < 4 * nd) { steps += res.steps; ncoll++; }
                    n++;
                }
        } while (swt_now() - t0 < 0.05);
        t[r] = (swt_now() - t0) / n;
        tc[r] = (swt_thread_cpu() - c0) / n;
    }
    *steps_mean = (double)steps / (double)ncoll;
    *cpu_median = sw_bench_median(tc, reps);
    return sw_bench_median(t, reps);
}

/* max relative error of v_crit at 3 diameters against the reference values */
static double vcrit_error(const swr_model *m, const double *dd, const double *vref,
                          const swt_vcrit_opts *o)
{
    double e = 0.0;
    for (int k = 0; k < 3; k++) {
        swt_vcrit_result a;
        swt_vcrit(m, dd[k], o, &a);
        if (a.status != SWT_VCRIT_FOUND || !isfinite(vref[k])) return INFINITY;
        e = fmax(e, fabs(a.vcrit / vref[k] - 1.0));
    }
    return e;
}

int main(int argc, char **argv)
{
    int reps = 7, threads = 2;
    swr_params p;
    swr_params_default(&p);
    char err[400];
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--reps") == 0 && i + 1 < argc) reps = atoi(argv[++i]);
        else if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc) threads = atoi(argv[++i]);
        else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
            if (swr_params_set_kv(&p, argv[++i], err, sizeof err) != 0) {
                fprintf(stderr, "swr_bench: --set: %s\n", err);
                return 2;
            }
        } else if (strcmp(argv[i], "--help") == 0) {
            puts("usage: swr_bench [--reps N] [--threads N] [--set KEY=VALUE]...  (see bench/regime.sh)");
            return 0;
        } else {
            fprintf(stderr, "swr_bench: unknown option '%s'\n", argv[i]);
            return 2;
        }
    }
    if (reps < 1 || reps > 1000 || threads < 1 || threads > 64) {
        fprintf(stderr, "swr_bench: --reps 1..1000, --threads 1..64\n");
        return 2;
    }
    if (swr_params_validate(&p, err, sizeof err) != 0) { fprintf(stderr, "swr_bench: %s\n", err); return 2; }
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m) { fprintf(stderr, "swr_bench: %s\n", err); return 2; }

    enum { ND = 46 };
    double d[ND], vc[ND], t[1000];
    for (int i = 0; i < ND; i++) d[i] = 10e-6 + 90e-6 * i / (ND - 1);
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    o.vmax = SWR_V_MAX; /* every speed the kernel accepts (some laws stick up to ~800 m/s) */

    /* v_crit of 46 diameters */
    vc_ctx c = { m, &o, d, vc };
    for (int r = 0; r < reps; r++) {
        double t0 = swt_now();
        swt_parallel_for(ND, threads, vc_one, &c);
        t[r] = swt_now() - t0;
    }
    double t_vcrit = sw_bench_median(t, reps);

    /* one collision: impacts at 0.5, 0.9, 1.1, 2 v_crit for every diameter */
    double steps_mean = 0.0, c_coll = 0.0;
    double t_coll = time_collisions(m, d, vc, ND, reps, &steps_mean, &c_coll);

    /* accuracy of v_crit at this setting: against a much finer step */
    char txt[32];
    swr_params pf = p;
    snprintf(txt, sizeof txt, "%.10g", REF_ACCURACY);
    swr_model *mref = NULL;
    if (swr_params_set(&pf, "accuracy", txt, err, sizeof err) == 0)
        mref = swr_model_alloc(&pf, err, sizeof err);
    if (!mref) { fprintf(stderr, "swr_bench: reference model: %s\n", err); return 1; }
    double vref[3];
    const double dd[3] = { 10e-6, 30e-6, 100e-6 };
    swt_vcrit_opts of = o;
    of.rtol = 1e-7;
    for (int k = 0; k < 3; k++) {
        swt_vcrit_result b;
        swt_vcrit(mref, dd[k], &of, &b);
        vref[k] = b.status == SWT_VCRIT_FOUND ? b.vcrit : NAN;
    }
    swr_model_free(mref);
    double acc_err = vcrit_error(m, dd, vref, &of);

    /* the lowest accuracy setting (of a list) with v_crit within 0.1 %, and one
     * collision there */
    static const double accs[] = { 10, 15, 20, 30, 45, 60, 90, 120, 180, 240, 360, 480, 720, 960, 1440, 1920 };
    double acc01 = 0.0, err01 = 0.0, t_coll01 = 0.0, steps01 = 0.0, c_coll01 = 0.0;
    for (size_t k = 0; k < sizeof accs / sizeof accs[0]; k++) {
        swr_params pa = p;
        snprintf(txt, sizeof txt, "%.10g", accs[k]);
        if (swr_params_set(&pa, "accuracy", txt, err, sizeof err) != 0) break;
        swr_model *ma = swr_model_alloc(&pa, err, sizeof err);
        if (!ma) break;
        double e = vcrit_error(ma, dd, vref, &of);
        if (e <= 1e-3) {
            double vca[ND];
            vc_ctx ca = { ma, &o, d, vca };
            swt_parallel_for(ND, threads, vc_one, &ca);
            acc01 = accs[k];
            err01 = e;
            t_coll01 = time_collisions(ma, d, vca, ND, reps, &steps01, &c_coll01);
            swr_model_free(ma);
            break;
        }
        swr_model_free(ma);
    }

    /* the 46 x 50 map, speed range as snowregime map chooses it */
    swt_grid g = { 46, 50, 10e-6, 100e-6, vc[ND - 1] / 1.5, fmin(1.5 * vc[0], SWR_V_MAX), 1 };
    double tg[1000], tt[1000];
    long nstick = 0;
    for (int r = 0; r < reps; r++) {
        swt_map *mp = swt_map_alloc(&g, err, sizeof err);
        if (!mp) { fprintf(stderr, "swr_bench: %s\n", err); return 1; }
        swt_interface it;
        double t0 = swt_now();
        swt_map_run(mp, m, &o, threads, err, sizeof err);
        double t1 = swt_now();
        swt_interface_extract(mp, m, &o, 1, threads, &it, err, sizeof err);
        tt[r] = swt_now() - t0;
        tg[r] = t1 - t0;
        nstick = mp->nstick;
        swt_interface_free(&it);
        swt_map_free(mp);
    }
    double t_grid = sw_bench_median(tg, reps), t_map = sw_bench_median(tt, reps);

    printf("swr_bench: %d repetitions, %d threads, accuracy %g steps per contact time\n",
           reps, threads, p.accuracy);
    printf("collision_us %.4g\n", 1e6 * t_coll);
    printf("collision_cpu_us %.4g\n", 1e6 * c_coll);
    printf("collision_steps_mean %.1f\n", steps_mean);
    printf("vcrit_rel_error_max %.3g\n", acc_err);
    printf("accuracy_for_0.1pct %g\n", acc01);
    printf("vcrit_rel_error_at_it %.3g\n", err01);
    printf("collision_us_at_0.1pct %.4g\n", 1e6 * t_coll01);
    printf("collision_cpu_us_at_0.1pct %.4g\n", 1e6 * c_coll01);
    printf("collision_steps_at_0.1pct %.1f\n", steps01);
    printf("vcrit46_ms %.4g\n", 1e3 * t_vcrit);
    printf("map_grid_ms %.4g\n", 1e3 * t_grid);
    printf("map_total_ms %.4g\n", 1e3 * t_map);
    printf("map_sticking_points %ld\n", nstick);
    printf("map_vrange %.4g %.4g\n", g.vmin, g.vmax);
    swr_model_free(m);
    return 0;
}
