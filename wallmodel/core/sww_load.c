/* sww_load.c - reader of regime.coeffs (doc/regime-coeffs.md): the subset of
 * OpenFOAM dictionary syntax `//` and C comments, `key value;`, `key (v ...);`,
 * `key "text";` and sub-dictionaries `name { ... }`. Only the entries of the
 * sub-dictionary `regime` are used; they go through sww_regime_number/list/word
 * (the same path as numbers set from code), then sww_regime_commit. The tokens
 * come from swx_lex.h (the dialect SWX_STRINGS | SWX_STRICT); the keys, their
 * meaning and the messages about them are here. */
#include "sww_internal.h"
#include "swx_lex.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FILE (1L << 22)
#define MAX_TOK SWX_MAX_TOK

typedef struct {
    swx_lex lx;             /* the tokens: SWX_STRINGS | SWX_STRICT */
    sww_model *m;
    /* the line of every key set, for the consistency errors of the commit,
     * which know the keys but not the file */
    struct { char key[48]; int line; } keys[96];
    int nkeys;
} loader;

static void note_key(loader *L, const char *key, int line)
{
    if (L->nkeys < (int)(sizeof L->keys / sizeof L->keys[0])) {
        snprintf(L->keys[L->nkeys].key, sizeof L->keys[0].key, "%s", key);
        L->keys[L->nkeys++].line = line;
    }
}

/* A commit error names keys ('dMin', 'dMax'): add the lines that set them. */
static void add_key_lines(const loader *L, sww_model *m)
{
    char add[400] = "";
    size_t n = 0;
    for (int i = 0; i < L->nkeys && n + 1 < sizeof add; i++) {
        char q[52];
        snprintf(q, sizeof q, "'%s'", L->keys[i].key);
        if (!strstr(m->err, q))
            continue;
        const int w = snprintf(add + n, sizeof add - n, "%s%s line %d", n ? ", " : "",
                               L->keys[i].key, L->keys[i].line);
        if (w < 0)
            break;
        n += (size_t)w < sizeof add - n ? (size_t)w : sizeof add - n - 1;
    }
    if (n) {
        const size_t e = strlen(m->err);
        snprintf(m->err + e, sizeof m->err - e, " (%s)", add);
    }
}

static int lex_fail(loader *L, int code, int line, const char *what)
{
    return sww_fail(L->m, code, "%s:%d: %s", L->lx.path, line, what);
}

/* Advance to the next token; returns SWW_OK or an error (the lexer's message,
 * "path:line: what"). */
static int next(loader *L)
{
    return swx_next(&L->lx) ? sww_fail(L->m, SWW_EPARSE, "%s", L->lx.err) : SWW_OK;
}

static int expect_fail(loader *L, const char *key, const char *what)
{
    return sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s': expected %s, found '%s'", L->lx.path,
                    L->lx.tline, key, what, swx_desc(&L->lx));
}

/* prefix "path:line: " to the setter's message */
static int setter_fail(loader *L, int line, int rc)
{
    char msg[SWW_ERRLEN];
    snprintf(msg, sizeof msg, "%s", L->m->err);
    sww_fail(L->m, rc, "%s:%d: %s", L->lx.path, line, msg);
    return rc;
}

/* One entry after its keyword; use = 1 inside `regime` (send to the model). */
static int parse_dict(loader *L, int use, int depth, int *found_regime);

static int parse_entry(loader *L, const char *key, int keyline, int use, int depth, int *found_regime)
{
    int rc;
    if (L->lx.kind == SWX_LBRACE) {
        if (use)
            return sww_fail(L->m, SWW_EINVAL, "%s:%d: key '%s': a sub-dictionary is not a regime key "
                            "(doc/regime-coeffs.md lists them)", L->lx.path, keyline, key);
        if (depth > 16)
            return lex_fail(L, SWW_EPARSE, keyline, "sub-dictionaries nested too deep");
        const int is_regime = depth == 0 && !strcmp(key, "regime");
        if (is_regime) {
            if (*found_regime)
                return sww_fail(L->m, SWW_EPARSE, "%s:%d: sub-dictionary 'regime' appears twice",
                                L->lx.path, keyline);
            *found_regime = 1;
        }
        if ((rc = next(L)))
            return rc;
        if ((rc = parse_dict(L, is_regime, depth + 1, found_regime)))
            return rc;
        if (L->lx.kind != SWX_RBRACE)
            return sww_fail(L->m, SWW_EPARSE, "%s:%d: sub-dictionary '%s' (line %d) is not closed "
                            "by '}'", L->lx.path, L->lx.tline, key, keyline);
        return next(L);
    }
    if (L->lx.kind == SWX_LPAR) {
        /* the rebound tables (K x M x N values) may be longer than the others */
        const size_t limit = use && (!strcmp(key, "reboundEn") || !strcmp(key, "reboundEt"))
                           ? SWW_MAX_REBOUND : SWW_MAX_TABLE;
        double *vals = NULL;
        size_t n = 0, cap = 0;
        int line = L->lx.tline;
        rc = SWW_OK;
        for (;;) {
            if ((rc = next(L)))
                break;
            if (L->lx.kind == SWX_RPAR)
                break;
            if (L->lx.kind != SWX_WORD) {
                rc = expect_fail(L, key, "a number or ')'");
                break;
            }
            if (n >= limit) {
                rc = sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s': more than %zu values", L->lx.path,
                              L->lx.tline, key, limit);
                break;
            }
            if (n == cap) {
                const size_t nc = cap ? 2 * cap : 64;
                double *p = realloc(vals, (nc < limit ? nc : limit) * sizeof *p);
                if (!p) {
                    rc = sww_fail(L->m, SWW_ENOMEM, "%s:%d: key '%s': out of memory", L->lx.path,
                                  L->lx.tline, key);
                    break;
                }
                vals = p;
                cap = nc < limit ? nc : limit;
            }
            if (!swx_number(L->lx.text, &vals[n])) {
                rc = sww_fail(L->m, SWW_EINVAL, "%s:%d: key '%s': value '%s' (entry %zu) is "
                              "not a number", L->lx.path, L->lx.tline, key, L->lx.text, n);
                break;
            }
            n++;
        }
        if (rc == SWW_OK && (rc = next(L)) == SWW_OK && L->lx.kind != SWX_SEMI)
            rc = expect_fail(L, key, "';' after the list");
        if (rc == SWW_OK && use && (rc = sww_regime_list(L->m, key, vals, n)))
            rc = setter_fail(L, line, rc);
        if (rc == SWW_OK && use)
            note_key(L, key, line);
        free(vals);
        if (rc)
            return rc;
        return next(L);
    }
    if (L->lx.kind == SWX_WORD || L->lx.kind == SWX_STRING) {
        char val[MAX_TOK];
        const int is_string = L->lx.kind == SWX_STRING, line = L->lx.tline;
        memcpy(val, L->lx.text, sizeof val);
        if ((rc = next(L)))
            return rc;
        if (L->lx.kind != SWX_SEMI)
            return expect_fail(L, key, "';'");
        if (use) {
            double v;
            if (!is_string && swx_number(val, &v))
                rc = sww_regime_number(L->m, key, v);
            else
                rc = sww_regime_word(L->m, key, val);
            if (rc)
                return setter_fail(L, line, rc);
            note_key(L, key, line);
        }
        return next(L);
    }
    return expect_fail(L, key, "a value, '(' or '{'");
}

