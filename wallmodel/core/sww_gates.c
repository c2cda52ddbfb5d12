/* sww_gates.c - the limits the gates apply (see sww.h): the tangential limit
 * D_t(v_n, v_t) of the regime's oblique table and d_crit(v_n, v_t) with it,
 * the constant gate's vtMax(d), and the shear gate's critical stress
 * tau_c(d). */
#include "sww_internal.h"
#include "swp_detach.h"

#include <math.h>
#include <stddef.h>

/* ln D_t(v_n, v_t) for v_t > 0: the tangential limit (commit), bilinear in
 * ln v_n (clamped to the span) and ln v_t; below the first non-zero node and
 * beyond the last, each column continued as a power law in v_t with its
 * first / last segment's slope (never rising with v_t). */
double sww_oblique_lndt(const sww_model *m, double vn, double vt)
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
        j = sww_cell_of(X, 0, N - 1, x);
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
        i = sww_cell_of(S, 1, K - 1, y);
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
    const double dt = exp(sww_oblique_lndt(m, vn, vt));
    return dn < dt ? dn : dt;
}

double sww_oblique_slide(const sww_model *m)
{
    return m->ob_ready && m->has[K_OBSLIDE] ? m->num[K_OBSLIDE] : NAN;
}

int sww_oblique_table(const sww_model *m, size_t *nvt, size_t *nvn)
{
    if (nvt)
        *nvt = m->ob_ready ? m->ob_nvt : 0;
    if (nvn)
        *nvn = m->ob_ready ? m->ob_nvn : 0;
    return m->ob_ready;
}

double sww_vt_max(const sww_model *m, double d)
{
    if (isnan(d) || !(d > 0.0) || isinf(d))
        return NAN;
    if (m->vt_on != 1)
        return INFINITY;
    if (m->vt_exp == 0.0 || m->vt_max == 0.0)
        return m->vt_max;
    return sww_scaled_power(m->vt_max, d, m->vt_dref, m->vt_exp);
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
