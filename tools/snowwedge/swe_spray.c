/* swe_spray.c - the wedge's spray: distribution, size classes, mass medians
 * (swe_spray.h). */
#include "swe_spray.h"
#include "swo_err.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#define fail(err, errlen, ...) swo_fail(SWE_EINVAL, err, errlen, __VA_ARGS__)

void swe_spray_default(swe_spray *s)
{
    s->mvd = 20.0;
    s->sigma_g = 1.8;
    s->dmin = 2.0;
    s->dmax = 150.0;
    s->freeze = 1.03;
}

int swe_spray_check(const swe_spray *s, char *err, size_t errlen)
{
    if (!(s->mvd >= 0.1 && s->mvd <= 1000))
        return fail(err, errlen, "mvd %g um is not in [0.1, 1000]", s->mvd);
    if (!(s->sigma_g > 1 && s->sigma_g <= 10))
        return fail(err, errlen, "sigma_g %g is not in (1, 10]", s->sigma_g);
    if (!(s->freeze >= 0.5 && s->freeze <= 2))
        return fail(err, errlen, "freeze %g is not in [0.5, 2]", s->freeze);
    if (!(s->dmin > 0 && s->dmax > s->dmin && s->dmax <= 10000))
        return fail(err, errlen, "range %g,%g um is not MIN,MAX with 0 < MIN < MAX <= 10000",
                    s->dmin, s->dmax);
    return 0;
}

double swe_spray_cdf(const swe_spray *s, double x)
{
    return gsl_cdf_ugaussian_P((log(x / s->freeze) - log(s->mvd)) / log(s->sigma_g));
}

double swe_spray_density(const swe_spray *s, double x_m)
{
    const double mu = log(s->mvd * s->freeze * 1e-6), ls = log(s->sigma_g);
    const double z = (log(x_m) - mu) / ls;
    return exp(-0.5 * z * z) / (x_m * ls * 2.5066282746310002) * 1e-6;
}

int swe_spray_classes(const swe_spray *s, const double *d, size_t n, double *w, double *e0,
                      double *e1, char *err, size_t errlen)
{
    int rc = swe_spray_check(s, err, errlen);
    if (rc)
        return rc;
    if (n == 0)
        return fail(err, errlen, "no class");
    for (size_t i = 0; i < n; i++) {
        if (!(d[i] > 0) || (i > 0 && !(d[i] > d[i - 1])))
            return fail(err, errlen, "class diameters must be positive and increasing (%g)", d[i]);
    }
    const double lo = s->dmin * s->freeze, hi = s->dmax * s->freeze;
    const double tot = swe_spray_cdf(s, hi) - swe_spray_cdf(s, lo);
    if (!(tot > 0))
        return fail(err, errlen, "the spray holds no mass in %g .. %g um", lo, hi);
    for (size_t i = 0; i < n; i++) {
        double a = (i == 0) ? lo : sqrt(d[i - 1] * d[i]);
        double b = (i == n - 1) ? hi : sqrt(d[i] * d[i + 1]);
        if (a < lo)
            a = lo;
        if (b > hi)
            b = hi;
        e0[i] = a;
        e1[i] = b;
        w[i] = (b > a) ? (swe_spray_cdf(s, b) - swe_spray_cdf(s, a)) / tot : 0.0;
    }
    return 0;
}

/* a root of f in ln x over [ln lo, ln hi] by bisection (GSL) */
typedef struct {
    const swe_spray *s;
    const double *e0, *e1, *w, *c;
    size_t n;
    double target;
} median_ctx;

static double deposit_below(const median_ctx *m, double x)
{
    double g = 0;
    for (size_t i = 0; i < m->n; i++) {
        const double u = (x < m->e1[i]) ? x : m->e1[i];
        if (u > m->e0[i]) {
            const double f0 = swe_spray_cdf(m->s, m->e0[i]);
            g += m->c[i] * (swe_spray_cdf(m->s, u) - f0) /
                 (swe_spray_cdf(m->s, m->e1[i]) - f0 + 1e-300) * m->w[i];
        }
    }
    return g;
}

static double f_spray(double y, void *p)
{
    const median_ctx *m = p;
    return swe_spray_cdf(m->s, exp(y)) - m->target;
}

static double f_deposit(double y, void *p)
{
    const median_ctx *m = p;
    return deposit_below(m, exp(y)) - m->target;
}

static int bisect(double (*f)(double, void *), median_ctx *m, double *x, char *err, size_t errlen)
{
    const double lo = m->s->dmin * m->s->freeze, hi = m->s->dmax * m->s->freeze;
    gsl_function fn = {f, m};
    gsl_root_fsolver *r = gsl_root_fsolver_alloc(gsl_root_fsolver_bisection);
    if (!r)
        return SWE_ENOMEM;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int status = gsl_root_fsolver_set(r, &fn, log(lo), log(hi));
    for (int it = 0; status == GSL_SUCCESS && it < 200; it++) {
        status = gsl_root_fsolver_iterate(r);
        if (status != GSL_SUCCESS)
            break;
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(r), gsl_root_fsolver_x_upper(r), 1e-14,
                                   0) == GSL_SUCCESS)
            break;
    }
    gsl_set_error_handler(old);
    if (status != GSL_SUCCESS) {
        gsl_root_fsolver_free(r);
        return fail(err, errlen, "the median is not bracketed in %g .. %g um", lo, hi);
    }
    *x = exp(gsl_root_fsolver_root(r));
    gsl_root_fsolver_free(r);
    return 0;
}

int swe_spray_median(const swe_spray *s, double *x, char *err, size_t errlen)
{
    int rc = swe_spray_check(s, err, errlen);
    if (rc)
        return rc;
    median_ctx m = {s, NULL, NULL, NULL, NULL, 0, 0};
    m.target = 0.5 * (swe_spray_cdf(s, s->dmin * s->freeze) + swe_spray_cdf(s, s->dmax * s->freeze));
    return bisect(f_spray, &m, x, err, errlen);
}

int swe_deposit_median(const swe_spray *s, const double *e0, const double *e1, const double *w,
                       const double *c, size_t n, double *x, char *err, size_t errlen)
{
    int rc = swe_spray_check(s, err, errlen);
    if (rc)
        return rc;
    median_ctx m = {s, e0, e1, w, c, n, 0};
    const double all = deposit_below(&m, s->dmax * s->freeze);
    if (!(all > 0))
        return fail(err, errlen, "no class captured anything: no deposit median");
    m.target = 0.5 * all;
    return bisect(f_deposit, &m, x, err, errlen);
}
