/* swg_ladder.h - what a resolution ladder of runs needs besides the GCI
 * (doc/convergence.md, "Total error of a ladder"): the mean of a time series
 * over a window with its batch-means standard error, the discretization
 * error of every level against the extrapolated (or the finest) value, the
 * total error sqrt(sampling^2 + discretization^2) of every run and the
 * cheapest run under a target.
 *
 * Every function takes const inputs, returns 0 or an SWG_E* code (swg_gci.h)
 * with a one-line message in err (when err is given), and never exits. */
#ifndef SWG_LADDER_H
#define SWG_LADDER_H

#include "swg_gci.h"

#include <stddef.h>

/* ---- a time series over a window ----------------------------------------- */

typedef struct {
    double mean;   /* mean of the samples with t0 < t <= t1 */
    double se;     /* its standard error by batch means: the samples in nbatch
                      consecutive batches of (nearly) equal count, se = the sample
                      standard deviation of the batch means / sqrt(nbatch) */
    size_t n;      /* samples in the window */
    int nbatch;    /* batches used */
    double first, last; /* times of the first and the last sample in the window */
} swg_series_stat;

/* The samples (t[i], x[i]), i < n, with t strictly increasing and every value
 * finite (|x| <= SWG_VALUE_MAX): mean and batch-means standard error over
 * t0 < t <= t1 with nbatch batches (2 to 1000; at least 2 samples a batch).
 * Refused: t not increasing, a value out of range, t0 >= t1, fewer than
 * 2 nbatch samples in the window. */
int swg_series_mean(const double *t, const double *x, size_t n, double t0, double t1, int nbatch,
                    swg_series_stat *out, char *err, size_t errlen);

/* ---- discretization error of every level --------------------------------- */

/* what the levels' error is measured against */
typedef enum {
    SWG_REF_EXTRAPOLATED = 0, /* phi_ext21: a monotone ladder (or two resolved levels) */
    SWG_REF_BOUND             /* a ladder that does not resolve a monotone trend: a bound
                                 over two readings, A the finest value phi1 uncertain by
                                 its last change |phi2 - phi1|, B the extrapolation of the
                                 finest pair with the schemes' formal order p (p_two),
                                 phi1 - (phi2 - phi1) / (r21^p - 1), uncertain by that
                                 step; every level's error the larger of the two */
} swg_ref_kind;

typedef struct {
    swg_result gci;    /* the finest three levels (swg_three_level), or the two
                          (swg_two_level with the assumed order) */
    swg_ref_kind kind;
    double ref;        /* phi_ext21 or phi1 */
    double ref_se;     /* its sampling standard error (se_phi_ext21 or se1) */
    double ref_u;      /* its own discretization uncertainty: (Fs - 1) |phi1 - phi_ext21|
                          for the extrapolated value (the GCI band beyond the
                          extrapolation; Fs 1.25 with three levels, 3 with two); for a
                          bound the one of the reading taken as ref */
    /* SWG_REF_BOUND: the two readings (else ref_a = ref_b = ref, u_a = u_b = ref_u) */
    double ref_a, u_a; /* phi1, |phi2 - phi1| */
    double ref_b, u_b; /* phi1 - (phi2 - phi1) / (r21^p - 1), |(phi2 - phi1) / (r21^p - 1)| */
} swg_disc;

/* Levels l[0..n-1], finest first (h strictly increasing), n >= 2: the verdict of
 * the finest three (or two, with the assumed order p_two) and the reference; the
 * discretization error of every level into disc[0..n-1].
 * Where the ladder resolves a monotone trend (the verdict gives an order:
 * Richardson and the GCI), its distance to the extrapolated value combined with
 * that value's own uncertainty ref_u:
 *   disc[i] = sqrt((phi_i - ref)^2 + ref_u^2).
 * Where it does not (steps inside the sampling noise, oscillation, divergence),
 * a bound that covers both readings of such a ladder (SWG_REF_BOUND): the finest
 * value A, uncertain by its last change, and the extrapolation B of the finest
 * pair with the schemes' formal order p_two, uncertain by its own step:
 *   disc[i] = max(sqrt((phi_i - ref_a)^2 + u_a^2), sqrt((phi_i - ref_b)^2 + u_b^2)),
 * and ref is the reading of the smaller magnitude (relative errors the larger;
 * B only when it has A's sign: an extrapolation through zero is no reference).
 * So a coarse level that lands near the finest value of a ladder that does not
 * converge is not taken as accurate, and a fall that the statistics do not
 * resolve is not read as convergence. p_two in (0, SWG_P_LIMIT]. */
int swg_discretization(const swg_level *l, size_t n, double p_two, const swg_settings *s,
                       swg_disc *d, double *disc, char *err, size_t errlen);

/* "extrapolated" or "bound" (the reference_kind of snowladder's tables) */
const char *swg_ref_kind_name(swg_ref_kind k);

/* ---- total error and the cheapest run -------------------------------------- */

/* total = sqrt(se^2 + disc^2) (hypot); rel = total / |ref| and *has_rel 1 when
 * ref != 0, else rel 0 and *has_rel 0. se, disc >= 0 and finite. */
int swg_total_error(double se, double disc, double ref, double *total, double *rel, int *has_rel,
                    char *err, size_t errlen);

/* Of n runs with relative total errors rel[] (ok[i] 0: no relative error, never
   picked) and costs cost[] (>= 0): the cheapest with rel <= target (ties: the
   smaller error, then the first). *idx gets it; returns 1 when one was found, 0
   when none reaches the target, -1 on bad input (a negative or non-finite cost
   or target). */
int swg_pick(const double *rel, const int *ok, const double *cost, size_t n, double target,
             size_t *idx);

#endif
