/* sww.c - the wall-interaction decision (see sww.h). */
#include "sww_internal.h"
#include "swp_cor.h"
#include "swp_detach.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const num_keys[K_NNUM] = {
    "version", "degree", "vnMin", "vnMax", "dMin", "dMax", "slopeLow", "slopeHigh",
    "rmsResidual", "maxResidual", "yieldVelocity", "reboundNormal", "gamma", "Estar",
    "rhoParticle", "mu", "obliqueSlide", "probabilityPoints"
};

/* The message for a key the regime dictionary does not know (a misspelt
 * yieldVelocity would otherwise leave the rebound elastic without a word). */
static int unknown_key(sww_model *m, const char *key)
{
    return sww_fail(m, SWW_EINVAL, "key '%s' is not a regime key (doc/regime-coeffs.md lists them)",
                    key);
}

/* list keys */
static int is_list_key(const char *key)
{
    return !strcmp(key, "coeffs") || !strcmp(key, "vn") || !strcmp(key, "dCrit")
        || !strcmp(key, "obliqueVt") || !strcmp(key, "obliqueVn") || !strcmp(key, "obliqueDCrit")
        || !strcmp(key, "probabilityD") || !strcmp(key, "probabilityVn")
        || !strcmp(key, "probabilityVt") || !strcmp(key, "probabilityStick") || !strcmp(key, "reboundD")
        || !strcmp(key, "reboundVn") || !strcmp(key, "reboundVt") || !strcmp(key, "reboundEn")
        || !strcmp(key, "reboundEt");
}

int sww_fail(sww_model *m, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->err, sizeof m->err, fmt, ap);
    va_end(ap);
    return code;
}

sww_model *sww_alloc(void)
{
    sww_model *m = calloc(1, sizeof *m);
    if (m) {
        m->vt_max = INFINITY;
        m->vt_dref = 5e-5;
        m->tau_c = INFINITY;
        m->roughness = 1.0;
        m->e_t = 1.0;
    }
    return m;
}

static void oblique_clear(sww_model *m)
{
    free(m->ob_vt);
    free(m->ob_lnv);
    free(m->ob_lnd);
    free(m->ob_s);
    free(m->ob_lnt);
    m->ob_vt = m->ob_lnv = m->ob_lnd = m->ob_s = m->ob_lnt = NULL;
    m->ob_nvt = m->ob_nvn = m->ob_nd = 0;
    m->ob_ready = 0;
}

static void probability_clear(sww_model *m)
{
    free(m->pr_lnd);
    free(m->pr_lnv);
    free(m->pr_p);
    free(m->pr_vt);
    m->pr_lnd = m->pr_lnv = m->pr_p = m->pr_vt = NULL;
    m->pr_nd = m->pr_nvn = m->pr_np = m->pr_nvt = 0;
    m->pr_ready = 0;
}

static void rebound_clear(sww_model *m)
{
    free(m->rb_lnd);
    free(m->rb_lnv);
    free(m->rb_vt);
    free(m->rb_lnt);
    free(m->rb_en);
    free(m->rb_et);
    m->rb_lnd = m->rb_lnv = m->rb_vt = m->rb_lnt = m->rb_en = m->rb_et = NULL;
    m->rb_nd = m->rb_nvn = m->rb_nvt = m->rb_nen = m->rb_net = 0;
    m->rb_ready = 0;
}

void sww_regime_clear(sww_model *m)
{
    free(m->tab_lnv);
    free(m->tab_lnd);
    m->tab_lnv = m->tab_lnd = NULL;
    oblique_clear(m);
    probability_clear(m);
    rebound_clear(m);
    memset(m->num, 0, sizeof m->num);
    memset(m->has, 0, sizeof m->has);
    m->representation = m->basis = 0;
    m->ncoeffs = m->ntab = m->n_vn = m->n_dcrit = 0;
    m->has_vn = m->has_dcrit = 0;
    m->label[0] = '\0';
    m->ready = 0;
}

void sww_free(sww_model *m)
{
    if (!m)
        return;
    sww_regime_clear(m);
    free(m);
}

const char *sww_errmsg(const sww_model *m)
{
    return m ? m->err : "no model";
}

/* ---------------------------------------------------------------- setting */

int sww_regime_number(sww_model *m, const char *key, double v)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    for (int k = 0; k < K_NNUM; k++) {
        if (strcmp(key, num_keys[k]) != 0)
            continue;
        if (!isfinite(v))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g is not a finite number", key, v);
        m->num[k] = v;
        m->has[k] = 1;
        m->ready = 0;
        return SWW_OK;
    }
    if (is_list_key(key))
        return sww_fail(m, SWW_EINVAL, "key '%s': expects a list ( ... ), got the number %g", key, v);
    if (!strcmp(key, "representation") || !strcmp(key, "basis") || !strcmp(key, "label"))
        return sww_fail(m, SWW_EINVAL, "key '%s': expects a word, got the number %g", key, v);
    return unknown_key(m, key);
}

static int set_table_part(sww_model *m, const char *key, const double *v, size_t n, int dcrit)
{
    if (n < 2 || n > SWW_MAX_TABLE)
        return sww_fail(m, SWW_EINVAL, "key '%s': %zu values, a table needs 2 to %d", key, n,
                        SWW_MAX_TABLE);
    double **dst = dcrit ? &m->tab_lnd : &m->tab_lnv;
    double *p = realloc(*dst, n * sizeof *p);
    if (!p)
        return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
    *dst = p;
    for (size_t i = 0; i < n; i++) {
        if (!(v[i] > 0.0))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) must be > 0", key,
                            v[i], i);
        p[i] = log(v[i]);
    }
    if (dcrit) {
        m->has_dcrit = 1;
        m->n_dcrit = n;
    } else {
        for (size_t i = 1; i < n; i++)
            if (!(v[i] > v[i - 1]))
                return sww_fail(m, SWW_EINVAL,
                                "key 'vn': value %g (entry %zu) is not larger than %g: "
                                "the table must be strictly increasing", v[i], i, v[i - 1]);
        m->has_vn = 1;
        m->n_vn = n;
    }
    return SWW_OK;
}

/* The oblique table's lists (checked together at commit): obliqueVt kept as
 * given, obliqueVn and obliqueDCrit as their logarithms. */
static int set_oblique_part(sww_model *m, const char *key, const double *v, size_t n)
{
    const int which = !strcmp(key, "obliqueVt") ? 0 : !strcmp(key, "obliqueVn") ? 1 : 2;
    if (n < (which == 2 ? 4u : 2u) || n > SWW_MAX_TABLE)
        return sww_fail(m, SWW_EINVAL, "key '%s': %zu values, expected %d to %d", key, n,
                        which == 2 ? 4 : 2, SWW_MAX_TABLE);
    double *p = malloc(n * sizeof *p);
    if (!p)
        return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
    for (size_t i = 0; i < n; i++) {
        if (which == 0 ? !(v[i] >= 0.0) : !(v[i] > 0.0)) {
            free(p);
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) must be %s", key, v[i],
                            i, which == 0 ? ">= 0" : "> 0");
        }
        if (which < 2 && i > 0 && !(v[i] > v[i - 1])) {
            free(p);
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not larger than %g: "
                            "the list must be strictly increasing", key, v[i], i, v[i - 1]);
        }
        p[i] = which == 0 ? v[i] : log(v[i]);
    }
    if (which == 0 && v[0] != 0.0) {
        free(p);
        return sww_fail(m, SWW_EINVAL, "key 'obliqueVt': the first value is %g, it must be 0 "
                        "(the head-on row)", v[0]);
    }
    double **dst = which == 0 ? &m->ob_vt : which == 1 ? &m->ob_lnv : &m->ob_lnd;
    size_t *cnt = which == 0 ? &m->ob_nvt : which == 1 ? &m->ob_nvn : &m->ob_nd;
    free(*dst);
    *dst = p;
    *cnt = n;
    m->ob_ready = 0;
    return SWW_OK;
}

/* The stick-probability table's lists (checked together at commit):
 * probabilityD and probabilityVn strictly increasing and > 0, kept as their
 * logarithms; probabilityVt from 0 strictly increasing, kept; probabilityStick
 * in [0, 1] as given. */
