/* sww_regime.c - setting the regime dictionary's keys (see sww.h): one number,
 * list or word at a time (sww_regime_number / _list / _word, the path of
 * sww_regime_load too), each value checked on its own and the tables' lists
 * kept in the form the lookups use; the checks of the keys together are the
 * commit's (sww_fit.c). */
#include "sww_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const sww_num_keys[K_NNUM] = {
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

int sww_regime_number(sww_model *m, const char *key, double v)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    for (int k = 0; k < K_NNUM; k++) {
        if (strcmp(key, sww_num_keys[k]) != 0)
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
        if (!strcmp(key, sww_num_keys[k]))
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
        if (!strcmp(key, sww_num_keys[k]))
            return sww_fail(m, SWW_EINVAL, "key '%s': value '%s' is not a number", key, w);
    if (is_list_key(key))
        return sww_fail(m, SWW_EINVAL, "key '%s': expects a list ( ... ), got '%s'", key, w);
    return unknown_key(m, key);
}
