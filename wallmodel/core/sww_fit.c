/* sww_fit.c - the interface d_crit(v_n) (see sww.h): the fit inside
 * [vnMin, vnMax] (polynomial or table) and its power-law continuation beyond
 * (sww_dcrit); sww_regime_commit, which checks the regime's keys together
 * (the interface, the oblique, stick-probability and rebound tables) and
 * derives what the lookups need from them. */
#include "sww_internal.h"
#include "swp_cor.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
        const size_t lo = sww_cell_of(X, 0, last, x), hi = lo + 1;
        const double t = (x - X[lo]) / (X[hi] - X[lo]);
        return exp(Y[lo] + t * (Y[hi] - Y[lo]));
    }
    const double x = m->basis == 2 ? vn : log(vn);
    double s = m->coeffs[m->ncoeffs - 1];
    for (size_t i = m->ncoeffs - 1; i-- > 0;)
        s = s * x + m->coeffs[i];
    return m->basis == 2 ? s : exp(s);
}

double sww_dcrit(const sww_model *m, double vn)
{
    if (!m->ready || isnan(vn))
        return NAN;
    if (vn <= 0.0)
        return INFINITY;
    const double lo = m->num[K_VNMIN], hi = m->num[K_VNMAX];
    if (vn < lo)
        return sww_scaled_power(m->d_lo, vn, lo, m->num[K_SLOPELOW]);
    if (vn > hi)
        return sww_scaled_power(m->d_hi, vn, hi, m->num[K_SLOPEHIGH]);
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
            return sww_fail(m, SWW_EMISSING, "%s: missing key '%s'", o, sww_num_keys[required[i]]);
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
        /* the other representation's keys are refused, not ignored (a table
         * beside the polynomial would otherwise be dropped without a word) */
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
                            sww_num_keys[positive[i]], m->num[positive[i]]);
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
