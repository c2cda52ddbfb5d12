/* sww_load.c - reader of regime.coeffs (doc/regime-coeffs.md): the subset of
 * OpenFOAM dictionary syntax `//` and C comments, `key value;`, `key (v ...);`,
 * `key "text";` and sub-dictionaries `name { ... }`. Only the entries of the
 * sub-dictionary `regime` are used; they go through sww_regime_number/list/word
 * (the same path as numbers set from code), then sww_regime_commit. */
#include "sww_internal.h"

#include <sys/stat.h>

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FILE (1L << 22)
#define MAX_TOK 256

typedef enum { T_EOF, T_WORD, T_STRING, T_LPAR, T_RPAR, T_LBRACE, T_RBRACE, T_SEMI } tok_kind;

typedef struct {
    const char *path;
    const char *s, *p, *end;
    int line;
    /* current token */
    tok_kind kind;
    int tline;
    char text[MAX_TOK];
    sww_model *m;
    /* the line of every key set, for the consistency errors of the commit,
     * which know the keys but not the file */
    struct { char key[48]; int line; } keys[96];
    int nkeys;
} lexer;

static void note_key(lexer *L, const char *key, int line)
{
    if (L->nkeys < (int)(sizeof L->keys / sizeof L->keys[0])) {
        snprintf(L->keys[L->nkeys].key, sizeof L->keys[0].key, "%s", key);
        L->keys[L->nkeys++].line = line;
    }
}

/* A commit error names keys ('dMin', 'dMax'): add the lines that set them. */
static void add_key_lines(const lexer *L, sww_model *m)
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

static int lex_fail(lexer *L, int code, int line, const char *what)
{
    return sww_fail(L->m, code, "%s:%d: %s", L->path, line, what);
}

/* Advance to the next token; returns SWW_OK or an error. */
static int next(lexer *L)
{
    for (;;) {
        while (L->p < L->end && isspace((unsigned char)*L->p)) {
            if (*L->p == '\n')
                L->line++;
            L->p++;
        }
        if (L->p + 1 < L->end && L->p[0] == '/' && L->p[1] == '/') {
            while (L->p < L->end && *L->p != '\n')
                L->p++;
            continue;
        }
        if (L->p + 1 < L->end && L->p[0] == '/' && L->p[1] == '*') {
            const int start = L->line;
            L->p += 2;
            while (L->p + 1 < L->end && !(L->p[0] == '*' && L->p[1] == '/')) {
                if (*L->p == '\n')
                    L->line++;
                L->p++;
            }
            if (L->p + 1 >= L->end)
                return lex_fail(L, SWW_EPARSE, start, "unterminated /* comment");
            L->p += 2;
            continue;
        }
        break;
    }
    L->tline = L->line;
    L->text[0] = '\0';
    if (L->p >= L->end) {
        L->kind = T_EOF;
        return SWW_OK;
    }
    const char c = *L->p;
    switch (c) {
    case '(': L->kind = T_LPAR; L->p++; return SWW_OK;
    case ')': L->kind = T_RPAR; L->p++; return SWW_OK;
    case '{': L->kind = T_LBRACE; L->p++; return SWW_OK;
    case '}': L->kind = T_RBRACE; L->p++; return SWW_OK;
    case ';': L->kind = T_SEMI; L->p++; return SWW_OK;
    default: break;
    }
    size_t n = 0;
    if (c == '"') {
        L->p++;
        while (L->p < L->end && *L->p != '"' && *L->p != '\n') {
            if (n + 1 >= MAX_TOK)
                return lex_fail(L, SWW_EPARSE, L->tline, "string longer than 255 characters");
            L->text[n++] = *L->p++;
        }
        if (L->p >= L->end || *L->p != '"')
            return lex_fail(L, SWW_EPARSE, L->tline, "unterminated string (missing \")");
        L->p++;
        L->text[n] = '\0';
        L->kind = T_STRING;
        return SWW_OK;
    }
    while (L->p < L->end && !isspace((unsigned char)*L->p) && !strchr("(){};\"", *L->p)
           && !(L->p + 1 < L->end && L->p[0] == '/' && (L->p[1] == '/' || L->p[1] == '*'))) {
        if (!isprint((unsigned char)*L->p)) {
            char msg[64];
            snprintf(msg, sizeof msg, "unexpected byte 0x%02x", (unsigned char)*L->p);
            return lex_fail(L, SWW_EPARSE, L->line, msg);
        }
        if (n + 1 >= MAX_TOK)
            return lex_fail(L, SWW_EPARSE, L->tline, "word longer than 255 characters");
        L->text[n++] = *L->p++;
    }
    L->text[n] = '\0';
    L->kind = T_WORD;
    return SWW_OK;
}

