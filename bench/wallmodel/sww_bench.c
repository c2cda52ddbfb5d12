/* sww_bench.c - cost of one sww_decide call (wall-model C core), gates off and on.
 *
 * Usage: sww_bench [--help] [--calls N] [--repeats R] REGIME_FILE
 *
 * Decides N impacts (default 1e6) with diameters 1-200 um and normal speeds
 * 0.01-30 m/s (inside and outside the fit range) R times (default 7) for each
 * configuration and prints the median time per call in ns: gates off, the
 * constant tangential gate, with the adhesion shear gate, and, when the file
 * has the oblique table (snowregime map --vt 0,...), the regime tangential
 * gate alone; and sww_decide_blend with a half-covered face (the file as both
 * regimes). When the file has no stick-probability table (rough wall), the
 * same map with a synthetic one of snowregime map's default grid (46
 * diameters 10-100 um linear x 50 speeds 0.1-10 m/s log; p a logistic step
 * across the file's interface) against the sharp map, gates off: over the
 * impacts above and over impacts all inside the table. When the file has the
 * kernel's rebound tables (snowregime map), gates off with them
 * against the classic rebound (Thornton / constant e_n, reboundTangential).
 * Exit 2 on bad input.
 */
#include "sw_bench.h"
#include "sww.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* Median ns per call of sww_decide (cov NULL) or sww_decide_blend(m, cov, w). */
static double run_blend(const sww_model *m, const sww_model *cov, double w, const sww_impact *in,
                        long n, int reps, long *fates)
{
    double t[64];
    for (int r = 0; r < reps; r++) {
        long f[3] = { 0, 0, 0 };
        const double t0 = sw_bench_now();
        for (long i = 0; i < n; i++) {
            sww_outcome o;
            if ((cov ? sww_decide_blend(m, cov, w, &in[i], &o) : sww_decide(m, &in[i], &o)) == SWW_OK)
                f[o.fate]++;
        }
        t[r] = (sw_bench_now() - t0) / n * 1e9;
        memcpy(fates, f, sizeof f);
    }
    return sw_bench_median(t, reps);
}

static double run(const sww_model *m, const sww_impact *in, long n, int reps, long *fates)
{
    return run_blend(m, NULL, 0.0, in, n, reps, fates);
}