static int set_probability_part(sww_model *m, const char *key, const double *v, size_t n)
{
    if (!strcmp(key, "probabilityVt")) {
        if (n < 2 || n > SWW_MAX_TABLE)
            return sww_fail(m, SWW_EINVAL, "key '%s': %zu values, expected 2 to %d", key, n,
                            SWW_MAX_TABLE);
        if (v[0] != 0.0)
            return sww_fail(m, SWW_EINVAL, "key '%s': the first value is %g: the table starts at "
                            "v_t = 0", key, v[0]);
        for (size_t i = 1; i < n; i++)
            if (!(v[i] > v[i - 1]) || isinf(v[i]))
                return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not a finite "
                                "speed larger than %g: the list must be strictly increasing", key,
                                v[i], i, v[i - 1]);
        double *p = malloc(n * sizeof *p);
        if (!p)
            return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
        memcpy(p, v, n * sizeof *p);
        free(m->pr_vt);
        m->pr_vt = p;
        m->pr_nvt = n;
        m->pr_ready = 0;
        return SWW_OK;
    }
    const int which = !strcmp(key, "probabilityD") ? 0 : !strcmp(key, "probabilityVn") ? 1 : 2;
    const size_t nmin = which == 2 ? 4u : 2u;
    if (n < nmin || n > SWW_MAX_TABLE)
        return sww_fail(m, SWW_EINVAL, "key '%s': %zu values, expected %zu to %d", key, n, nmin,
                        SWW_MAX_TABLE);
    for (size_t i = 0; i < n; i++) {
        if (which == 2 && !(v[i] >= 0.0 && v[i] <= 1.0))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not a probability "
                            "in [0, 1]", key, v[i], i);
        if (which < 2 && !(v[i] > 0.0))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) must be > 0", key, v[i],
                            i);
        if (which < 2 && i > 0 && !(v[i] > v[i - 1]))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not larger than %g: "
                            "the list must be strictly increasing", key, v[i], i, v[i - 1]);
    }
    double *p = malloc(n * sizeof *p);
    if (!p)
        return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
    for (size_t i = 0; i < n; i++)
        p[i] = which == 2 ? v[i] : log(v[i]);
    if (which < 2) {
        m->pr_lo[which] = v[0];
        m->pr_hi[which] = v[n - 1];
    }
    double **dst = which == 0 ? &m->pr_lnd : which == 1 ? &m->pr_lnv : &m->pr_p;
    size_t *cnt = which == 0 ? &m->pr_nd : which == 1 ? &m->pr_nvn : &m->pr_np;
    free(*dst);
    *dst = p;
    *cnt = n;
    m->pr_ready = 0;
    return SWW_OK;
}

/* The rebound tables' lists (checked together at commit): reboundD and
 * reboundVn > 0 and strictly increasing, kept as logarithms; reboundVt from 0
 * strictly increasing (kept, and ln v_t of the non-zero nodes); reboundEn and
 * reboundEt factors in [0, 1]. */
static int set_rebound_part(sww_model *m, const char *key, const double *v, size_t n)
{
    const int which = !strcmp(key, "reboundD") ? 0 : !strcmp(key, "reboundVn") ? 1
                    : !strcmp(key, "reboundVt") ? 2 : !strcmp(key, "reboundEn") ? 3 : 4;
    const size_t nmax = which >= 3 ? SWW_MAX_REBOUND : SWW_MAX_TABLE;
    if (n < 2 || n > nmax)
        return sww_fail(m, SWW_EINVAL, "key '%s': %zu values, expected 2 to %zu", key, n, nmax);
    for (size_t i = 0; i < n; i++) {
        if (which >= 3 && !(v[i] >= 0.0 && v[i] <= 1.0))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not a rebound factor "
                            "in [0, 1]", key, v[i], i);
        if (which < 2 && !(v[i] > 0.0))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) must be > 0", key, v[i],
                            i);
        if (which < 3 && i > 0 && !(v[i] > v[i - 1]))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not larger than %g: "
                            "the list must be strictly increasing", key, v[i], i, v[i - 1]);
    }
    if (which == 2 && v[0] != 0.0)
        return sww_fail(m, SWW_EINVAL, "key 'reboundVt': the first value is %g, it must be 0 "
                        "(the head-on layer)", v[0]);
    double *p = malloc(n * sizeof *p), *q = NULL;
    if (!p)
        return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
    for (size_t i = 0; i < n; i++)
        p[i] = which < 2 ? log(v[i]) : v[i];
    if (which == 2) {
        if (!(q = malloc(n * sizeof *q))) {
            free(p);
            return sww_fail(m, SWW_ENOMEM, "key '%s': out of memory", key);
        }
        q[0] = -INFINITY; /* not used: layer 0 is v_t = 0 */
        for (size_t i = 1; i < n; i++)
            q[i] = log(v[i]);
        free(m->rb_lnt);
        m->rb_lnt = q;
    }
    if (which < 2) {
        m->rb_lo[which] = v[0];
        m->rb_hi[which] = v[n - 1];
    }
    double **dst = which == 0 ? &m->rb_lnd : which == 1 ? &m->rb_lnv : which == 2 ? &m->rb_vt
                 : which == 3 ? &m->rb_en : &m->rb_et;
    size_t *cnt = which == 0 ? &m->rb_nd : which == 1 ? &m->rb_nvn : which == 2 ? &m->rb_nvt
                : which == 3 ? &m->rb_nen : &m->rb_net;
    free(*dst);
    *dst = p;
    *cnt = n;
    m->rb_ready = 0;
    return SWW_OK;
}

int sww_regime_list(sww_model *m, const char *key, const double *v, size_t n)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return sww_fail(m, SWW_EINVAL, "key '%s': value %g (entry %zu) is not a finite number",
                            key, v[i], i);
    m->ready = 0;
    if (!strcmp(key, "coeffs")) {
        if (n < 1 || n > SWW_MAX_COEFFS)
            return sww_fail(m, SWW_EINVAL, "key 'coeffs': %zu values, expected 1 to %d", n,
                            SWW_MAX_COEFFS);
        memcpy(m->coeffs, v, n * sizeof *v);
        m->ncoeffs = n;
        return SWW_OK;
    }
    if (!strcmp(key, "vn"))
        return set_table_part(m, key, v, n, 0);
    if (!strcmp(key, "dCrit"))
        return set_table_part(m, key, v, n, 1);
    if (!strcmp(key, "obliqueVt") || !strcmp(key, "obliqueVn") || !strcmp(key, "obliqueDCrit"))
        return set_oblique_part(m, key, v, n);
    if (!strcmp(key, "probabilityD") || !strcmp(key, "probabilityVn")
        || !strcmp(key, "probabilityVt") || !strcmp(key, "probabilityStick"))
        return set_probability_part(m, key, v, n);
    if (!strncmp(key, "rebound", 7) && is_list_key(key))
        return set_rebound_part(m, key, v, n);
    for (int k = 0; k < K_NNUM; k++)
        if (!strcmp(key, num_keys[k]))
            return sww_fail(m, SWW_EINVAL, "key '%s': expects one number, got a list of %zu", key, n);
    if (!strcmp(key, "representation") || !strcmp(key, "basis") || !strcmp(key, "label"))
        return sww_fail(m, SWW_EINVAL, "key '%s': expects a word, got a list of %zu", key, n);
    return unknown_key(m, key);
}

int sww_regime_word(sww_model *m, const char *key, const char *w)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    m->ready = 0;
    if (!strcmp(key, "representation")) {
        if (!strcmp(w, "polynomial"))
            m->representation = 1;
        else if (!strcmp(w, "table"))
            m->representation = 2;
        else
            return sww_fail(m, SWW_EINVAL,
                            "key 'representation': value '%s' is not polynomial or table", w);
        return SWW_OK;
    }
    if (!strcmp(key, "basis")) {
        if (!strcmp(w, "log"))
            m->basis = 1;
        else if (!strcmp(w, "linear"))
            m->basis = 2;
        else
            return sww_fail(m, SWW_EINVAL, "key 'basis': value '%s' is not log or linear", w);
        return SWW_OK;
    }
    if (!strcmp(key, "label")) {
        snprintf(m->label, sizeof m->label, "%s", w);
        return SWW_OK;
    }
    for (int k = 0; k < K_NNUM; k++)
        if (!strcmp(key, num_keys[k]))
            return sww_fail(m, SWW_EINVAL, "key '%s': value '%s' is not a number", key, w);
    if (is_list_key(key))
        return sww_fail(m, SWW_EINVAL, "key '%s': expects a list ( ... ), got '%s'", key, w);
    return unknown_key(m, key);
}

/* ---------------------------------------------------------------- the fit */

/* The cell [lo, lo + 1] of the increasing X[lo..hi] that holds x (bisection;
 * x at or beyond the ends gives the end cell). Returns lo. */
static size_t cell_of(const double *X, size_t lo, size_t hi, double x)
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

