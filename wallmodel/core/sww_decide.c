/* sww_decide.c - the decision for one impact (see sww.h): the stick
 * probability (the rough wall's table or the interface's sharp criterion),
 * then the tangential and shear gates, then the rebound of a bounce. */
#include "sww_internal.h"

#include <math.h>
#include <stddef.h>

/* The cell [i, i + 1] of the probability table's axis a that holds x (the
 * stored ln value, inside the axis' span; xv the value itself): directly on
 * a uniform axis (a rounding step at a node corrected), else by bisection. */
static size_t prob_cell(const sww_model *m, int a, const double *X, size_t n, double x, double xv)
{
    if (!m->pr_mode[a])
        return sww_cell_of(X, 0, n - 1, x);
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
    /* NaN first: an ordered comparison of a NaN raises FE_INVALID (trapped in OpenFOAM) */
    if (isnan(in->d) || isnan(in->vn) || isnan(in->vt) || isnan(in->u)
        || !(in->d > 0.0) || isinf(in->d) || !(in->vn >= 0.0) || isinf(in->vn)
        || !(in->vt >= 0.0) || isinf(in->vt) || !(in->u >= 0.0 && in->u < 1.0))
        return SWW_EINVAL;
    /* with the shear gate on, tau_w is an input of every impact, checked here
     * and not only when a stick candidate reaches the gate: a bad
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
               && (isinf(in->vt) || log(in->d) > sww_oblique_lndt(m, in->vn, in->vt))) {
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
