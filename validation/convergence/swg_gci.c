/* swg_gci.c - observed order, Richardson extrapolation and the grid
 * convergence index of a resolution ladder (see swg_gci.h, doc/convergence.md). */
#include "swg_gci.h"
#include "swo_err.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define fail(err, errlen, code, ...) swo_fail(code, err, errlen, __VA_ARGS__)

/* x finite and inside [lo, hi]; a NaN is never compared (an ordered comparison
   with a NaN raises FE_INVALID, a trap in the test build) */
static int in_range(double x, double lo, double hi)
{
    return isfinite(x) && x >= lo && x <= hi;
}

/* *out = |a / b| when b != 0 and the quotient stays below 1e200 (the inputs are
   bounded by SWG_VALUE_MAX, so b * 1e200 cannot overflow); 0 otherwise */
static int safe_ratio(double a, double b, double *out)
{
    if (b == 0.0 || fabs(a) > fabs(b) * 1e200)
        return 0;
    *out = fabs(a / b);
    return 1;
}

void swg_settings_default(swg_settings *s)
{
    s->p_min = 0.5;
    s->p_max = 8.0;
    s->fs3 = 1.25;
    s->fs2 = 3.0;
    s->z = 2.0;
    s->tol = 1e-12;
    s->max_iter = 100;
}

int swg_settings_check(const swg_settings *s, char *err, size_t errlen)
{
    if (!s)
        return fail(err, errlen, SWG_EINVAL, "settings: none given");
    if (!in_range(s->p_min, 1e-3, SWG_P_LIMIT))
        return fail(err, errlen, SWG_EINVAL, "p_min %g is outside [0.001, %g]", s->p_min,
                    SWG_P_LIMIT);
    if (!in_range(s->p_max, s->p_min, SWG_P_LIMIT) || !(s->p_max > s->p_min))
        return fail(err, errlen, SWG_EINVAL, "p_max %g is not in (p_min %g, %g]", s->p_max,
                    s->p_min, SWG_P_LIMIT);
    if (!in_range(s->fs3, 1.0, 10.0))
        return fail(err, errlen, SWG_EINVAL, "three-level safety factor %g is outside [1, 10]",
                    s->fs3);
    if (!in_range(s->fs2, 1.0, 10.0))
        return fail(err, errlen, SWG_EINVAL, "two-level safety factor %g is outside [1, 10]",
                    s->fs2);
    if (!in_range(s->z, 0.0, 10.0))
        return fail(err, errlen, SWG_EINVAL, "z %g (standard errors) is outside [0, 10]", s->z);
    if (!in_range(s->tol, 1e-15, 1e-3))
        return fail(err, errlen, SWG_EINVAL, "tolerance %g is outside [1e-15, 1e-3]", s->tol);
    if (s->max_iter < 1 || s->max_iter > 1000)
        return fail(err, errlen, SWG_EINVAL, "iteration bound %d is outside [1, 1000]",
                    s->max_iter);
    return 0;
}

int swg_cell_size(double volume, double cells, int dim, double *h, char *err, size_t errlen)
{
    if (dim < 1 || dim > 3)
        return fail(err, errlen, SWG_EINVAL, "dimension %d is not 1, 2 or 3", dim);
    if (!in_range(volume, 1e-100, 1e100) || !(volume > 0.0))
        return fail(err, errlen, SWG_EINVAL, "volume %g is outside (0, 1e100] (or below 1e-100)",
                    volume);
    if (!in_range(cells, 1.0, 1e15))
        return fail(err, errlen, SWG_EINVAL, "cell count %g is outside [1, 1e15]", cells);
    const double x = pow(volume / cells, 1.0 / dim);
    if (!in_range(x, SWG_H_MIN, SWG_H_MAX))
        return fail(err, errlen, SWG_EINVAL, "cell size (%g / %g)^(1/%d) = %g is outside [%g, %g]",
                    volume, cells, dim, x, SWG_H_MIN, SWG_H_MAX);
    *h = x;
    return 0;
}