static const char *tok_desc(const lexer *L)
{
    switch (L->kind) {
    case T_EOF: return "end of file";
    case T_LPAR: return "'('";
    case T_RPAR: return "')'";
    case T_LBRACE: return "'{'";
    case T_RBRACE: return "'}'";
    case T_SEMI: return "';'";
    default: return L->text;
    }
}

static int expect_fail(lexer *L, const char *key, const char *what)
{
    return sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s': expected %s, found '%s'", L->path,
                    L->tline, key, what, tok_desc(L));
}

/* strict number: the whole word must convert, finite; decimal only (strtod also
 * takes hexadecimal "0x6", which OpenFOAM's reader does not: one file, one meaning) */
static int to_number(const char *w, double *v)
{
    char *e;
    if (strpbrk(w, "xX"))
        return 0;
    errno = 0;
    *v = strtod(w, &e);
    return e != w && *e == '\0';
}

/* prefix "path:line: " to the setter's message */
static int setter_fail(lexer *L, int line, int rc)
{
    char msg[SWW_ERRLEN];
    snprintf(msg, sizeof msg, "%s", L->m->err);
    sww_fail(L->m, rc, "%s:%d: %s", L->path, line, msg);
    return rc;
}

/* One entry after its keyword; use = 1 inside `regime` (send to the model). */
static int parse_dict(lexer *L, int use, int depth, int *found_regime);