/* d_crit inside the range (no range handling). */
static double fit_eval(const sww_model *m, double vn)
{
    if (m->representation == 2) {
        const double x = log(vn);
        const double *X = m->tab_lnv, *Y = m->tab_lnd;
        const size_t last = m->ntab - 1;
        if (x <= X[0])
            return exp(Y[0]);
        if (x >= X[last])
            return exp(Y[last]);
        const size_t lo = cell_of(X, 0, last, x), hi = lo + 1;
        const double t = (x - X[lo]) / (X[hi] - X[lo]);
        return exp(Y[lo] + t * (Y[hi] - Y[lo]));
    }
    const double x = m->basis == 2 ? vn : log(vn);
    double s = m->coeffs[m->ncoeffs - 1];
    for (size_t i = m->ncoeffs - 1; i-- > 0;)
        s = s * x + m->coeffs[i];
    return m->basis == 2 ? s : exp(s);
}

/* a (x/x0)^k for a, x, x0 > 0 and k finite with |k| <= 1e3, without an
 * overflow (issue 22: OpenFOAM traps it): INFINITY beyond e^709 = 8e307,
 * exp of the logarithm where the ratio or the power alone would leave the
 * doubles' range, and exactly a * pow(x / x0, k), as before, everywhere else. */
static double scaled_power(double a, double x, double x0, double k)
{
    const double lr = log(x) - log(x0), lp = k * lr, la = lp + log(a);
    if (la > 709.0)
        return INFINITY;
    if (fabs(lr) > 700.0 || fabs(lp) > 700.0)
        return exp(la); /* at most 8e307; an underflow to 0 is not trapped */
    return a * pow(x / x0, k);
}

double sww_dcrit(const sww_model *m, double vn)
{
    if (!m->ready || isnan(vn))
        return NAN;
    if (vn <= 0.0)
        return INFINITY;
    const double lo = m->num[K_VNMIN], hi = m->num[K_VNMAX];
    if (vn < lo)
        return scaled_power(m->d_lo, vn, lo, m->num[K_SLOPELOW]);
    if (vn > hi)
        return scaled_power(m->d_hi, vn, hi, m->num[K_SLOPEHIGH]);
    return fit_eval(m, vn);
}

/* The oblique table at commit: all three keys or none; sizes; d_crit
 * non-increasing with v_t in every column (2e-3 relative: the kernel's
 * bisection tolerance); ln v_t of the nodes; the tangential limit D_t. */
static int oblique_commit(sww_model *m, const char *o)
{
    m->ob_ready = 0;
    const int n_given = (m->ob_nvt > 0) + (m->ob_nvn > 0) + (m->ob_nd > 0);
    if (n_given == 0)
        return SWW_OK;
    if (n_given < 3)
        return sww_fail(m, SWW_EMISSING, "%s: the oblique table needs obliqueVt, obliqueVn and "
                        "obliqueDCrit together (missing '%s')", o, !m->ob_nvt ? "obliqueVt"
                        : !m->ob_nvn ? "obliqueVn" : "obliqueDCrit");
    if (m->ob_nd != m->ob_nvt * m->ob_nvn)
        return sww_fail(m, SWW_EINVAL, "%s: key 'obliqueDCrit': %zu values, but obliqueVt x "
                        "obliqueVn = %zu x %zu = %zu", o, m->ob_nd, m->ob_nvt, m->ob_nvn,
                        m->ob_nvt * m->ob_nvn);
    if (m->has[K_OBSLIDE] && !(m->num[K_OBSLIDE] >= 0.0))
        return sww_fail(m, SWW_EINVAL, "%s: key 'obliqueSlide': value %g must be >= 0", o,
                        m->num[K_OBSLIDE]);
    for (size_t i = 1; i < m->ob_nvt; i++)
        for (size_t j = 0; j < m->ob_nvn; j++) {
            const double a = m->ob_lnd[(i - 1) * m->ob_nvn + j], b = m->ob_lnd[i * m->ob_nvn + j];
            if (b > a + 2e-3)
                return sww_fail(m, SWW_EINVAL, "%s: key 'obliqueDCrit': d_crit rises from %g to "
                                "%g m between v_t = %g and %g m/s (v_n = %g m/s): it must not "
                                "increase with v_t", o, exp(a), exp(b), m->ob_vt[i - 1],
                                m->ob_vt[i], exp(m->ob_lnv[j]));
        }
    /* The tangential limit D_t: at a node where d_crit lies below the head-on
     * value of its column (by more than the kernel's bisection tolerance) the
     * tangential motion limits sticking and D_t = d_crit; where the normal
     * limit binds, D_t is only known to lie above, and takes the lowest-v_n
     * column's value of the same row (the tangential limit of a flat wall
     * hardly depends on v_n) if that is higher. The wall model then takes
     * min(d_crit(v_n), D_t): the kink between the two limits is exact, not
     * interpolated. */
    const size_t N = m->ob_nvn, K = m->ob_nvt;
    double *sc = realloc(m->ob_s, K * sizeof *sc);
    if (sc)
        m->ob_s = sc;
    double *t = realloc(m->ob_lnt, K * N * sizeof *t);
    if (t)
        m->ob_lnt = t;
    if (!sc || !t)
        return sww_fail(m, SWW_ENOMEM, "%s: out of memory", o);
    sc[0] = -INFINITY;
    for (size_t i = 1; i < K; i++)
        sc[i] = log(m->ob_vt[i]);
    /* uniform spacing in ln v_n (to 1e-9 of a cell): direct indexing */
    const double *X = m->ob_lnv, dx = (X[N - 1] - X[0]) / (double)(N - 1);
    m->ob_dx_inv = 1.0 / dx;
    for (size_t j = 0; j < N; j++)
        if (fabs(X[j] - (X[0] + (double)j * dx)) > 1e-9 * dx)
            m->ob_dx_inv = 0.0;
    const double *D = m->ob_lnd;
    const double tol = 3e-3;
    for (size_t i = 0; i < K; i++)
        for (size_t j = 0; j < N; j++) {
            const double d = D[i * N + j];
            if (i == 0 || d < D[j] - tol)
                t[i * N + j] = d;
            else
                t[i * N + j] = D[i * N] > d ? D[i * N] : d;
        }
    m->ob_ready = 1;
    return SWW_OK;
}

/* The stick-probability table at commit: all three lists or none, M x N
 * values; probabilityPoints (informative) a whole number >= 1. */
static int probability_commit(sww_model *m, const char *o)
{
    m->pr_ready = 0;
    if (m->has[K_PRPOINTS]) {
        const double np = m->num[K_PRPOINTS];
        if (!(np >= 1.0) || np != floor(np))
            return sww_fail(m, SWW_EINVAL, "%s: key 'probabilityPoints': value %g is not a whole "
                            "number >= 1 (impact points per cell)", o, np);
    }
    const int n_given = (m->pr_nd > 0) + (m->pr_nvn > 0) + (m->pr_np > 0);
    if (n_given == 0 && m->pr_nvt > 0)
        return sww_fail(m, SWW_EMISSING, "%s: key 'probabilityVt' without the stick-probability "
                        "table (probabilityD, probabilityVn, probabilityStick)", o);
    if (n_given == 0)
        return SWW_OK;
    if (n_given < 3)
        return sww_fail(m, SWW_EMISSING, "%s: the stick-probability table needs probabilityD, "
                        "probabilityVn and probabilityStick together (missing '%s')", o,
                        !m->pr_nd ? "probabilityD" : !m->pr_nvn ? "probabilityVn"
                        : "probabilityStick");
    if (m->pr_nvt == 0 && m->pr_np != m->pr_nd * m->pr_nvn)
        return sww_fail(m, SWW_EINVAL, "%s: key 'probabilityStick': %zu values, but probabilityD "
                        "x probabilityVn = %zu x %zu = %zu", o, m->pr_np, m->pr_nd, m->pr_nvn,
                        m->pr_nd * m->pr_nvn);
    if (m->pr_nvt > 0 && m->pr_np != m->pr_nd * m->pr_nvt * m->pr_nvn)
        return sww_fail(m, SWW_EINVAL, "%s: key 'probabilityStick': %zu values, but probabilityD "
                        "x probabilityVt x probabilityVn = %zu x %zu x %zu = %zu", o, m->pr_np,
                        m->pr_nd, m->pr_nvt, m->pr_nvn, m->pr_nd * m->pr_nvt * m->pr_nvn);
    /* uniform axes (to 1e-9 of a cell): the cell directly, no search */
    for (int a = 0; a < 2; a++) {
        const double *X = a == 0 ? m->pr_lnd : m->pr_lnv;
        const size_t n = a == 0 ? m->pr_nd : m->pr_nvn;
        m->pr_mode[a] = 0;
        for (int mode = 1; mode <= 2 && !m->pr_mode[a]; mode++) {
            const double x0 = mode == 1 ? X[0] : exp(X[0]);
            const double dx = ((mode == 1 ? X[n - 1] : exp(X[n - 1])) - x0) / (double)(n - 1);
            int uniform = 1;
            for (size_t j = 0; j < n && uniform; j++)
                uniform = fabs((mode == 1 ? X[j] : exp(X[j])) - (x0 + (double)j * dx)) <= 1e-9 * dx;
            if (uniform) {
                m->pr_mode[a] = mode;
                m->pr_x0[a] = x0;
                m->pr_inv[a] = 1.0 / dx;
            }
        }
    }
    m->pr_ready = 1;
    return SWW_OK;
}

