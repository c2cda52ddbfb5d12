/* swd_bench.c - cost of one step of the near-wall walk (swd_advance), the
 * call every host makes per parcel and tracking step. Prints, per place
 * (viscous sublayer, buffer layer, the blend, the bulk; with and without a
 * gradient of k, which decides whether the step's midpoint is evaluated),
 * the median over R repetitions of the nanoseconds per call.
 *
 * Usage: swd_bench [REPS]   (default 7; each repetition 2 million calls)
 * Not a test: nothing is asserted. */
#include "sw_bench.h"
#include "swd.h"

#include <stdio.h>
#include <stdlib.h>


int main(int argc, char **argv)
{
    const int reps = argc > 1 ? atoi(argv[1]) : 7;
    if (reps < 1 || reps > 1000) {
        fprintf(stderr, "swd_bench: REPS '%s' is not a whole number in 1..1000\n", argv[1]);
        return 2;
    }
    swd_model *m = swd_alloc();
    if (!m)
        return 1;
    const double nu = 1.5e-5, ut = 0.5;
    const struct {
        const char *name;
        double yplus;
        int grad;
    } places[] = {
        { "sublayer y+ 2, k uniform", 2, 0 },   { "sublayer y+ 2, grad k", 2, 1 },
        { "buffer y+ 20, grad k", 20, 1 },      { "blend y+ 120, grad k", 120, 1 },
        { "bulk y+ 400, k uniform", 400, 0 },   { "bulk y+ 400, grad k", 400, 1 },
    };
    enum { N = 2000000 };
    printf("# swd_advance: ns per call, median of %d repetitions of %d calls\n", reps, N);
    double *t = malloc(reps * sizeof *t);
    volatile double sink = 0.0;
    for (size_t p = 0; p < sizeof places / sizeof *places; p++) {
        swd_local at = { .y = places[p].yplus * nu / ut, .u_tau = ut, .nu = nu, .k = 0.4,
                         .eps = 2.0 };
        if (places[p].grad) {
            at.grad_k[0] = 3.0;
            at.grad_k[1] = 40.0;
        }
        double w[3] = { 0.1, -0.2, 0.3 }, kick[3];
        const double xi[3] = { 0.3, -0.1, 0.2 };
        for (int r = 0; r < reps; r++) {
            const double t0 = sw_bench_now();
            for (int i = 0; i < N; i++) {
                swd_advance(m, &at, 1e-5, 1e-4, w, xi, kick, NULL);
                sink += kick[1];
            }
            t[r] = (sw_bench_now() - t0) / N * 1e9;
        }
        printf("%-28s %8.1f ns\n", places[p].name, sw_bench_median(t, reps));
    }
    free(t);
    swd_free(m);
    return sink == 12345.678;   /* keeps the loop */
}