static int parse_entry(lexer *L, const char *key, int keyline, int use, int depth, int *found_regime)
{
    int rc;
    if (L->kind == T_LBRACE) {
        if (use)
            return sww_fail(L->m, SWW_EINVAL, "%s:%d: key '%s': a sub-dictionary is not a regime key "
                            "(doc/regime-coeffs.md lists them)", L->path, keyline, key);
        if (depth > 16)
            return lex_fail(L, SWW_EPARSE, keyline, "sub-dictionaries nested too deep");
        const int is_regime = depth == 0 && !strcmp(key, "regime");
        if (is_regime) {
            if (*found_regime)
                return sww_fail(L->m, SWW_EPARSE, "%s:%d: sub-dictionary 'regime' appears twice",
                                L->path, keyline);
            *found_regime = 1;
        }
        if ((rc = next(L)))
            return rc;
        if ((rc = parse_dict(L, is_regime, depth + 1, found_regime)))
            return rc;
        if (L->kind != T_RBRACE)
            return sww_fail(L->m, SWW_EPARSE, "%s:%d: sub-dictionary '%s' (line %d) is not closed "
                            "by '}'", L->path, L->tline, key, keyline);
        return next(L);
    }
    if (L->kind == T_LPAR) {
        /* the rebound tables (K x M x N values) may be longer than the others */
        const size_t limit = use && (!strcmp(key, "reboundEn") || !strcmp(key, "reboundEt"))
                           ? SWW_MAX_REBOUND : SWW_MAX_TABLE;
        double *vals = NULL;
        size_t n = 0, cap = 0;
        int line = L->tline;
        rc = SWW_OK;
        for (;;) {
            if ((rc = next(L)))
                break;
            if (L->kind == T_RPAR)
                break;
            if (L->kind != T_WORD) {
                rc = expect_fail(L, key, "a number or ')'");
                break;
            }
            if (n >= limit) {
                rc = sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s': more than %zu values", L->path,
                              L->tline, key, limit);
                break;
            }
            if (n == cap) {
                const size_t nc = cap ? 2 * cap : 64;
                double *p = realloc(vals, (nc < limit ? nc : limit) * sizeof *p);
                if (!p) {
                    rc = sww_fail(L->m, SWW_ENOMEM, "%s:%d: key '%s': out of memory", L->path,
                                  L->tline, key);
                    break;
                }
                vals = p;
                cap = nc < limit ? nc : limit;
            }
            if (!to_number(L->text, &vals[n])) {
                rc = sww_fail(L->m, SWW_EINVAL, "%s:%d: key '%s': value '%s' (entry %zu) is "
                              "not a number", L->path, L->tline, key, L->text, n);
                break;
            }
            n++;
        }
        if (rc == SWW_OK && (rc = next(L)) == SWW_OK && L->kind != T_SEMI)
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
    if (L->kind == T_WORD || L->kind == T_STRING) {
        char val[MAX_TOK];
        const int is_string = L->kind == T_STRING, line = L->tline;
        memcpy(val, L->text, sizeof val);
        if ((rc = next(L)))
            return rc;
        if (L->kind != T_SEMI)
            return expect_fail(L, key, "';'");
        if (use) {
            double v;
            if (!is_string && to_number(val, &v))
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

static int parse_dict(lexer *L, int use, int depth, int *found_regime)
{
    /* keys seen in this dictionary (duplicates are an error inside regime) */
    char seen[64][MAX_TOK];
    int nseen = 0, rc;
    while (L->kind == T_WORD) {
        char key[MAX_TOK];
        const int line = L->tline;
        memcpy(key, L->text, sizeof key);
        if (key[0] == '#' || key[0] == '$')
            return sww_fail(L->m, SWW_EPARSE, "%s:%d: '%s': directives and $variables are not "
                            "part of the regime.coeffs syntax", L->path, line, key);
        if (use) {
            for (int i = 0; i < nseen; i++)
                if (!strcmp(seen[i], key))
                    return sww_fail(L->m, SWW_EPARSE, "%s:%d: key '%s' appears twice", L->path,
                                    line, key);
            if (nseen < 64)
                memcpy(seen[nseen++], key, sizeof key);
        }
        if ((rc = next(L)))
            return rc;
        if ((rc = parse_entry(L, key, line, use, depth, found_regime)))
            return rc;
    }
    if (L->kind == T_STRING)
        return sww_fail(L->m, SWW_EPARSE, "%s:%d: expected a keyword, found the string \"%s\"",
                        L->path, L->tline, L->text);
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
    /* a regular file only: opening a FIFO for reading would wait for a writer */
    struct stat st;
    if (stat(path, &st) != 0)
        return sww_fail(m, SWW_EIO, "%s: cannot open: %s", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return sww_fail(m, SWW_EIO, "%s: not a regular file", path);
    FILE *f = fopen(path, "rb");
    if (!f)
        return sww_fail(m, SWW_EIO, "%s: cannot open: %s", path, strerror(errno));
    /* read in a buffer that grows with the file (a few kB for a map), up to
     * MAX_FILE + 1 bytes to tell a too large file */
    size_t cap = 1 << 14, n = 0;
    char *buf = malloc(cap);
    int err = 0, more = 0;
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (ferror(f)) {
            err = 1;
            break;
        }
        if (feof(f))
            break;
        if (n > (size_t)MAX_FILE) {
            more = 1;
            break;
        }
        char *nb = realloc(buf, 2 * cap);
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap *= 2;
    }
    fclose(f);
    if (n > (size_t)MAX_FILE)
        more = 1;
    if (!buf)
        return sww_fail(m, SWW_ENOMEM, "%s: out of memory", path);
    if (err) {
        free(buf);
        return sww_fail(m, SWW_EIO, "%s: read error", path);
    }
    if (more) {
        free(buf);
        return sww_fail(m, SWW_EIO, "%s: file larger than %ld bytes", path, MAX_FILE);
    }
    sww_regime_clear(m);
    lexer L = { .path = path, .s = buf, .p = buf, .end = buf + n, .line = 1, .m = m };
    int found = 0, rc = next(&L);
    if (!rc)
        rc = parse_dict(&L, 0, 0, &found);
    if (!rc && L.kind != T_EOF)
        rc = sww_fail(m, SWW_EPARSE, "%s:%d: expected a keyword, found %s", path, L.tline, tok_desc(&L));
    free(buf);
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