/* The rebound tables at commit: reboundD, reboundVn, reboundEn together;
 * reboundVt and reboundEt together; counts K x M x N; the Thornton factor at
 * the last v_n node for the continuation above it. */
static int rebound_commit(sww_model *m, const char *o)
{
    m->rb_ready = 0;
    const int n_given = (m->rb_nd > 0) + (m->rb_nvn > 0) + (m->rb_nen > 0) + (m->rb_nvt > 0)
                      + (m->rb_net > 0);
    if (n_given == 0)
        return SWW_OK;
    if (!m->rb_nd || !m->rb_nvn || !m->rb_nen)
        return sww_fail(m, SWW_EMISSING, "%s: the rebound table needs reboundD, reboundVn and "
                        "reboundEn together (missing '%s')", o, !m->rb_nd ? "reboundD"
                        : !m->rb_nvn ? "reboundVn" : "reboundEn");
    if (m->rb_net && !m->rb_nvt)
        return sww_fail(m, SWW_EMISSING, "%s: key 'reboundEt' needs 'reboundVt' (the tangential "
                        "speeds of its layers)", o);
    if (m->rb_nvt && !m->rb_net)
        return sww_fail(m, SWW_EMISSING, "%s: key 'reboundVt' needs 'reboundEt' (missing "
                        "'reboundEt')", o);
    const size_t K = m->rb_nvt ? m->rb_nvt : 1, M = m->rb_nd, N = m->rb_nvn;
    if (m->rb_nen != K * M * N)
        return sww_fail(m, SWW_EINVAL, "%s: key 'reboundEn': %zu values, but %s reboundD x "
                        "reboundVn = %zu x %zu x %zu = %zu", o, m->rb_nen, m->rb_nvt ?
                        "reboundVt x" : "(no reboundVt) 1 x", K, M, N, K * M * N);
    if (m->rb_net && m->rb_net != K * M * N)
        return sww_fail(m, SWW_EINVAL, "%s: key 'reboundEt': %zu values, but reboundVt x reboundD "
                        "x reboundVn = %zu x %zu x %zu = %zu", o, m->rb_net, K, M, N, K * M * N);
    m->rb_ep_hi = 0.0;
    if (!m->has[K_REBOUND] && m->has[K_YIELD] && m->rb_hi[1] > m->num[K_YIELD])
        m->rb_ep_hi = swp_cor_thornton(m->num[K_YIELD] / m->rb_hi[1]);
    if (!(m->rb_ep_hi > 0.0))
        m->rb_ep_hi = 0.0;
    m->rb_ready = 1;
    return SWW_OK;
}

int sww_regime_commit(sww_model *m, const char *origin)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    const char *o = origin ? origin : "regime";
    m->ready = 0;
    if (!m->representation)
        return sww_fail(m, SWW_EMISSING, "%s: missing key 'representation' (polynomial or table)", o);
    static const int required[] = { K_VNMIN, K_VNMAX, K_SLOPELOW, K_SLOPEHIGH };
    for (size_t i = 0; i < sizeof required / sizeof *required; i++)
        if (!m->has[required[i]])
            return sww_fail(m, SWW_EMISSING, "%s: missing key '%s'", o, num_keys[required[i]]);
    const double lo = m->num[K_VNMIN], hi = m->num[K_VNMAX];
    if (!(lo > 0.0))
        return sww_fail(m, SWW_EINVAL, "%s: key 'vnMin': value %g must be > 0", o, lo);
    if (!(lo < hi))
        return sww_fail(m, SWW_EINVAL, "%s: key 'vnMin': value %g is not below vnMax %g", o, lo, hi);
    if (m->num[K_SLOPELOW] > 0.0)
        return sww_fail(m, SWW_EINVAL, "%s: key 'slopeLow': value %g > 0: the interface must "
                        "be decreasing or flat", o, m->num[K_SLOPELOW]);
    if (m->num[K_SLOPEHIGH] > 0.0)
        return sww_fail(m, SWW_EINVAL, "%s: key 'slopeHigh': value %g > 0: the interface must "
                        "be decreasing or flat", o, m->num[K_SLOPEHIGH]);
    if (m->has[K_VERSION] && m->num[K_VERSION] != 1.0)
        return sww_fail(m, SWW_EINVAL, "%s: key 'version': value %g is not supported (1)", o,
                        m->num[K_VERSION]);
    const char *fitkey;
    if (m->representation == 1) {
        fitkey = "coeffs";
        if (!m->ncoeffs)
            return sww_fail(m, SWW_EMISSING, "%s: missing key 'coeffs' (representation polynomial)", o);
        if (m->has[K_DEGREE] && m->num[K_DEGREE] != (double)(m->ncoeffs - 1))
            return sww_fail(m, SWW_EINVAL, "%s: key 'degree': value %g does not match the %zu "
                            "coeffs (degree %zu)", o, m->num[K_DEGREE], m->ncoeffs, m->ncoeffs - 1);
        /* the other representation's keys are refused, not ignored (hostile sweep,
         * issue 22: a table beside the polynomial was dropped without a word) */
        if (m->has_vn || m->has_dcrit)
            return sww_fail(m, SWW_EINVAL, "%s: key '%s': not used with representation "
                            "polynomial (vn and dCrit belong to representation table)", o,
                            m->has_vn ? "vn" : "dCrit");
    } else {
        if (m->ncoeffs || m->has[K_DEGREE])
            return sww_fail(m, SWW_EINVAL, "%s: key '%s': not used with representation table "
                            "(coeffs and degree belong to representation polynomial)", o,
                            m->ncoeffs ? "coeffs" : "degree");
        fitkey = "dCrit";
        if (!m->has_vn)
            return sww_fail(m, SWW_EMISSING, "%s: missing key 'vn' (representation table)", o);
        if (!m->has_dcrit)
            return sww_fail(m, SWW_EMISSING, "%s: missing key 'dCrit' (representation table)", o);
        if (m->n_vn != m->n_dcrit)
            return sww_fail(m, SWW_EINVAL, "%s: key 'dCrit': %zu values but 'vn' has %zu", o,
                            m->n_dcrit, m->n_vn);
        m->ntab = m->n_vn;
        const double v0 = exp(m->tab_lnv[0]), v1 = exp(m->tab_lnv[m->ntab - 1]);
        if (v0 > lo * (1.0 + 1e-12) || v1 < hi * (1.0 - 1e-12))
            return sww_fail(m, SWW_EINVAL, "%s: key 'vn': table span [%g, %g] does not cover "
                            "[vnMin, vnMax] = [%g, %g]", o, v0, v1, lo, hi);
    }
    if (m->has[K_YIELD] && !(m->num[K_YIELD] > 0.0))
        return sww_fail(m, SWW_EINVAL, "%s: key 'yieldVelocity': value %g must be > 0", o, m->num[K_YIELD]);
    if (m->has[K_REBOUND] && !(m->num[K_REBOUND] >= 0.0 && m->num[K_REBOUND] <= 1.0))
        return sww_fail(m, SWW_EINVAL, "%s: key 'reboundNormal': value %g is not in [0, 1]", o,
                        m->num[K_REBOUND]);
    static const int positive[] = { K_GAMMA, K_ESTAR, K_RHO, K_DMIN, K_DMAX };
    for (size_t i = 0; i < sizeof positive / sizeof *positive; i++)
        if (m->has[positive[i]] && !(m->num[positive[i]] > 0.0))
            return sww_fail(m, SWW_EINVAL, "%s: key '%s': value %g must be > 0", o,
                            num_keys[positive[i]], m->num[positive[i]]);
    if (m->has[K_MU] && !(m->num[K_MU] >= 0.0))
        return sww_fail(m, SWW_EINVAL, "%s: key 'mu': value %g must be >= 0", o, m->num[K_MU]);
    if (m->has[K_DMIN] && m->has[K_DMAX] && !(m->num[K_DMIN] < m->num[K_DMAX]))
        return sww_fail(m, SWW_EINVAL, "%s: keys 'dMin', 'dMax': %g must be below %g", o,
                        m->num[K_DMIN], m->num[K_DMAX]);
    /* the interface inside its range: positive, finite, decreasing or flat */
    const int N = 512;
    double prev = INFINITY, vprev = lo;
    for (int i = 0; i <= N; i++) {
        const double v = i == N ? hi : lo * pow(hi / lo, (double)i / N);
        const double d = fit_eval(m, v);
        if (!(d > 0.0) || !isfinite(d))
            return sww_fail(m, SWW_EINVAL, "%s: key '%s': d_crit(%g m/s) = %g is not a finite "
                            "positive diameter", o, fitkey, v, d);
        if (d > prev * (1.0 + 1e-9))
            return sww_fail(m, SWW_EINVAL, "%s: key '%s': the interface increases from d_crit(%g) "
                            "= %g to d_crit(%g) = %g inside [vnMin, vnMax]: it must be "
                            "decreasing or flat", o, fitkey, vprev, prev, v, d);
        prev = d;
        vprev = v;
    }
    m->d_lo = fit_eval(m, lo);
    m->d_hi = fit_eval(m, hi);
    const int rc_ob = oblique_commit(m, o);
    if (rc_ob != SWW_OK)
        return rc_ob;
    const int rc_pr = probability_commit(m, o);
    if (rc_pr != SWW_OK)
        return rc_pr;
    const int rc_rb = rebound_commit(m, o);
    if (rc_rb != SWW_OK)
        return rc_rb;
    if (m->rb_model == SWW_REBOUND_TABLE && !m->rb_ready)
        return sww_fail(m, SWW_EMISSING, "%s: rebound 'table' needs the kernel's rebound table "
                        "(reboundD, reboundVn, reboundEn: make regime.coeffs with snowregime map)",
                        o);
    if (m->vt_on == 2 && !m->ob_ready && !(m->pr_ready && m->pr_nvt > 0)) {
        m->vt_on = 0;
        return sww_fail(m, SWW_EMISSING, "%s: the regime tangential gate needs the oblique table "
                        "(obliqueVt, obliqueVn, obliqueDCrit: snowregime map --vt 0,...) or a "
                        "rough wall's stick probability over v_t (probabilityVt: snowregime map "
                        "--set wall=lattice --vt 0,...)", o);
    }
    m->ready = 1;
    m->err[0] = '\0';
    /* an adhesion shear gate set before needs the (new) regime's data */
    if (m->shear_on == 2 && !(m->has[K_GAMMA] && m->has[K_ESTAR])) {
        m->shear_on = 0;
        return sww_fail(m, SWW_EMISSING, "%s: the adhesion shear gate needs 'gamma' and "
                        "'Estar' in the regime dictionary", o);
    }
    return SWW_OK;
}