const char *swg_verdict_name(swg_verdict v)
{
    switch (v) {
    case SWG_MONOTONE: return "monotone";
    case SWG_OSCILLATORY: return "oscillatory";
    case SWG_OSC_DIVERGENT: return "oscillatory-divergent";
    case SWG_DIVERGENT: return "divergent";
    case SWG_ZERO_FINE: return "zero-fine-difference";
    case SWG_UNCHANGED: return "unchanged";
    case SWG_UNRESOLVED: return "not resolved by the statistics";
    case SWG_TWO_LEVEL: return "two-level";
    }
    return "unknown";
}

/* ---- the apparent order ---- */

typedef struct {
    double a, b, L; /* ln r21, ln r32, ln|e32/e21| */
} order_eq;

/* s = +1: ln(r21^p (r32^p - 1) / (r21^p - 1)) - ln|e32/e21|, strictly increasing in p */
static double g_plus(double p, void *vp)
{
    const order_eq *q = vp;
    return p * q->a + log(expm1(p * q->b)) - log(expm1(p * q->a)) - q->L;
}

/* q(p) of Celik's equation; s = +1 or -1 */
static double q_of(double p, const order_eq *q, int s)
{
    if (s > 0)
        return log(expm1(p * q->a)) - log(expm1(p * q->b));
    return log1p(exp(p * q->a)) - log1p(exp(p * q->b));
}

/* s = -1: p ln r21 - |ln|e32/e21| + q(p)| */
static double f_minus(double p, void *vp)
{
    const order_eq *q = vp;
    return p * q->a - fabs(q->L + q_of(p, q, -1));
}

int swg_order(double r21, double r32, double e21, double e32, const swg_settings *s,
              swg_order_result *o, char *err, size_t errlen)
{
    int rc = swg_settings_check(s, err, errlen);
    if (rc)
        return rc;
    if (!in_range(r21, SWG_R_MIN, SWG_R_MAX))
        return fail(err, errlen, SWG_EINVAL, "r21 %g is outside [%g, %g]", r21, SWG_R_MIN,
                    SWG_R_MAX);
    if (!in_range(r32, SWG_R_MIN, SWG_R_MAX))
        return fail(err, errlen, SWG_EINVAL, "r32 %g is outside [%g, %g]", r32, SWG_R_MIN,
                    SWG_R_MAX);
    if (!in_range(fabs(e21), 1e-300, 4 * SWG_VALUE_MAX) || !in_range(fabs(e32), 1e-300,
                                                                     4 * SWG_VALUE_MAX))
        return fail(err, errlen, SWG_EINVAL,
                    "the order needs two non-zero finite differences (e21 %g, e32 %g)", e21, e32);
    memset(o, 0, sizeof *o);
    order_eq q = { log(r21), log(r32), log(fabs(e32)) - log(fabs(e21)) };
    const int sg = (e21 > 0) == (e32 > 0) ? 1 : -1;
    double (*f)(double, void *) = sg > 0 ? g_plus : f_minus;
    const double lo = s->p_min, hi = s->p_max;

    if (sg > 0 && fabs(q.a - q.b) <= 1e-12 * q.a) {
        /* constant ratio: q(p) = 0, p = ln|e32/e21| / ln r */
        const double p = q.L / q.a;
        o->p = p < lo ? lo : p > hi ? hi : p;
        o->bound = p < lo ? SWG_BOUND_LOW : p > hi ? SWG_BOUND_HIGH : SWG_BOUND_NONE;
        o->iterations = 0;
        o->width = 0.0;
        o->converged = 1;
    } else {
        const double flo = f(lo, &q), fhi = f(hi, &q);
        o->converged = 1;
        if (flo == 0.0 || fhi == 0.0) {
            o->p = flo == 0.0 ? lo : hi;
        } else if (flo > 0.0 && fhi > 0.0) {
            o->p = lo;
            o->bound = SWG_BOUND_LOW;
        } else if (flo < 0.0 && fhi < 0.0) {
            o->p = hi;
            o->bound = SWG_BOUND_HIGH;
        } else {
            gsl_function F = { f, &q };
            gsl_root_fsolver *sv = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
            if (!sv)
                return fail(err, errlen, SWG_ENOMEM, "the root solver could not be allocated");
            /* the bracket is checked above; the handler is off all the same, so a
               GSL error comes back as a code, never an abort */
            gsl_error_handler_t *old = gsl_set_error_handler_off();
            double a = lo, b = hi;
            int it = 0, done = 0, st = gsl_root_fsolver_set(sv, &F, a, b);
            while (st == GSL_SUCCESS && it < s->max_iter && !done) {
                it++;
                if (gsl_root_fsolver_iterate(sv) != GSL_SUCCESS) {
                    st = GSL_FAILURE;
                    break;
                }
                a = gsl_root_fsolver_x_lower(sv);
                b = gsl_root_fsolver_x_upper(sv);
                done = gsl_root_test_interval(a, b, 0.0, s->tol) == GSL_SUCCESS;
            }
            const double root = gsl_root_fsolver_root(sv);
            gsl_set_error_handler(old);
            gsl_root_fsolver_free(sv);
            if (st != GSL_SUCCESS || !isfinite(root))
                return fail(err, errlen, SWG_EINVAL, "the order's root solver failed after %d "
                            "iterations (r21 %g, r32 %g, e21 %g, e32 %g)", it, r21, r32, e21, e32);
            o->p = root;
            o->iterations = it;
            o->width = b - a;
            o->converged = done;
        }
    }
    o->residual = fabs(o->p - fabs(q.L + q_of(o->p, &q, sg)) / q.a);
    return 0;
}

/* ---- ladders ---- */

static int check_level(const swg_level *l, int i, char *err, size_t errlen)
{
    if (!in_range(l->h, SWG_H_MIN, SWG_H_MAX))
        return fail(err, errlen, SWG_EINVAL, "level %d: h %g is outside [%g, %g]", i, l->h,
                    SWG_H_MIN, SWG_H_MAX);
    if (!in_range(l->value, -SWG_VALUE_MAX, SWG_VALUE_MAX))
        return fail(err, errlen, SWG_EINVAL, "level %d: value %g is not finite within +-%g", i,
                    l->value, SWG_VALUE_MAX);
    if (!in_range(l->se, 0.0, SWG_VALUE_MAX))
        return fail(err, errlen, SWG_EINVAL, "level %d: standard error %g is outside [0, %g]", i,
                    l->se, SWG_VALUE_MAX);
    return 0;
}

static int ratio(const swg_level *fine, const swg_level *coarse, int i, double *r, char *err,
                 size_t errlen)
{
    *r = coarse->h / fine->h;
    if (!in_range(*r, SWG_R_MIN, SWG_R_MAX))
        return fail(err, errlen, SWG_EINVAL,
                    "r%d%d = h%d/h%d = %g / %g = %g is outside [%g, %g] (levels finest first, "
                    "distinct h)", i + 1, i, i + 1, i, coarse->h, fine->h, *r, SWG_R_MIN,
                    SWG_R_MAX);
    return 0;
}

/* combined standard error, |e| over it, and whether e is resolved */
static void resolve(double e, double se_a, double se_b, double z, double *se, double *zz, int *res)
{
    *se = hypot(se_a, se_b);
    if (*se == 0.0) {
        *zz = 0.0;
        *res = 1; /* deterministic values: a difference, even zero, is exact */
        return;
    }
    *zz = fabs(e) > *se * 1e200 ? 1e200 : fabs(e) / *se;
    *res = fabs(e) > z * *se;
}

static void spread(const swg_level *l, int n, swg_result *r)
{
    r->phi_min = r->phi_max = l[0].value;
    for (int i = 1; i < n; i++) {
        if (l[i].value < r->phi_min)
            r->phi_min = l[i].value;
        if (l[i].value > r->phi_max)
            r->phi_max = l[i].value;
    }
    r->spread = r->phi_max - r->phi_min;
    double x;
    r->half_spread_rel = safe_ratio(0.5 * r->spread, l[0].value, &x) ? x : 0.0;
}

/* |dval| se / (2 delta), when it stays below 1e300; 0 with *ok cleared otherwise */
static double lin_term(double dval, double se, double delta, int *ok)
{
    if (dval == 0.0 || se == 0.0)
        return 0.0;
    if (log10(fabs(dval)) + log10(se) - log10(2.0 * delta) > 300.0) {
        *ok = 0;
        return 0.0;
    }
    return fabs(dval) * se / (2.0 * delta);
}

/* p and phi_ext21 of three values on the ladder's ratios */
static int p_ext(double r21, double r32, double v1, double v2, double v3, const swg_settings *s,
                 double *p, double *ext)
{
    swg_order_result o;
    if (swg_order(r21, r32, v2 - v1, v3 - v2, s, &o, NULL, 0))
        return -1;
    *p = o.p;
    *ext = v1 - (v2 - v1) / expm1(o.p * log(r21));
    return 0;
}

/* order-dependent results of a ladder with its order in r->order.p */
static void extrapolate(const swg_level *l, int n, double fs, swg_result *r)
{
    const double p = r->order.p;
    const double d21 = expm1(p * log(r->r21)); /* r21^p - 1 > 0 */
    r->has_order = 1;
    r->phi_ext21 = l[0].value - r->e21 / d21;
    r->gci_abs = fs * fabs(r->e21) / d21;
    double ea, eext;
    r->has_rel = safe_ratio(r->e21, l[0].value, &ea)
                 && safe_ratio(r->phi_ext21 - l[0].value, r->phi_ext21, &eext)
                 && ea * fs / d21 < 1e200;
    if (r->has_rel) {
        r->e_a21 = ea;
        r->e_ext21 = eext;
        r->gci_fine21 = fs * ea / d21;
    }
    if (n == 3) {
        const double d32 = expm1(p * log(r->r32));
        r->phi_ext32 = l[1].value - r->e32 / d32;
        r->gci32_abs = fs * fabs(r->e32) / d32;
        /* GCI32 / (r21^p GCI21) in absolute form (exactly 1 for phi0 + C h^p),
           through logarithms */
        const double lg = log(fabs(r->e32)) - log(d32) - p * log(r->r21) - log(fabs(r->e21))
                          + log(d21);
        r->asymptotic = fabs(lg) < 400.0 ? exp(lg) : 0.0;
    }
    r->u95_abs = hypot(r->gci_abs, 2.0 * l[0].se);
}

int swg_three_level(const swg_level l[3], const swg_settings *s, swg_result *res, char *err,
                    size_t errlen)
{
    int rc = swg_settings_check(s, err, errlen);
    if (rc)
        return rc;
    for (int i = 0; i < 3; i++)
        if ((rc = check_level(&l[i], i + 1, err, errlen)))
            return rc;
    swg_result r;
    memset(&r, 0, sizeof r);
    r.nlevels = 3;
    if ((rc = ratio(&l[0], &l[1], 1, &r.r21, err, errlen))
        || (rc = ratio(&l[1], &l[2], 2, &r.r32, err, errlen)))
        return rc;
    r.ratio_below_1_3 = r.r21 < 1.3 || r.r32 < 1.3;
    r.e21 = l[1].value - l[0].value;
    r.e32 = l[2].value - l[1].value;
    resolve(r.e21, l[0].se, l[1].se, s->z, &r.se21, &r.z21, &r.resolved21);
    resolve(r.e32, l[1].se, l[2].se, s->z, &r.se32, &r.z32, &r.resolved32);
    /* R = e21/e32 and its value over the one at p = 0, Rn = R ln r32 / ln r21: the
       apparent order is positive exactly when 0 < Rn < 1 (the left side of the
       order's equation rises strictly from ln(ln r32 / ln r21) at p = 0), so the
       patterns are read from Rn; with r21 = r32 it is Celik's R */
    const double a = log(r.r21), b = log(r.r32);
    if (r.e32 != 0.0) {
        r.R = fabs(r.e21) > fabs(r.e32) * 1e200 ? copysign(1e200, r.e21 * r.e32)
                                                 : r.e21 / r.e32;
        r.Rn = fabs(r.R) * b > a * 1e200 ? copysign(1e200, r.R) : r.R * b / a;
    }
    /* the pattern of the values, by signs and magnitudes (no division) */
    const int shrinks = fabs(r.e21) * b < fabs(r.e32) * a; /* |Rn| < 1 */
    if (r.e21 == 0.0 && r.e32 == 0.0)
        r.pattern = SWG_UNCHANGED;
    else if (r.e21 == 0.0)
        r.pattern = SWG_ZERO_FINE;
    else if (r.e32 == 0.0)
        r.pattern = SWG_DIVERGENT;
    else if ((r.e21 > 0) == (r.e32 > 0))
        r.pattern = shrinks ? SWG_MONOTONE : SWG_DIVERGENT;
    else
        r.pattern = shrinks ? SWG_OSCILLATORY : SWG_OSC_DIVERGENT;
    r.verdict = r.resolved21 && r.resolved32 ? r.pattern : SWG_UNRESOLVED;
    spread(l, 3, &r);

    if (r.verdict == SWG_MONOTONE) {
        if ((rc = swg_order(r.r21, r.r32, r.e21, r.e32, s, &r.order, err, errlen)))
            return rc;
        extrapolate(l, 3, s->fs3, &r);
        /* the sampling error carried through: central differences in each value */
        r.has_se_ext = 1;
        if (l[0].se > 0.0 || l[1].se > 0.0 || l[2].se > 0.0) {
            const double delta = 1e-6 * fmin(fabs(r.e21), fabs(r.e32));
            double tp[3], te[3];
            for (int i = 0; i < 3 && r.has_se_ext; i++) {
                double v[3] = { l[0].value, l[1].value, l[2].value }, pp, pm, ep, em;
                v[i] = l[i].value + delta;
                const int a = p_ext(r.r21, r.r32, v[0], v[1], v[2], s, &pp, &ep);
                v[i] = l[i].value - delta;
                const int b = p_ext(r.r21, r.r32, v[0], v[1], v[2], s, &pm, &em);
                if (a || b) {
                    r.has_se_ext = 0;
                    break;
                }
                tp[i] = lin_term(pp - pm, l[i].se, delta, &r.has_se_ext);
                te[i] = lin_term(ep - em, l[i].se, delta, &r.has_se_ext);
            }
            if (r.has_se_ext) {
                r.se_p = hypot(hypot(tp[0], tp[1]), tp[2]);
                r.se_phi_ext21 = hypot(hypot(te[0], te[1]), te[2]);
            } else {
                r.se_p = r.se_phi_ext21 = 0.0;
            }
        }
    }
    *res = r;
    return 0;
}

int swg_two_level(const swg_level l[2], double p_assumed, const swg_settings *s, swg_result *res,
                  char *err, size_t errlen)
{
    int rc = swg_settings_check(s, err, errlen);
    if (rc)
        return rc;
    for (int i = 0; i < 2; i++)
        if ((rc = check_level(&l[i], i + 1, err, errlen)))
            return rc;
    if (!in_range(p_assumed, 1e-3, SWG_P_LIMIT))
        return fail(err, errlen, SWG_EINVAL, "assumed order %g is outside [0.001, %g]",
                    p_assumed, SWG_P_LIMIT);
    swg_result r;
    memset(&r, 0, sizeof r);
    r.nlevels = 2;
    if ((rc = ratio(&l[0], &l[1], 1, &r.r21, err, errlen)))
        return rc;
    r.ratio_below_1_3 = r.r21 < 1.3;
    r.e21 = l[1].value - l[0].value;
    resolve(r.e21, l[0].se, l[1].se, s->z, &r.se21, &r.z21, &r.resolved21);
    r.resolved32 = 1;
    r.pattern = r.e21 == 0.0 ? SWG_UNCHANGED : SWG_TWO_LEVEL;
    r.verdict = r.resolved21 ? r.pattern : SWG_UNRESOLVED;
    spread(l, 2, &r);
    if (r.verdict == SWG_TWO_LEVEL) {
        r.order.p = p_assumed;
        extrapolate(l, 2, s->fs2, &r);
        /* phi_ext = (r^p phi1 - phi2) / (r^p - 1): linear in the values */
        const double d = expm1(p_assumed * log(r.r21));
        r.has_se_ext = 1;
        r.se_phi_ext21 = hypot((d + 1.0) / d * l[0].se, l[1].se / d);
    }
    *res = r;
    return 0;
}
