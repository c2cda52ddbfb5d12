/* swg_gci.h - discretization error of a resolution ladder: observed order of
 * convergence, Richardson extrapolation and Roache's grid convergence index
 * (GCI) by the procedure of Celik, Ghia, Roache, Freitas, Coleman and Raad
 * (J. Fluids Eng. 130, 078001, 2008), with the sampling error of every level
 * as part of the verdict (doc/convergence.md).
 *
 * Levels are numbered as in the paper: 1 the finest, 3 the coarsest, with
 * representative cell sizes h1 < h2 < h3 (or time steps, or any resolution
 * parameter that goes to zero). Every function takes const inputs, returns 0
 * or an SWG_E* code with a one-line message in err (when err is given), and
 * gives finite numbers for every finite input: degenerate ladders (equal
 * values, a zero difference, oscillation, divergence, differences inside the
 * sampling noise) get a named verdict, never a NaN. The C core never exits. */
#ifndef SWG_GCI_H
#define SWG_GCI_H

#include <stddef.h>

/* error codes (0 = success) */
enum {
    SWG_EINVAL = 1, /* an input outside its documented range */
    SWG_ENOMEM = 2  /* an allocation failed */
};

/* Input limits (documented in doc/convergence.md): they keep every
 * intermediate finite, so the floating-point traps of the test build never
 * fire. */
#define SWG_VALUE_MAX 1e100 /* |value| and standard error at most this */
#define SWG_H_MIN 1e-100    /* h in [SWG_H_MIN, SWG_H_MAX] */
#define SWG_H_MAX 1e100
#define SWG_R_MIN 1.001 /* refinement ratio between neighbouring levels */
#define SWG_R_MAX 100.0
#define SWG_P_LIMIT 20.0 /* the order range must lie inside (0, SWG_P_LIMIT] */

/* one level of the ladder */
typedef struct {
    double h;     /* representative cell size (or step), > 0 */
    double value; /* the quantity phi on this level */
    double se;    /* its sampling standard error, >= 0 (0: a deterministic value) */
} swg_level;

/* settings of the procedure */
typedef struct {
    double p_min, p_max; /* the apparent order is bounded to [p_min, p_max] */
    double fs3;          /* safety factor with three levels (Celik: 1.25) */
    double fs2;          /* safety factor with two levels and an assumed order (Roache: 3) */
    double z;            /* a difference within z combined standard errors of zero is not
                            resolved by the statistics (default 2) */
    double tol;          /* relative tolerance of the order's root (default 1e-12) */
    int max_iter;        /* iteration bound of the root solver (default 100) */
} swg_settings;

/* the defaults: p in [0.5, 8], fs3 1.25, fs2 3, z 2, tol 1e-12, 100 iterations */
void swg_settings_default(swg_settings *s);
/* check a settings struct: 0 or SWG_EINVAL with the setting named */
int swg_settings_check(const swg_settings *s, char *err, size_t errlen);

/* representative cell size h = (volume / cells)^(1/dim), dim 1, 2 or 3 */
int swg_cell_size(double volume, double cells, int dim, double *h, char *err, size_t errlen);

/* the verdict of a ladder; Rn = (e21/e32) ln r32 / ln r21 is Celik's R = e21/e32
   over its value at p = 0 (Rn = R when r21 = r32): the apparent order is
   positive exactly when 0 < Rn < 1 */
typedef enum {
    SWG_MONOTONE = 0,     /* 0 < Rn < 1: monotone convergence; order, extrapolation, GCI */
    SWG_OSCILLATORY,      /* -1 < Rn < 0: oscillatory convergence; spread, no order */
    SWG_OSC_DIVERGENT,    /* Rn <= -1: oscillatory divergence; spread, no order */
    SWG_DIVERGENT,        /* Rn >= 1 (or e32 = 0 with e21 != 0): divergent; spread */
    SWG_ZERO_FINE,        /* e21 = 0, e32 != 0: the finest pair equal, no finite order; spread */
    SWG_UNCHANGED,        /* all values equal (no sampling error): no measurable change */
    SWG_UNRESOLVED,       /* a level difference within z combined standard errors */
    SWG_TWO_LEVEL         /* two levels with an assumed order */
} swg_verdict;

/* a short name ("monotone", "oscillatory", ..., "not resolved by the statistics") */
const char *swg_verdict_name(swg_verdict v);

/* which end of [p_min, p_max] the order was held at */
typedef enum { SWG_BOUND_NONE = 0, SWG_BOUND_LOW, SWG_BOUND_HIGH } swg_bound;