/* ---------------------------------------------------------------- options */

int sww_set_tangential_gate(sww_model *m, double vt_max, double d_ref, double exponent)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(vt_max) || !(vt_max >= 0.0) || isinf(vt_max))
        return sww_fail(m, SWW_EINVAL, "tangential gate: vtMax %g must be a finite speed >= 0", vt_max);
    if (isnan(d_ref) || !(d_ref > 0.0) || isinf(d_ref))
        return sww_fail(m, SWW_EINVAL, "tangential gate: dRef %g must be a finite diameter > 0", d_ref);
    if (isnan(exponent) || !(fabs(exponent) <= 1e3))
        return sww_fail(m, SWW_EINVAL, "tangential gate: exponent %g is outside [-1000, 1000]",
                        exponent);
    m->vt_on = 1;
    m->vt_max = vt_max;
    m->vt_dref = d_ref;
    m->vt_exp = exponent;
    return SWW_OK;
}

int sww_set_tangential_regime(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (!m->ready || !(m->ob_ready || (m->pr_ready && m->pr_nvt > 0)))
        return sww_fail(m, SWW_EMISSING, "tangential gate 'regime': the regime map has no "
                        "oblique table (obliqueVt, obliqueVn, obliqueDCrit: make it with "
                        "snowregime map --vt 0,... --max-slide S) and no rough wall's stick "
                        "probability over v_t (probabilityVt: snowregime map --set wall=lattice "
                        "--vt 0,...)");
    m->vt_on = 2;
    return SWW_OK;
}

/* ln D_t(v_n, v_t) for v_t > 0: the tangential limit (commit), bilinear in
 * ln v_n (clamped to the span) and ln v_t; below the first non-zero node and
 * beyond the last, each column continued as a power law in v_t with its
 * first / last segment's slope (never rising with v_t). */
static double oblique_lndt(const sww_model *m, double vn, double vt)
{
    const size_t N = m->ob_nvn, K = m->ob_nvt;
    const double *X = m->ob_lnv;
    double x = log(vn);
    if (x < X[0])
        x = X[0];
    if (x > X[N - 1])
        x = X[N - 1];
    size_t j;
    if (m->ob_dx_inv > 0.0) {
        /* uniform in ln v_n (as snowregime writes it): the cell directly */
        const double f = (x - X[0]) * m->ob_dx_inv;
        j = f < (double)(N - 2) ? (size_t)f : N - 2;
    } else {
        j = cell_of(X, 0, N - 1, x);
    }
    const size_t jh = j + 1;
    const double tx = (x - X[j]) / (X[jh] - X[j]);
    const double *S = m->ob_s, *D = m->ob_lnt;   /* S[i] = ln vt_i, rows 1..K-1 */
    const double y = log(vt);
    size_t i, ih;
    if (K == 2) {
        i = ih = 1;
    } else if (y <= S[1]) {
        i = 1;
        ih = 2;
    } else if (y >= S[K - 1]) {
        i = K - 2;
        ih = K - 1;
    } else {
        i = cell_of(S, 1, K - 1, y);
        ih = i + 1;
    }
    const double a0 = D[i * N + j] + tx * (D[i * N + jh] - D[i * N + j]);
    if (ih == i)
        return a0;
    const double a1 = D[ih * N + j] + tx * (D[ih * N + jh] - D[ih * N + j]);
    const double slope = (a1 - a0) / (S[ih] - S[i]);
    if (y < S[i] || y > S[ih]) {
        /* outside the nodes: power law, never rising with v_t */
        const double sl = slope < 0.0 ? slope : 0.0;
        return y < S[i] ? a0 + sl * (y - S[i]) : a1 + sl * (y - S[ih]);
    }
    return a0 + slope * (y - S[i]);
}

double sww_dcrit_oblique(const sww_model *m, double vn, double vt)
{
    if (!m->ready || isnan(vn) || isnan(vt))
        return NAN;
    const double dn = sww_dcrit(m, vn);
    if (!m->ob_ready || !(vt > 0.0) || vn <= 0.0)
        return dn;
    if (isinf(vt))
        return 0.0;
    const double dt = exp(oblique_lndt(m, vn, vt));
    return dn < dt ? dn : dt;
}

double sww_oblique_slide(const sww_model *m)
{
    return m->ob_ready && m->has[K_OBSLIDE] ? m->num[K_OBSLIDE] : NAN;
}

int sww_check_oblique_slide(sww_model *m, double slide)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (!isfinite(slide) || slide < 0.0)
        return sww_fail(m, SWW_EINVAL, "tangentialGate slideLength %g must be a finite length "
                        ">= 0 m", slide);
    if (!m->ob_ready)
        return sww_fail(m, SWW_EMISSING, "tangentialGate slideLength %g m: the regime has no "
                        "oblique table (obliqueVt, obliqueVn, obliqueDCrit) to check it against: "
                        "make regime.coeffs with snowregime map --vt 0,... --max-slide %g", slide,
                        slide);
    if (!m->has[K_OBSLIDE])
        return sww_fail(m, SWW_EMISSING, "tangentialGate slideLength %g m: the regime's oblique "
                        "table has no obliqueSlide (the slide length it was made with), so it "
                        "cannot be checked: remake regime.coeffs with snowregime map --vt 0,... "
                        "--max-slide %g (which writes obliqueSlide), or remove slideLength",
                        slide, slide);
    const double made = m->num[K_OBSLIDE];
    if (!(fabs(slide - made) <= 1e-9 * made))
        return sww_fail(m, SWW_EINVAL, "tangentialGate slideLength %g m differs from the regime "
                        "table's obliqueSlide %g m: remake regime.coeffs with snowregime map "
                        "--max-slide %g", slide, made, slide);
    return SWW_OK;
}

int sww_oblique_table(const sww_model *m, size_t *nvt, size_t *nvn)
{
    if (nvt)
        *nvt = m->ob_ready ? m->ob_nvt : 0;
    if (nvn)
        *nvn = m->ob_ready ? m->ob_nvn : 0;
    return m->ob_ready;
}

int sww_probability_table(const sww_model *m, size_t *nd, size_t *nvn)
{
    if (nd)
        *nd = m->pr_ready ? m->pr_nd : 0;
    if (nvn)
        *nvn = m->pr_ready ? m->pr_nvn : 0;
    return m->pr_ready;
}

size_t sww_probability_vt(const sww_model *m, double *vt_max)
{
    const size_t k = m->pr_ready ? m->pr_nvt : 0;
    if (vt_max)
        *vt_max = k ? m->pr_vt[k - 1] : 0.0;
    return k;
}

void sww_set_tangential_off(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    m->vt_on = 0;
}

int sww_set_shear_gate_constant(sww_model *m, double tau_c)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(tau_c) || !(tau_c >= 0.0) || isinf(tau_c))
        return sww_fail(m, SWW_EINVAL, "shear gate: tauCrit %g must be a finite stress >= 0 Pa", tau_c);
    m->shear_on = 1;
    m->tau_c = tau_c;
    return SWW_OK;
}

int sww_set_shear_gate_adhesion(sww_model *m, double roughness)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(roughness) || !(roughness > 0.0 && roughness <= 1.0))
        return sww_fail(m, SWW_EINVAL, "shear gate: roughnessFactor %g is not in (0, 1]", roughness);
    if (!m->has[K_GAMMA])
        return sww_fail(m, SWW_EMISSING, "shear gate model adhesion: missing key 'gamma' "
                        "(work of adhesion) in the regime dictionary");
    if (!m->has[K_ESTAR])
        return sww_fail(m, SWW_EMISSING, "shear gate model adhesion: missing key 'Estar' "
                        "(effective modulus) in the regime dictionary");
    m->shear_on = 2;
    m->roughness = roughness;
    return SWW_OK;
}

void sww_set_shear_off(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    m->shear_on = 0;
}

int sww_set_rebound_tangential(sww_model *m, double e_t)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(e_t) || !(e_t >= 0.0 && e_t <= 1.0))
        return sww_fail(m, SWW_EINVAL, "reboundTangential %g is not in [0, 1]", e_t);
    m->e_t = e_t;
    return SWW_OK;
}

/* ---------------------------------------------------------------- queries */

double sww_rebound_normal(const sww_model *m, double vn)
{
    if (m->has[K_REBOUND])
        return m->num[K_REBOUND];
    if (m->has[K_YIELD])
        /* vn <= V_y is elastic (x >= 1): compared, not divided, so that a
         * subnormal vn cannot overflow the ratio */
        return vn > m->num[K_YIELD] ? swp_cor_thornton(m->num[K_YIELD] / vn) : 1.0;
    return 1.0;
}

/* The cell of axis X (n >= 2 nodes, ln values; span [lo, hi] as values) that
 * holds v and the weight of its upper node: clamped to the end nodes (v at or
 * below lo, v = 0 included, takes the first node without a logarithm). */
static size_t rb_cell(const double *X, size_t n, double v, double lo, double hi, double *t)
{
    if (!(v > lo)) {
        *t = 0.0;
        return 0;
    }
    if (!(v < hi)) {
        *t = 1.0;
        return n - 2;
    }
    const double x = log(v);
    const size_t i = cell_of(X, 0, n - 1, x);
    const double w = (x - X[i]) / (X[i + 1] - X[i]);
    *t = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
    return i;
}

/* Bilinear value of layer k of table T (K x M x N) in cell (i, j). */
static double rb_layer(const double *T, size_t k, size_t M, size_t N, size_t i, double tx,
                       size_t j, double ty)
{
    const double *P0 = T + (k * M + i) * N + j, *P1 = P0 + N;
    return (1.0 - tx) * ((1.0 - ty) * P0[0] + ty * P0[1]) + tx * ((1.0 - ty) * P1[0] + ty * P1[1]);
}

/* One rebound table at (d, v_n, v_t) (see sww_rebound); et: the e_t table,
 * whose layer 0 (v_t = 0) is not used. */
static double rb_eval(const sww_model *m, const double *T, int et, double d, double vn, double vt)
{
    const size_t M = m->rb_nd, N = m->rb_nvn, K = m->rb_nvt ? m->rb_nvt : 1;
    double tx, ty;
    const size_t i = rb_cell(m->rb_lnd, M, d, m->rb_lo[0], m->rb_hi[0], &tx);
    const size_t j = rb_cell(m->rb_lnv, N, vn, m->rb_lo[1], m->rb_hi[1], &ty);
    size_t k0 = 0, k1 = 0;
    double w = 0.0;
    if (K > 1) {
        const double *V = m->rb_vt;
        if (!(vt > 0.0)) {
            k0 = k1 = et ? 1 : 0;
        } else if (vt < V[1]) {
            /* between the head-on layer and the first oblique one: linear in v_t
             * (ln 0 does not exist); e_t has no head-on value: layer 1 */
            k0 = et ? 1 : 0;
            k1 = 1;
            w = vt / V[1];
        } else if (!(vt < V[K - 1])) {
            k0 = k1 = K - 1;
        } else {
            k0 = cell_of(m->rb_lnt, 1, K - 1, log(vt));
            k1 = k0 + 1;
            w = (log(vt) - m->rb_lnt[k0]) / (m->rb_lnt[k1] - m->rb_lnt[k0]);
            w = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
        }
    }
    double e = rb_layer(T, k0, M, N, i, tx, j, ty);
    if (k1 != k0)
        e += w * (rb_layer(T, k1, M, N, i, tx, j, ty) - e);
    /* above the last v_n node: Thornton's plastic law carries e_n on */
    if (!et && m->rb_ep_hi > 0.0 && vn > m->rb_hi[1])
        e *= swp_cor_thornton(m->num[K_YIELD] / vn) / m->rb_ep_hi;
    return e < 0.0 ? 0.0 : (e > 1.0 ? 1.0 : e);
}

int sww_rebound_uses_table(const sww_model *m)
{
    return m->rb_ready && m->rb_model != SWW_REBOUND_CLASSIC;
}

void sww_rebound(const sww_model *m, double d, double vn, double vt, double *e_n, double *e_t)
{
    if (!m->ready || isnan(d) || isnan(vn) || isnan(vt) || !(d > 0.0) || isinf(d)
        || !(vn >= 0.0) || isinf(vn) || !(vt >= 0.0) || isinf(vt)) {
        *e_n = *e_t = NAN;
        return;
    }
    if (sww_rebound_uses_table(m)) {
        *e_n = rb_eval(m, m->rb_en, 0, d, vn, vt);
        *e_t = m->rb_net ? rb_eval(m, m->rb_et, 1, d, vn, vt) : m->e_t;
    } else {
        *e_n = sww_rebound_normal(m, vn);
        *e_t = m->e_t;
    }
}

int sww_rebound_table(const sww_model *m, size_t *nd, size_t *nvn, size_t *nvt)
{
    if (nd)
        *nd = m->rb_ready ? m->rb_nd : 0;
    if (nvn)
        *nvn = m->rb_ready ? m->rb_nvn : 0;
    if (nvt)
        *nvt = m->rb_ready ? (m->rb_nvt ? m->rb_nvt : 1) : 0;
    return m->rb_ready;
}

int sww_set_rebound_model(sww_model *m, int model)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (model != SWW_REBOUND_AUTO && model != SWW_REBOUND_TABLE && model != SWW_REBOUND_CLASSIC)
        return sww_fail(m, SWW_EINVAL, "rebound model %d is not auto (0), table (1) or classic (2)",
                        model);
    if (model == SWW_REBOUND_TABLE && !m->rb_ready)
        return sww_fail(m, SWW_EMISSING, "rebound 'table': the regime map has no rebound table "
                        "(reboundD, reboundVn, reboundEn: make regime.coeffs with snowregime map)");
    m->rb_model = model;
    return SWW_OK;
}

double sww_vt_max(const sww_model *m, double d)
{
    if (isnan(d) || !(d > 0.0) || isinf(d))
        return NAN;
    if (m->vt_on != 1)
        return INFINITY;
    if (m->vt_exp == 0.0 || m->vt_max == 0.0)
        return m->vt_max;
    return scaled_power(m->vt_max, d, m->vt_dref, m->vt_exp);
}

