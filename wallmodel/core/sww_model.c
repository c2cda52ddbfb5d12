/* sww_model.c - the wall-interaction model's lifecycle (see sww.h): sww_alloc
 * with the options' defaults, sww_regime_clear (the regime and its tables
 * dropped, the options kept), sww_free, and the message of the last failed
 * call (sww_fail, sww_errmsg). */
#include "sww_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
