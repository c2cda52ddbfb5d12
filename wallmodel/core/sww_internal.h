/* sww_internal.h - what the sww_*.c files of the wall-interaction core share
 * and its users do not see (private): the model structure, the regime's
 * numeric keys, the error setter, the cell search and the overflow-free power
 * law of the lookups, and the oblique table's tangential limit. */
#ifndef SWW_INTERNAL_H
#define SWW_INTERNAL_H

#include "sww.h"

#include <math.h>
#include <stddef.h>

#define SWW_MAX_COEFFS 16
#define SWW_MAX_TABLE 4096
#define SWW_MAX_REBOUND 65536   /* reboundEn / reboundEt: K x M x N values */
#define SWW_ERRLEN 512
#define SWW_LABELLEN 256

/* numeric keys of the regime dictionary, in this order (names: sww_num_keys) */
enum {
    K_VERSION, K_DEGREE, K_VNMIN, K_VNMAX, K_DMIN, K_DMAX, K_SLOPELOW, K_SLOPEHIGH,
    K_RMS, K_MAXRES, K_YIELD, K_REBOUND, K_GAMMA, K_ESTAR, K_RHO, K_MU, K_OBSLIDE, K_PRPOINTS,
    K_NNUM
};

struct sww_model {
    /* regime keys as given */
    double num[K_NNUM];
    int has[K_NNUM];
    int representation;            /* 0 unset, 1 polynomial, 2 table */
    int basis;                     /* 0 unset (log), 1 log, 2 linear */
    double coeffs[SWW_MAX_COEFFS];
    size_t ncoeffs;
    double *tab_lnv, *tab_lnd;     /* table in ln-ln, allocated at set time */
    size_t ntab;
    int has_vn, has_dcrit;
    size_t n_vn, n_dcrit;
    char label[SWW_LABELLEN];
    /* oblique table d_crit(v_n, v_t): obliqueVt, obliqueVn, obliqueDCrit */
    double *ob_vt, *ob_lnv, *ob_lnd;  /* v_t, ln v_n, ln d_crit (K x N, rows by v_t) */
    double *ob_s, *ob_lnt;            /* ln v_t, ln D_t the tangential limit (commit) */
    double ob_dx_inv;                 /* 1 / ln-v_n spacing when uniform, else 0 */
    size_t ob_nvt, ob_nvn, ob_nd;
    int ob_ready;                  /* the table passed the commit checks */
    /* stick-probability table of a rough wall: probabilityD, probabilityVn,
     * optional probabilityVt, probabilityStick (M x K x N: rows by d, then by
     * v_t, then v_n; K = 1 without probabilityVt) */
    double *pr_lnd, *pr_lnv, *pr_p;   /* ln d, ln v_n, p_stick in [0, 1] */
    double *pr_vt;                    /* v_t nodes [m/s] (from 0), NULL without */
    size_t pr_nd, pr_nvn, pr_np, pr_nvt;
    /* per axis (0 d, 1 v_n), set at commit: nodes uniform in ln (1) or in the
     * value itself (2: snowregime's linear diameters), else 0 (bisection);
     * the first node and 1 / spacing in that coordinate */
    int pr_mode[2];
    double pr_x0[2], pr_inv[2];
    double pr_lo[2], pr_hi[2];     /* the span of each axis as given [m], [m/s] */
    int pr_ready;                  /* the table passed the commit checks */
    /* the kernel's rebound of bouncing impacts: reboundD, reboundVn,
     * optional reboundVt, reboundEn (K x M x N, layers by v_t, rows by d; K = 1
     * without reboundVt), reboundEt (K x M x N, with reboundVt only) */
    double *rb_lnd, *rb_lnv, *rb_vt, *rb_lnt;  /* ln d, ln v_n, v_t, ln v_t (layers >= 1) */
    double *rb_en, *rb_et;
    size_t rb_nd, rb_nvn, rb_nvt, rb_nen, rb_net;
    double rb_lo[2], rb_hi[2];     /* span of d and v_n as given [m], [m/s] */
    double rb_ep_hi;               /* Thornton e_p at the last v_n node (0: no continuation) */
    int rb_ready;                  /* the tables passed the commit checks */
    int rb_model;                  /* SWW_REBOUND_AUTO / _TABLE / _CLASSIC */
    /* derived at commit */
    int ready;
    double d_lo, d_hi;             /* d_crit at vnMin, vnMax */
    /* options */
    int vt_on;                     /* 0 off, 1 constant vtMax (d/dRef)^exponent, 2 regime table */
    double vt_max, vt_dref, vt_exp;
    int shear_on;                  /* 0 off, 1 constant, 2 adhesion */
    double tau_c, roughness;
    double e_t;
    char err[SWW_ERRLEN];
};

/* The message of a failed call: formats it into m->err, returns code
 * (sww_model.c). */
int sww_fail(sww_model *m, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The names of the numeric keys K_*, in the enum's order (sww_regime.c). */
extern const char *const sww_num_keys[K_NNUM];

/* ln D_t(v_n, v_t) for v_n, v_t > 0 of a model whose oblique table passed the
 * commit: the tangential limit of the regime gate (sww_gates.c). */
double sww_oblique_lndt(const sww_model *m, double vn, double vt);

/* The cell [lo, lo + 1] of the increasing X[lo..hi] that holds x (bisection;
 * x at or beyond the ends gives the end cell). Returns lo. */
static inline size_t sww_cell_of(const double *X, size_t lo, size_t hi, double x)
{
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        if (X[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* a (x/x0)^k for a, x, x0 > 0 and k finite with |k| <= 1e3, without an
 * overflow (OpenFOAM runs with the overflow trap on): INFINITY beyond
 * e^709 = 8e307, exp of the logarithm where the ratio or the power alone would
 * leave the doubles' range, and exactly a * pow(x / x0, k) everywhere else. */
static inline double sww_scaled_power(double a, double x, double x0, double k)
{
    const double lr = log(x) - log(x0), lp = k * lr, la = lp + log(a);
    if (la > 709.0)
        return INFINITY;
    if (fabs(lr) > 700.0 || fabs(lp) > 700.0)
        return exp(la); /* at most 8e307; an underflow to 0 is not trapped */
    return a * pow(x / x0, k);
}

#endif