double sww_tau_crit(const sww_model *m, double d)
{
    /* outside [1e-12, 1e3] m the detachment formulas (R^3, R^-4/3) leave the
     * doubles' range: no number, rather than an overflow or 0/0 */
    if (isnan(d) || !(d >= SWW_TAU_D_MIN && d <= SWW_TAU_D_MAX))
        return NAN;
    switch (m->shear_on) {
    case 1:
        return m->tau_c;
    case 2:
        return swp_tau_detach(m->num[K_GAMMA], m->num[K_ESTAR], 0.5 * d,
                              m->has[K_MU] ? m->num[K_MU] : 0.0, m->roughness);
    default:
        return INFINITY;
    }
}

int sww_ready(const sww_model *m) { return m->ready; }
int sww_tangential_on(const sww_model *m) { return m->vt_on; }
int sww_shear_on(const sww_model *m) { return m->shear_on != 0; }
double sww_vn_min(const sww_model *m) { return m->num[K_VNMIN]; }
double sww_vn_max(const sww_model *m) { return m->num[K_VNMAX]; }
const char *sww_label(const sww_model *m) { return m->label; }

sww_class sww_outcome_class(const sww_outcome *o)
{
    if (o->fate == SWW_STICK)
        return SWW_CLASS_STUCK;
    if (o->by_draw)
        return SWW_CLASS_PROBABILITY;
    if (o->fate == SWW_RIPOFF)
        return SWW_CLASS_SHEAR;
    return o->reason == SWW_BY_TANGENTIAL ? SWW_CLASS_TANGENTIAL : SWW_CLASS_CRITERION;
}

const char *sww_class_name(sww_class c)
{
    switch (c) {
    case SWW_CLASS_STUCK: return "stuck";
    case SWW_CLASS_CRITERION: return "criterion";
    case SWW_CLASS_TANGENTIAL: return "tangential";
    case SWW_CLASS_SHEAR: return "shear";
    case SWW_CLASS_PROBABILITY: return "probability";
    default: return "?";
    }
}

const char *sww_fate_name(sww_fate f)
{
    switch (f) {
    case SWW_STICK: return "stick";
    case SWW_BOUNCE: return "bounce";
    case SWW_RIPOFF: return "ripoff";
    }
    return "?";
}

void sww_describe(const sww_model *m, char *buf, size_t n)
{
    if (!n)
        return;
    if (!m->ready) {
        snprintf(buf, n, "snowWall: no regime map loaded");
        return;
    }
    char reb[160], vt[128], sh[128];
    if (sww_rebound_uses_table(m) && m->rb_nvt)
        snprintf(reb, sizeof reb, "e_n, e_t kernel table %zu x %zu x %zu (v_t 0..%g m/s, d %g..%g "
                 "m, v_n %g..%g m/s)", m->rb_nvt, m->rb_nd, m->rb_nvn, m->rb_vt[m->rb_nvt - 1],
                 m->rb_lo[0], m->rb_hi[0], m->rb_lo[1], m->rb_hi[1]);
    else if (sww_rebound_uses_table(m))
        snprintf(reb, sizeof reb, "e_n kernel table %zu x %zu (d %g..%g m, v_n %g..%g m/s)",
                 m->rb_nd, m->rb_nvn, m->rb_lo[0], m->rb_hi[0], m->rb_lo[1], m->rb_hi[1]);
    else if (m->has[K_REBOUND])
        snprintf(reb, sizeof reb, "e_n %g", m->num[K_REBOUND]);
    else if (m->has[K_YIELD])
        snprintf(reb, sizeof reb, "e_n Thornton(V_y %g m/s)", m->num[K_YIELD]);
    else
        snprintf(reb, sizeof reb, "e_n 1 (no yieldVelocity/reboundNormal)");
    if (m->vt_on == 1)
        snprintf(vt, sizeof vt, "on: vtMax %g m/s (d/%g m)^%g", m->vt_max, m->vt_dref, m->vt_exp);
    else if (m->vt_on == 2 && m->ob_ready)
        snprintf(vt, sizeof vt, "on: regime table %zu x %zu (v_t 0..%g m/s, slide %g m)",
                 m->ob_nvt, m->ob_nvn, m->ob_vt[m->ob_nvt - 1], m->num[K_OBSLIDE]);
    else if (m->vt_on == 2)
        snprintf(vt, sizeof vt, "on: the rough wall's stick probability over v_t 0..%g m/s "
                 "(%zu nodes; beyond: the last)", m->pr_vt[m->pr_nvt - 1], m->pr_nvt);
    else
        snprintf(vt, sizeof vt, "off");
    if (m->shear_on == 1)
        snprintf(sh, sizeof sh, "on: tau_c %g Pa", m->tau_c);
    else if (m->shear_on == 2)
        snprintf(sh, sizeof sh, "on: adhesion, roughness %g, tau_c(50 um) %.4g Pa", m->roughness,
                 sww_tau_crit(m, 5e-5));
    else
        snprintf(sh, sizeof sh, "off");
    char et[48] = "";
    if (!(sww_rebound_uses_table(m) && m->rb_net))
        snprintf(et, sizeof et, ", e_t %g", m->e_t);
    char pr[192] = "";
    if (m->pr_ready && m->pr_nvt)
        snprintf(pr, sizeof pr, "; stick probability table %zu x %zu x %zu (d %g..%g m, v_t 0..%g "
                 "m/s, v_n %g..%g m/s; outside: the interface)", m->pr_nd, m->pr_nvt, m->pr_nvn,
                 exp(m->pr_lnd[0]), exp(m->pr_lnd[m->pr_nd - 1]), m->pr_vt[m->pr_nvt - 1],
                 exp(m->pr_lnv[0]), exp(m->pr_lnv[m->pr_nvn - 1]));
    else if (m->pr_ready)
        snprintf(pr, sizeof pr, "; stick probability table %zu x %zu (d %g..%g m, v_n %g..%g m/s; "
                 "outside: the interface)", m->pr_nd, m->pr_nvn, exp(m->pr_lnd[0]),
                 exp(m->pr_lnd[m->pr_nd - 1]), exp(m->pr_lnv[0]), exp(m->pr_lnv[m->pr_nvn - 1]));
    snprintf(buf, n, "'%s' %s, vn [%g, %g] m/s, d_crit(vnMin) %.4g m, d_crit(vnMax) %.4g m, "
             "slopes %g/%g; %s%s; tangential gate %s; shear gate %s%s",
             m->label, m->representation == 2 ? "table" : (m->basis == 2 ? "polynomial(linear)"
             : "polynomial(log)"), m->num[K_VNMIN], m->num[K_VNMAX], m->d_lo, m->d_hi,
             m->num[K_SLOPELOW], m->num[K_SLOPEHIGH], reb, et, vt, sh, pr);
}

/* ---------------------------------------------------------------- decide */

/* The cell [i, i + 1] of the probability table's axis a that holds x (the
 * stored ln value, inside the axis' span; xv the value itself): directly on
 * a uniform axis (a rounding step at a node corrected), else by bisection. */
static size_t prob_cell(const sww_model *m, int a, const double *X, size_t n, double x, double xv)
{
    if (!m->pr_mode[a])
        return cell_of(X, 0, n - 1, x);
    const double f = ((m->pr_mode[a] == 1 ? x : xv) - m->pr_x0[a]) * m->pr_inv[a];
    size_t i = f > 0.0 ? (f < (double)(n - 2) ? (size_t)f : n - 2) : 0;
    while (i > 0 && x < X[i])
        i--;
    while (i < n - 2 && x > X[i + 1])
        i++;
    return i;
}

/* The stick probability: with a rough wall's table (probabilityStick), inside
 * its span [d_1, d_M] x [v_1, v_N] bilinear in (ln d, ln v_n), exact at the
 * nodes; elsewhere, and without a table, the interface's sharp decision
 * (1 for d <= d_crit(v_n), else 0). A table over v_t too (probabilityVt) is
 * read at v_t: linear between its layers, the last layer beyond them; vt < 0
 * reads the v_t = 0 layer. Reads the model only, allocates nothing. */
