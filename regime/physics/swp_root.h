/* swp_root.h - the safeguarded Newton iteration the contact laws share: the
 * root of an increasing function above a known lower bound (the JKR turning
 * point, the Thornton-Ning yield radius). */
#ifndef SWP_ROOT_H
#define SWP_ROOT_H

#ifdef __cplusplus
extern "C" {
#endif

/* f(x) and, when dfdx is not NULL, f'(x). */
typedef double (*swp_root_fn)(double x, void *ctx, double *dfdx);

/* Root of f, increasing on [lo, inf) with f(lo) <= 0: hi is doubled (at most
 * nexpand times) until f(hi) >= 0; then Newton from hi, every step kept inside
 * the bracket [lo, hi] (bisection when it leaves it or f' <= 0), the bracket
 * tightened by the sign of f. Returns the iterate after the first step smaller
 * than rtol x, or the last one after maxit steps. */
double swp_root_increasing(swp_root_fn f, void *ctx, double lo, double hi, int nexpand,
                           double rtol, int maxit);

#ifdef __cplusplus
}
#endif
#endif
