/* swd_load.c - reader of the sublayer closure's file (deposition.coeffs, written
 * by `snowdeposit calibrate`) for hosts without a dictionary reader of their own
 * (Code_Saturne, a Fluent UDF); see swd.h, swd_load_closure.
 *
 * The file is the subset of OpenFOAM dictionary syntax that the calibration
 * writes: `//` and C comments, `key value;`, `key ( v v ... );` and one
 * sub-dictionary `depositionClosure { ... }`, whose numbers are read; every other
 * entry is skipped. The tokens come from swx_lex.h (its dialect 0: no strings,
 * a lexer that never fails); the keys and the messages are here. */
#include "swd.h"
#include "swd_internal.h"

#include "swx_lex.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SWD_MAX_FILE (1L << 20)
#define SWD_MAX_LIST 4096

typedef struct {
    swx_lex lx;                 /* the tokens: dialect 0, never an error */
    char *err;
    size_t errlen;
} rd;

static int rfail(rd *r, int line, const char *fmt, const char *a, const char *b)
{
    char msg[320];
    snprintf(msg, sizeof msg, fmt, a ? a : "", b ? b : "");
    snprintf(r->err, r->errlen, "%s:%d: %s", r->lx.path, line, msg);
    return SWD_EINVAL;
}

/* the next token (this dialect has no lexer errors) */
static swx_kind next(rd *r)
{
    (void)swx_next(&r->lx);
    return r->lx.kind;
}

/* Is the current token a word (not the empty word at a NUL byte)? Its text,
 * or the character of ( ) { } ;, in w for the messages, cut to 63 characters. */
static int word(const rd *r, char w[64])
{
    snprintf(w, 64, "%.63s", r->lx.text);
    return r->lx.kind == SWX_WORD && r->lx.len > 0;
}

/* a strict decimal number, finite */
static int number(const char *w, double *v)
{
    return swx_number(w, v) && isfinite(*v);
}

/* The entries of the closure sub-dictionary that matter. */
typedef struct {
    double sub;                 /* sublayerYPlus (NAN: missing)   */
    double crw[4];              /* layerYPlus blendYPlus CT Cmu   */
    int crw_line[4];
    double *tau, *vs;
    size_t ntau, nvs;
    int tau_line, vs_line;
} closure;

static const char *const crw_keys[4] = { "layerYPlus", "blendYPlus", "CT", "Cmu" };

/* a list ( v v ... ) after its key, at its '('; *out malloc'ed */
static int read_list(rd *r, const char *key, double **out, size_t *n)
{
    double *v = malloc(SWD_MAX_LIST * sizeof *v);
    if (!v)
        return rfail(r, r->lx.line, "key '%s': out of memory%s", key, NULL);
    size_t k = 0;
    for (;;) {
        const swx_kind t = next(r);
        if (t == SWX_EOF) {
            free(v);
            return rfail(r, r->lx.line, "key '%s': the list has no closing ')'%s", key, NULL);
        }
        if (t == SWX_RPAR)
            break;
        char w[64];
        if (!word(r, w)) {
            free(v);
            return rfail(r, r->lx.tline, "key '%s': '%s' inside the list", key, w);
        }
        if (r->lx.len >= sizeof w) {
            free(v);
            return rfail(r, r->lx.tline, "key '%s': a value longer than 63 characters ('%s...')",
                         key, w);
        }
        if (k == SWD_MAX_LIST) {
            free(v);
            return rfail(r, r->lx.tline, "key '%s': more than 4096 values%s", key, NULL);
        }
        if (!number(w, &v[k])) {
            free(v);
            return rfail(r, r->lx.tline, "key '%s': '%s' is not a finite number", key, w);
        }
        k++;
    }
    *out = v;
    *n = k;
    return SWD_OK;
}

/* one value after its key (inside: 1 in depositionClosure) */
static int read_value(rd *r, const char *key, int line, int inside, closure *c)
{
    char w[64];
    if (!word(r, w))
        return rfail(r, line, "key '%s': no value%s", key, NULL);
    if (r->lx.len >= sizeof w && inside)
        return rfail(r, line, "key '%s': a value longer than 63 characters ('%s...')", key, w);
    if (inside) {
        double v;
        int k = -1;
        for (int i = 0; i < 4; i++)
            if (!strcmp(key, crw_keys[i]))
                k = i;
        if ((k >= 0 || !strcmp(key, "sublayerYPlus")) && !number(w, &v))
            return rfail(r, line, "key '%s': '%s' is not a finite number", key, w);
        if (k >= 0)
            c->crw[k] = v, c->crw_line[k] = line;
        else if (!strcmp(key, "sublayerYPlus"))
            c->sub = v;
    }
    return SWD_OK;
}