static double stick_probability(const sww_model *m, double d, double vn, double vt, double d_crit)
{
    if (m->pr_ready && d >= m->pr_lo[0] && d <= m->pr_hi[0] && vn >= m->pr_lo[1]
        && vn <= m->pr_hi[1]) {
        const size_t M = m->pr_nd, N = m->pr_nvn, K = m->pr_nvt ? m->pr_nvt : 1;
        const double *X = m->pr_lnd, *Y = m->pr_lnv;
        const double x = log(d), y = log(vn);
        const size_t i = prob_cell(m, 0, X, M, x, d), j = prob_cell(m, 1, Y, N, y, vn);
        const double tx = (x - X[i]) / (X[i + 1] - X[i]), ty = (y - Y[j]) / (Y[j + 1] - Y[j]);
        /* the v_t layers k, k + 1 and the weight of k + 1 */
        size_t k = 0;
        double tz = 0.0;
        if (K > 1 && vt > 0.0) {
            if (vt >= m->pr_vt[K - 1]) {
                k = K - 2;
                tz = 1.0;
            } else {
                while (k < K - 2 && vt >= m->pr_vt[k + 1])
                    k++;
                tz = (vt - m->pr_vt[k]) / (m->pr_vt[k + 1] - m->pr_vt[k]);
            }
        }
        double p = 0.0;
        for (int l = 0; l < 2; l++) {
            const double w = l ? tz : 1.0 - tz;
            if (w == 0.0)
                continue;
            const double *P0 = m->pr_p + (i * K + k + (size_t)l) * N + j, *P1 = P0 + K * N;
            p += w * ((1.0 - tx) * ((1.0 - ty) * P0[0] + ty * P0[1])
                      + tx * ((1.0 - ty) * P1[0] + ty * P1[1]));
        }
        return p < 0.0 ? 0.0 : (p > 1.0 ? 1.0 : p);
    }
    return d <= d_crit ? 1.0 : 0.0;
}

int sww_decide(const sww_model *m, const sww_impact *in, sww_outcome *out)
{
    if (!m->ready)
        return SWW_ENOTREADY;
    /* NaN first: an ordered comparison of a NaN raises FE_INVALID (issue 22) */
    if (isnan(in->d) || isnan(in->vn) || isnan(in->vt) || isnan(in->u)
        || !(in->d > 0.0) || isinf(in->d) || !(in->vn >= 0.0) || isinf(in->vn)
        || !(in->vt >= 0.0) || isinf(in->vt) || !(in->u >= 0.0 && in->u < 1.0))
        return SWW_EINVAL;
    /* with the shear gate on, tau_w is an input of every impact, checked here
     * and not only when a stick candidate reaches the gate (issue 22): a bad
     * value is found at the first impact, not at the first stick candidate */
    if (m->shear_on && (isnan(in->tau_w) || !(in->tau_w >= 0.0) || isinf(in->tau_w)))
        return SWW_EINVAL;
    const double dc = sww_dcrit(m, in->vn);
    out->d_crit = dc;
    out->range = in->vn < m->num[K_VNMIN] ? -1 : (in->vn > m->num[K_VNMAX] ? 1 : 0);
    /* a rough wall's table over v_t is read at v_t with the regime gate on,
     * else at v_t = 0: a gate that is off leaves v_t out */
    const int pr_vt = m->vt_on == 2 && m->pr_ready && m->pr_nvt > 0;
    out->p_stick = stick_probability(m, in->d, in->vn, pr_vt ? in->vt : -1.0, dc);
    out->reason = SWW_BY_CRITERION;
    int stick = in->u < out->p_stick;
    out->by_draw = !stick && out->p_stick > 0.0;
    if (!stick && pr_vt && in->vt > 0.0 && in->u < stick_probability(m, in->d, in->vn, -1.0, dc)) {
        /* it would stick at v_t = 0: the tangential motion made it bounce */
        out->by_draw = 0;
        out->reason = SWW_BY_TANGENTIAL;
    }
    if (stick && m->vt_on == 1 && in->vt > sww_vt_max(m, in->d)) {
        stick = 0;
        out->reason = SWW_BY_TANGENTIAL;
    } else if (stick && m->vt_on == 2 && m->ob_ready && in->vt > 0.0 && in->vn > 0.0
               && (isinf(in->vt) || log(in->d) > oblique_lndt(m, in->vn, in->vt))) {
        /* a stick candidate (d <= d_crit(v_n), or by the rough wall's
         * probability): the tangential limit decides */
        stick = 0;
        out->reason = SWW_BY_TANGENTIAL;
    }
    if (stick && m->shear_on) {
        /* a diameter so large that tau_c is not a number is refused, not a
         * gate that silently never fires */
        const double tc = sww_tau_crit(m, in->d);
        if (isnan(tc))
            return SWW_EINVAL;
        if (in->tau_w >= tc) {
            out->fate = SWW_RIPOFF;
            out->reason = SWW_BY_SHEAR;
            sww_rebound(m, in->d, in->vn, in->vt, &out->e_n, &out->e_t);
            return SWW_OK;
        }
    }
    if (stick) {
        out->fate = SWW_STICK;
        out->e_n = out->e_t = 1.0;
    } else {
        out->fate = SWW_BOUNCE;
        sww_rebound(m, in->d, in->vn, in->vt, &out->e_n, &out->e_t);
    }
    return SWW_OK;
}

/* ---------------------------------------------------------------- draws */

static unsigned long long mix64(unsigned long long z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double sww_uniform_hash(unsigned long long seed, long long a, long long b, long long c,
                        long long k)
{
    unsigned long long h = mix64(seed);
    h = mix64(h ^ (unsigned long long)a);
    h = mix64(h ^ (unsigned long long)b);
    h = mix64(h ^ (unsigned long long)c);
    h = mix64(h ^ (unsigned long long)k);
    return (double)(h >> 11) * 0x1.0p-53; /* [0, 1 - 2^-53] */
}

/* ---------------------------------------------------------------- build-up */

double sww_monolayer_mass(double rho, double d)
{
    /* isfinite first: an ordered comparison of a NaN raises FE_INVALID */
    if (!isfinite(rho) || !isfinite(d) || rho <= 0.0 || d <= 0.0)
        return NAN;
    if (rho > 1.0 && d > DBL_MAX / rho)
        return INFINITY; /* the product would overflow */
    /* hexagonally close-packed spheres on a plane: area fraction pi/(2 sqrt 3),
     * a sphere's mass over its projected area (2/3) rho d */
    return M_PI / (2.0 * sqrt(3.0)) * (2.0 / 3.0) * rho * d;
}

double sww_cover_fraction(double mass_per_area, double cover_mass)
{
    if (isnan(mass_per_area) || isnan(cover_mass) || cover_mass <= 0.0)
        return NAN;
    if (mass_per_area <= 0.0)
        return 0.0;
    /* compared before dividing: a tiny cover_mass cannot overflow the ratio */
    return mass_per_area < cover_mass ? mass_per_area / cover_mass : 1.0;
}

int sww_decide_blend(const sww_model *bare, const sww_model *covered, double w,
                     const sww_impact *in, sww_outcome *out)
{
    if (isnan(w) || !(w >= 0.0 && w <= 1.0))
        return SWW_EINVAL;
    if (w == 0.0 || !covered)
        return sww_decide(bare, in, out);
    if (w == 1.0)
        return sww_decide(covered, in, out);
    /* each regime's own stick probability with its gates, the random number
     * aside: with u = 0 a regime sticks whenever its p_stick > 0 and no gate
     * stops it; a gated-off stick candidate has p = 0 */
    sww_impact in0 = *in;
    in0.u = 0.0;
    sww_outcome ob, oc;
    int rc = sww_decide(bare, &in0, &ob);
    if (rc != SWW_OK)
        return rc;
    rc = sww_decide(covered, &in0, &oc);
    if (rc != SWW_OK)
        return rc;
    if (isnan(in->u) || !(in->u >= 0.0 && in->u < 1.0))
        return SWW_EINVAL;
    const double pb = ob.fate == SWW_STICK ? ob.p_stick : 0.0;
    const double pc = oc.fate == SWW_STICK ? oc.p_stick : 0.0;
    const double p = (1.0 - w) * pb + w * pc;
    /* sticks with the blended probability, with the outcome of the regime more
     * likely to stick; otherwise the outcome of the regime less likely to
     * stick (ties: the covered one when w >= 1/2), a bounce by the criterion
     * when that regime would have stuck at u = 0 */
    const int stick = in->u < p;
    const int use_cov = stick ? (pc > pb ? 1 : (pb > pc ? 0 : w >= 0.5))
                              : (pc < pb ? 1 : (pb < pc ? 0 : w >= 0.5));
    *out = use_cov ? oc : ob;
    out->by_draw = !stick && p > 0.0;
    if (!stick && out->fate == SWW_STICK) {
        const sww_model *r = use_cov ? covered : bare;
        out->fate = SWW_BOUNCE;
        out->reason = SWW_BY_CRITERION;
        sww_rebound(r, in->d, in->vn, in->vt, &out->e_n, &out->e_t);
    }
    out->p_stick = p;
    out->d_crit = (1.0 - w) * ob.d_crit + w * oc.d_crit;
    return SWW_OK;
}