int main(int argc, char **argv)
{
    long n = 1000000;
    int reps = 7;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            puts("Usage: sww_bench [--help] [--calls N] [--repeats R] REGIME_FILE\n\n"
                 "Median time per sww_decide call [ns] for N impacts (default 1000000),\n"
                 "R repeats (default 7, at most 63): gates off, tangential gate on,\n"
                 "both gates on (adhesion shear gate), the regime tangential gate\n"
                 "when the file has the oblique table, the build-up blend, and a\n"
                 "synthetic stick-probability table (46 x 50) against the sharp map\n"
                 "when the file has none. Exit status 2 on bad input.");
            return 0;
        }
        if ((!strcmp(argv[i], "--calls") || !strcmp(argv[i], "--repeats")) && i + 1 < argc) {
            char *e;
            const long v = strtol(argv[i + 1], &e, 10);
            if (*e || v < 1 || (argv[i][2] == 'r' && v > 63)) {
                fprintf(stderr, "sww_bench: %s: bad value '%s'\n", argv[i], argv[i + 1]);
                return 2;
            }
            if (argv[i][2] == 'c')
                n = v;
            else
                reps = (int)v;
            i++;
            continue;
        }
        if (argv[i][0] == '-' || path) {
            fprintf(stderr, "sww_bench: unexpected argument '%s' (see --help)\n", argv[i]);
            return 2;
        }
        path = argv[i];
    }
    if (!path) {
        fprintf(stderr, "sww_bench: missing REGIME_FILE (see --help)\n");
        return 2;
    }
    sww_model *m = sww_alloc();
    sww_impact *in = malloc(n * sizeof *in);
    if (!m || !in) {
        fprintf(stderr, "sww_bench: out of memory\n");
        return 1;
    }
    if (sww_regime_load(m, path) != SWW_OK) {
        fprintf(stderr, "sww_bench: %s\n", sww_errmsg(m));
        return 2;
    }
    unsigned s = 12345;
    for (long i = 0; i < n; i++) {
        s = s * 1103515245u + 12345u;
        const double a = (s >> 8) / 16777216.0;
        s = s * 1103515245u + 12345u;
        const double b = (s >> 8) / 16777216.0;
        in[i] = (sww_impact){ .d = 1e-6 + 199e-6 * a, .vn = 0.01 * pow(3000.0, b),
                              .vt = 3.0 * a * b, .tau_w = 5.0 * b, .u = a };
    }
    long f[3];
    printf("sww_bench: %ld calls, median of %d repeats\n", n, reps);
    double t = run(m, in, n, reps, f);
    printf("gates off:          %6.1f ns/call  (stick %ld bounce %ld ripoff %ld)\n", t, f[0], f[1], f[2]);
    sww_set_tangential_gate(m, 1.0, 5e-5, -0.5);
    t = run(m, in, n, reps, f);
    printf("tangential gate:    %6.1f ns/call  (stick %ld bounce %ld ripoff %ld)\n", t, f[0], f[1], f[2]);
    if (sww_set_shear_gate_adhesion(m, 0.05) == SWW_OK) {
        t = run(m, in, n, reps, f);
        printf("tangential + shear: %6.1f ns/call  (stick %ld bounce %ld ripoff %ld)\n", t, f[0], f[1], f[2]);
    }
    /* the build-up blend with a face half covered (two decisions per call),
     * the covered regime a second copy of the file, gates off */
    sww_model *c = sww_alloc();
    if (c && sww_regime_load(c, path) == SWW_OK) {
        sww_set_tangential_off(m);
        sww_set_shear_off(m);
        const double tb = run_blend(m, c, 0.5, in, n, reps, f);
        printf("build-up blend w 0.5: %6.1f ns/call  (stick %ld bounce %ld ripoff %ld)\n", tb,
               f[0], f[1], f[2]);
    }
    sww_free(c);
    /* the rough wall's probability table against the sharp map */
    size_t pnd, pnv;
    if (sww_probability_table(m, &pnd, &pnv)) {
        printf("(the file has a stick-probability table %zu x %zu: every line above uses it)\n",
               pnd, pnv);
    } else {
        enum { ND = 46, NV = 50 };
        static double pd[ND], pv[NV], pp[ND * NV];
        for (int i = 0; i < ND; i++)
            pd[i] = 10e-6 + 90e-6 * i / (ND - 1);
        for (int j = 0; j < NV; j++)
            pv[j] = 0.1 * pow(100.0, (double)j / (NV - 1));
        for (int i = 0; i < ND; i++)
            for (int j = 0; j < NV; j++)
                pp[i * NV + j] = 1.0 / (1.0 + exp(log(pd[i] / sww_dcrit(m, pv[j])) / 0.3));
        sww_model *r = sww_alloc();
        if (r && sww_regime_load(r, path) == SWW_OK
            && sww_regime_list(r, "probabilityD", pd, ND) == SWW_OK
            && sww_regime_list(r, "probabilityVn", pv, NV) == SWW_OK
            && sww_regime_list(r, "probabilityStick", pp, ND * NV) == SWW_OK
            && sww_regime_commit(r, "sww_bench") == SWW_OK) {
            sww_set_tangential_off(m);
            sww_set_shear_off(m);
            long inside = 0;
            for (long i = 0; i < n; i++)
                inside += in[i].d >= pd[0] && in[i].d <= pd[ND - 1] && in[i].vn >= pv[0]
                          && in[i].vn <= pv[NV - 1];
            long fs[3], fr[3];
            const double ts = run(m, in, n, reps, fs), tr = run(r, in, n, reps, fr);
            printf("probability table %d x %d, gates off: sharp %6.1f ns/call, table %6.1f ns/call "
                   "(%.0f %% of the impacts inside; stick %ld / %ld)\n", ND, NV, ts, tr,
                   100.0 * inside / n, fs[0], fr[0]);
            /* the same number of impacts, every one inside the table */
            sww_impact *ins = malloc(n * sizeof *ins);
            if (ins) {
                for (long i = 0; i < n; i++) {
                    ins[i] = in[i];
                    ins[i].d = pd[0] * pow(pd[ND - 1] / pd[0], in[i].u);
                    ins[i].vn = pv[0] * pow(pv[NV - 1] / pv[0], in[(i + 1) % n].u);
                }
                const double ts2 = run(m, ins, n, reps, fs), tr2 = run(r, ins, n, reps, fr);
                printf("probability table %d x %d, gates off: sharp %6.1f ns/call, table %6.1f ns/call "
                       "(every impact inside; stick %ld / %ld)\n", ND, NV, ts2, tr2, fs[0], fr[0]);
                free(ins);
            }
        } else {
            fprintf(stderr, "sww_bench: synthetic probability table: %s\n", r ? sww_errmsg(r) : "out of memory");
        }
        sww_free(r);
    }
    size_t nvt, nvn;
    if (sww_oblique_table(m, &nvt, &nvn)) {
        sww_set_shear_off(m);
        sww_set_tangential_regime(m);
        t = run(m, in, n, reps, f);
        printf("regime gate (%zu x %zu): %6.1f ns/call  (stick %ld bounce %ld ripoff %ld)\n", nvt, nvn,
               t, f[0], f[1], f[2]);
    }
    size_t rd, rv, rt;
    if (sww_rebound_table(m, &rd, &rv, &rt)) {
        sww_set_tangential_off(m);
        sww_set_shear_off(m);
        sww_set_rebound_model(m, SWW_REBOUND_CLASSIC);
        const double tc = run(m, in, n, reps, f);
        sww_set_rebound_model(m, SWW_REBOUND_TABLE);
        t = run(m, in, n, reps, f);
        printf("rebound, gates off: classic %6.1f ns/call, kernel table %zu x %zu x %zu %6.1f ns/call "
               "(bounce %ld of %ld)\n", tc, rt, rd, rv, t, f[1], n);
        sww_set_rebound_model(m, SWW_REBOUND_AUTO);
    }
    free(in);
    sww_free(m);
    return 0;
}