/* the entries of a dictionary up to its '}' (inside: 1 in depositionClosure) */
static int read_dict(rd *r, int inside, int depth, closure *c, int *found)
{
    for (;;) {
        swx_kind t = next(r);
        if (t == SWX_EOF)
            return depth ? rfail(r, r->lx.line, "a sub-dictionary has no closing '}'%s%s", NULL, NULL)
                         : SWD_OK;
        if (t == SWX_RBRACE) {
            if (!depth)
                return rfail(r, r->lx.tline, "a '}' without its '{'%s%s", NULL, NULL);
            return SWD_OK;
        }
        char key[64];
        const int line = r->lx.tline;
        const int is_word = word(r, key);
        if (r->lx.len >= sizeof key)
            return rfail(r, line, "a keyword longer than 63 characters ('%s...')", key, NULL);
        if (!is_word)
            return rfail(r, line, "expected a keyword, found '%s'%s", key, NULL);
        t = next(r);
        if (t == SWX_EOF)
            return rfail(r, line, "key '%s': no value%s", key, NULL);
        if (t == SWX_LBRACE) {
            if (depth > 8)
                return rfail(r, line, "sub-dictionaries nested too deep%s%s", NULL, NULL);
            const int is_cl = depth == 0 && !strcmp(key, "depositionClosure");
            if (is_cl && *found)
                return rfail(r, line, "sub-dictionary 'depositionClosure' appears twice%s%s", NULL,
                             NULL);
            *found |= is_cl;
            const int rc = read_dict(r, is_cl, depth + 1, c, found);
            if (rc)
                return rc;
            continue;
        }
        if (t == SWX_LPAR) {
            double *v = NULL;
            size_t n = 0;
            const int rc = read_list(r, key, &v, &n);
            if (rc)
                return rc;
            if (inside && !strcmp(key, "tauPlus") && !c->tau) {
                c->tau = v, c->ntau = n, c->tau_line = line;
            } else if (inside && !strcmp(key, "vPlusSublayer") && !c->vs) {
                c->vs = v, c->nvs = n, c->vs_line = line;
            } else {
                free(v);
                if (inside && (!strcmp(key, "tauPlus") || !strcmp(key, "vPlusSublayer")))
                    return rfail(r, line, "key '%s' appears twice%s", key, NULL);
            }
        } else {
            const int rc = read_value(r, key, line, inside, c);
            if (rc)
                return rc;
        }
        if (next(r) != SWX_SEMI)
            return rfail(r, line, "key '%s': no ';' after its value%s", key, NULL);
    }
}

int swd_load_closure(swd_model *m, const char *path)
{
    char err[600] = "";
    if (!path)
        return swd_fail_message(m, "near-wall closure: no file name");
    rd r = { .err = err, .errlen = sizeof err };
    const int read = swx_read(&r.lx, path, SWD_MAX_FILE, 0);
    if (read) {
        /* the lexer's message; the size cap in this file's own words */
        if (read == SWX_EBIG)
            snprintf(err, sizeof err, "%s: file larger than 1 MiB", path);
        else
            snprintf(err, sizeof err, "%.*s", (int)sizeof err - 1, r.lx.err);
        return swd_fail_message(m, err);
    }
    closure c = { NAN, { NAN, NAN, NAN, NAN }, { 0, 0, 0, 0 }, NULL, NULL, 0, 0, 0, 0 };
    int found = 0;
    int rc = read_dict(&r, 0, 0, &c, &found);
    swx_done(&r.lx);
    if (!rc && !found)
        rc = rfail(&r, r.lx.line, "missing sub-dictionary 'depositionClosure { ... }'%s%s", NULL, NULL);
    if (!rc && (isnan(c.sub) || !c.tau || !c.vs))
        rc = rfail(&r, r.lx.line, "depositionClosure: missing key '%s'%s",
                   isnan(c.sub) ? "sublayerYPlus" : !c.tau ? "tauPlus" : "vPlusSublayer", NULL);
    if (!rc && c.ntau != c.nvs) {
        char a[80];
        snprintf(a, sizeof a, "%zu values, vPlusSublayer %zu", c.ntau, c.nvs);
        rc = rfail(&r, c.vs_line, "depositionClosure: tauPlus has %s%s", a, NULL);
    }
    /* the random walk it was calibrated with must be the one in use */
    for (int i = 0; !rc && i < 4; i++) {
        const double use = swd_get(m, crw_keys[i]);
        if (isnan(c.crw[i])) {
            rc = rfail(&r, r.lx.line, "depositionClosure: missing key '%s' (the setting it was "
                       "calibrated with)%s", crw_keys[i], NULL);
        } else if (fabs(c.crw[i] - use) > 1e-9 * fmax(fabs(use), 1.0)) {
            char a[256];
            snprintf(a, sizeof a, "%s %g, the model uses %g: recalibrate (snowdeposit calibrate "
                     "--set %s=%g) or use the same setting", crw_keys[i], c.crw[i], use,
                     crw_keys[i], use);
            rc = rfail(&r, c.crw_line[i], "depositionClosure: calibrated with %s%s", a, NULL);
        }
    }
    if (!rc) {
        rc = swd_set_closure(m, c.sub, c.tau, c.vs, c.ntau);
        if (rc) {
            snprintf(err, sizeof err, "%s: %s", path, swd_errmsg(m));
        }
    }
    free(c.tau);
    free(c.vs);
    return rc ? swd_fail_message(m, err) : SWD_OK;
}