/* the apparent order, solved alone (swg_order) */
typedef struct {
    double p;     /* the order (the bound when one was hit) */
    swg_bound bound;
    int iterations;  /* Brent iterations (0: closed form, constant ratio, or a bound) */
    double width;    /* width of the final bracket (0 for the closed form or a bound) */
    int converged;   /* 1: closed form, a bound, or the bracket within tol (relative) */
    double residual; /* |p - |ln|e32/e21| + q(p)| / ln r21|, Celik's fixed-point equation */
} swg_order_result;

/* Solve Celik's equation p = |ln|e32/e21| + q(p)| / ln r21,
 * q(p) = ln((r21^p - s) / (r32^p - s)), s = sign(e32/e21), on [p_min, p_max].
 * For s = +1 the equation is ln(r21^p (r32^p - 1) / (r21^p - 1)) = ln|e32/e21|, whose
 * left side increases strictly with p for any r21, r32 > 1: one root at most,
 * found by GSL's Brent solver (closed form ln|e32/e21| / ln r when r21 = r32); no
 * root inside the range holds p at the bound passed (bound says which). For s = -1
 * (an oscillating ladder; the paper's Table 1 computes an order for one) the
 * fixed-point form is solved by Brent where it changes sign on the range, else
 * held at the bound. e21 and e32 must be non-zero and finite. */
int swg_order(double r21, double r32, double e21, double e32, const swg_settings *s,
              swg_order_result *o, char *err, size_t errlen);

/* the result of a ladder of three (or two) levels */
typedef struct {
    swg_verdict verdict; /* the verdict, statistics included */
    swg_verdict pattern; /* the verdict from the values alone (never SWG_UNRESOLVED) */
    int nlevels;         /* 3, or 2 for swg_two_level */
    double r21, r32;     /* refinement ratios h2/h1, h3/h2 (r32 0 with two levels) */
    double e21, e32;     /* epsilon21 = phi2 - phi1, epsilon32 = phi3 - phi2 */
    double R;            /* e21 / e32 (0 when e32 = 0; held within +-1e200) */
    double Rn;           /* R ln r32 / ln r21: R over its value at p = 0 (= R when r21 = r32);
                            the verdicts are read from it */
    double se21, se32;   /* combined standard errors sqrt(se_i^2 + se_j^2) */
    double z21, z32;     /* |e| / se_combined (0 when that is 0) */
    int resolved21, resolved32; /* |e| > z se_combined (with no sampling error: e != 0) */
    /* order, extrapolation and GCI: set (has_order 1) only when verdict is
       SWG_MONOTONE or SWG_TWO_LEVEL; otherwise zero */
    int has_order;
    swg_order_result order; /* for SWG_TWO_LEVEL: the assumed order, no iterations */
    double phi_ext21;  /* (r21^p phi1 - phi2) / (r21^p - 1) */
    double phi_ext32;  /* (r32^p phi2 - phi3) / (r32^p - 1) (three levels) */
    double gci_abs;    /* Fs |e21| / (r21^p - 1): the fine-level band in the quantity's unit */
    double gci32_abs;  /* Fs |e32| / (r32^p - 1) (three levels) */
    double asymptotic; /* gci32_abs / (r21^p gci_abs), 1 in the asymptotic range
                          (three levels; 0 when beyond e^+-400) */
    int has_rel;       /* 1 when phi1 != 0 (and phi_ext21 != 0 for e_ext) */
    double e_a21;      /* |(phi1 - phi2) / phi1| */
    double e_ext21;    /* |(phi_ext21 - phi1) / phi_ext21| */
    double gci_fine21; /* Fs e_a21 / (r21^p - 1) */
    /* the sampling error carried through (linearised, central differences in
       each level's value): standard errors of p and phi_ext21 */
    int has_se_ext;
    double se_p, se_phi_ext21;
    double u95_abs;    /* sqrt(gci_abs^2 + (2 se1)^2): the GCI (a 95 % band after Roache)
                          combined with two sampling standard errors of the finest level */
    /* always set: the spread of the values */
    double phi_min, phi_max, spread; /* spread = max - min */
    double half_spread_rel;          /* (spread / 2) / |phi1| (0 when phi1 = 0) */
    int ratio_below_1_3;             /* a refinement ratio below 1.3 (Celik's advice) */
} swg_result;

/* Three levels, l[0] the finest (h strictly increasing): the verdict and, when
 * monotone and resolved, order, extrapolation, GCI. */
int swg_three_level(const swg_level l[3], const swg_settings *s, swg_result *res, char *err,
                    size_t errlen);

/* Two levels, l[0] the finer, with an assumed order p_assumed (in (0, SWG_P_LIMIT]):
 * extrapolation and GCI with the safety factor fs2, when the difference is resolved
 * (verdict SWG_TWO_LEVEL); SWG_UNRESOLVED or SWG_UNCHANGED otherwise. */
int swg_two_level(const swg_level l[2], double p_assumed, const swg_settings *s, swg_result *res,
                  char *err, size_t errlen);

#endif
