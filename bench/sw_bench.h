/* sw_bench.h - the two pieces every benchmark program under bench/ shares:
 * a monotonic clock and the median of repeated timings (header only; the
 * programs print figures and assert nothing). */
#ifndef SW_BENCH_H
#define SW_BENCH_H

#include <stdlib.h>
#include <time.h>

/* seconds of the monotonic clock */
static inline double sw_bench_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static inline int sw_bench_cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the median of v[0..n-1] (n >= 1; v is sorted in place) */
static inline double sw_bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, sw_bench_cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif
