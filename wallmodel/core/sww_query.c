/* sww_query.c - read-only queries of a model (see sww.h): the stick-probability
 * table's shape, the state of the regime and gates, the outcome classes and
 * fates by name, and the one-line description of a model (sww_describe). */
#include "sww_internal.h"

#include <math.h>
#include <stdio.h>

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
