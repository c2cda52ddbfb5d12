/* sww_rebound.c - the rebound of a bouncing particle (see sww.h): e_n from
 * reboundNormal, Thornton's plastic law (yieldVelocity) or the kernel's
 * rebound tables (reboundEn, reboundEt over d, v_n and v_t), e_t the
 * constant or the table. */
#include "sww_internal.h"
#include "swp_cor.h"

#include <math.h>
#include <stddef.h>

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
    const size_t i = sww_cell_of(X, 0, n - 1, x);
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
            k0 = sww_cell_of(m->rb_lnt, 1, K - 1, log(vt));
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