static int parse_dict(loader *L, int use, int depth, int *found_regime)
{
    /* keys seen in this dictionary (duplicates are an error inside regime) */
    char seen[64][MAX_TOK];
    int nseen = 0, rc;
    while (L->lx.kind == SWX_WORD) {
        char key[MAX_TOK];
        const int line = L->lx.tline;
        memcpy(key, L->lx.text, sizeof key);
        if (key[0] == '#' || key[0] == '$')
            return sww_fail(L->m, SWW_EPARSE, "%s:%d: '%s': directives and $variables are not "
                            "part of the regime.coeffs syntax", L->lx.path, line, key);
        if (use) {
            for (int i = 0; i < nseen; i++)
                if (!strcmp(seen[i], key))
                    return sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s' appears twice", L->lx.path,
                                    line, key);
            if (nseen < 64)
                memcpy(seen[nseen++], key, sizeof key);
        }
        if ((rc = next(L)))
            return rc;
        if ((rc = parse_entry(L, key, line, use, depth, found_regime)))
            return rc;
    }
    if (L->lx.kind == SWX_STRING)
        return sww_fail(L->m, SWW_EPARSE, "%s:%d: expected a keyword, found the string \"%s\"",
                        L->lx.path, L->lx.tline, L->lx.text);
    return SWW_OK;
}

static int regime_load(sww_model *m, const char *path);

/* A load is all or nothing: the file is read into a fresh model that carries
 * m's options (gates, rebound); only when it loads and commits does it take
 * m's place. A failed reload leaves m as it was (a loaded model stays ready)
 * with the message in sww_errmsg(m). */
int sww_regime_load(sww_model *m, const char *path)
{
    sww_model *t = sww_alloc();
    if (!t)
        return sww_fail(m, SWW_ENOMEM, "%s: out of memory", path ? path : "(null)");
    t->vt_on = m->vt_on;
    t->vt_max = m->vt_max;
    t->vt_dref = m->vt_dref;
    t->vt_exp = m->vt_exp;
    t->shear_on = m->shear_on;
    t->tau_c = m->tau_c;
    t->roughness = m->roughness;
    t->e_t = m->e_t;
    t->rb_model = m->rb_model;
    const int rc = path ? regime_load(t, path) : sww_fail(t, SWW_EIO, "no file name");
    if (rc != SWW_OK) {
        snprintf(m->err, sizeof m->err, "%s", t->err);
        sww_free(t);
        return rc;
    }
    const sww_model old = *m;
    *m = *t;
    *t = old;      /* t now owns the old regime's tables */
    sww_free(t);
    m->err[0] = '\0';
    return SWW_OK;
}

static int regime_load(sww_model *m, const char *path)
{
    loader L = { .m = m };
    int rc = swx_read(&L.lx, path, MAX_FILE, SWX_STRINGS | SWX_STRICT);
    if (rc)
        return sww_fail(m, rc == SWX_ENOMEM ? SWW_ENOMEM : SWW_EIO, "%s", L.lx.err);
    sww_regime_clear(m);
    int found = 0;
    rc = next(&L);
    if (!rc)
        rc = parse_dict(&L, 0, 0, &found);
    if (!rc && L.lx.kind != SWX_EOF)
        rc = sww_fail(m, SWW_EPARSE, "%s:%d: expected a keyword, found %s", path, L.lx.tline,
                      swx_desc(&L.lx));
    swx_done(&L.lx);
    if (rc) {
        sww_regime_clear(m);
        return rc;
    }
    if (!found) {
        sww_regime_clear(m);
        return sww_fail(m, SWW_EMISSING, "%s: missing sub-dictionary 'regime { ... }'", path);
    }
    rc = sww_regime_commit(m, path);
    if (rc) {
        add_key_lines(&L, m);
        m->ready = 0;
    }
    return rc;
}
