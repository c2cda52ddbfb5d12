/* swd_load.c - reader of the sublayer closure's file (deposition.coeffs, written
 * by `snowdeposit calibrate`) for hosts without a dictionary reader of their own
 * (Code_Saturne, a Fluent UDF); see swd.h, swd_load_closure.
 *
 * The file is the subset of OpenFOAM dictionary syntax that the calibration
 * writes: `//` and C comments, `key value;`, `key ( v v ... );` and one
 * sub-dictionary `depositionClosure { ... }`, whose numbers are read; every other
 * entry is skipped. */
#include "swd.h"
#include "swd_internal.h"

#include <sys/stat.h>
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SWD_MAX_FILE (1L << 20)
#define SWD_MAX_LIST 4096

typedef struct {
    const char *path, *p, *end;
    int line;
    char *err;
    size_t errlen;
} rd;

static int rfail(rd *r, int line, const char *fmt, const char *a, const char *b)
{
    char msg[320];
    snprintf(msg, sizeof msg, fmt, a ? a : "", b ? b : "");
    snprintf(r->err, r->errlen, "%s:%d: %s", r->path, line, msg);
    return SWD_EINVAL;
}

/* skip blanks and comments; 0 at the end of the text */
static int skip(rd *r)
{
    for (;;) {
        while (r->p < r->end && isspace((unsigned char)*r->p)) {
            if (*r->p == '\n')
                r->line++;
            r->p++;
        }
        if (r->p + 1 < r->end && r->p[0] == '/' && r->p[1] == '/') {
            while (r->p < r->end && *r->p != '\n')
                r->p++;
            continue;
        }
        if (r->p + 1 < r->end && r->p[0] == '/' && r->p[1] == '*') {
            r->p += 2;
            while (r->p + 1 < r->end && !(r->p[0] == '*' && r->p[1] == '/')) {
                if (*r->p == '\n')
                    r->line++;
                r->p++;
            }
            r->p = r->p + 1 < r->end ? r->p + 2 : r->end;
            continue;
        }
        return r->p < r->end;
    }
}

/* a word: up to a blank or one of ( ) { } ; - its length as read (a word
 * longer than n - 1 is cut in w and reported by its full length) */
static size_t word(rd *r, char *w, size_t n)
{
    size_t k = 0, len = 0;
    while (r->p < r->end && !isspace((unsigned char)*r->p) && !strchr("(){};", *r->p)) {
        if (k + 1 < n)
            w[k++] = *r->p;
        r->p++;
        len++;
    }
    w[k] = '\0';
    return len;
}

/* a strict decimal number, finite */
static int number(const char *w, double *v)
{
    char *e;
    if (!*w || strpbrk(w, "xX"))
        return 0;
    errno = 0;
    *v = strtod(w, &e);
    return e != w && *e == '\0' && isfinite(*v);
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

/* a list ( v v ... ) after its key; *out malloc'ed */
static int read_list(rd *r, const char *key, double **out, size_t *n)
{
    double *v = malloc(SWD_MAX_LIST * sizeof *v);
    if (!v)
        return rfail(r, r->line, "key '%s': out of memory%s", key, NULL);
    size_t k = 0;
    r->p++; /* ( */
    for (;;) {
        if (!skip(r)) {
            free(v);
            return rfail(r, r->line, "key '%s': the list has no closing ')'%s", key, NULL);
        }
        if (*r->p == ')') {
            r->p++;
            break;
        }
        char w[64];
        const size_t len = word(r, w, sizeof w);
        if (!len) {
            free(v);
            return rfail(r, r->line, "key '%s': '%s' inside the list", key,
                         (char[]){ *r->p, '\0' });
        }
        if (len >= sizeof w) {
            free(v);
            return rfail(r, r->line, "key '%s': a value longer than 63 characters ('%s...')", key, w);
        }
        if (k == SWD_MAX_LIST) {
            free(v);
            return rfail(r, r->line, "key '%s': more than 4096 values%s", key, NULL);
        }
        if (!number(w, &v[k])) {
            free(v);
            return rfail(r, r->line, "key '%s': '%s' is not a finite number", key, w);
        }
        k++;
    }
    *out = v;
    *n = k;
    return SWD_OK;
}

/* the entries of a dictionary up to its '}' (inside: 1 in depositionClosure) */
static int read_dict(rd *r, int inside, int depth, closure *c, int *found)
{
    for (;;) {
        if (!skip(r))
            return depth ? rfail(r, r->line, "a sub-dictionary has no closing '}'%s%s", NULL, NULL)
                         : SWD_OK;
        if (*r->p == '}') {
            if (!depth)
                return rfail(r, r->line, "a '}' without its '{'%s%s", NULL, NULL);
            r->p++;
            return SWD_OK;
        }
        char key[64];
        const int line = r->line;
        const size_t klen = word(r, key, sizeof key);
        if (klen >= sizeof key)
            return rfail(r, line, "a keyword longer than 63 characters ('%s...')", key, NULL);
        if (!klen)
            return rfail(r, line, "expected a keyword, found '%s'%s",
                         (char[]){ *r->p, '\0' }, NULL);
        if (!skip(r))
            return rfail(r, line, "key '%s': no value%s", key, NULL);
        if (*r->p == '{') {
            if (depth > 8)
                return rfail(r, line, "sub-dictionaries nested too deep%s%s", NULL, NULL);
            const int is_cl = depth == 0 && !strcmp(key, "depositionClosure");
            if (is_cl && *found)
                return rfail(r, line, "sub-dictionary 'depositionClosure' appears twice%s%s", NULL,
                             NULL);
            *found |= is_cl;
            r->p++;
            const int rc = read_dict(r, is_cl, depth + 1, c, found);
            if (rc)
                return rc;
            continue;
        }
        if (*r->p == '(') {
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
            char w[64];
            const size_t len = word(r, w, sizeof w);
            if (!len)
                return rfail(r, line, "key '%s': no value%s", key, NULL);
            if (len >= sizeof w && inside)
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
        }
        if (!skip(r) || *r->p != ';')
            return rfail(r, line, "key '%s': no ';' after its value%s", key, NULL);
        r->p++;
    }
}

int swd_load_closure(swd_model *m, const char *path)
{
    char err[600] = "";
    if (!path)
        return swd_fail_message(m, "near-wall closure: no file name");
    /* a regular file only: opening a FIFO for reading would wait for a writer */
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(err, sizeof err, "%s: cannot open: %s", path, strerror(errno));
        return swd_fail_message(m, err);
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(err, sizeof err, "%s: not a regular file", path);
        return swd_fail_message(m, err);
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, sizeof err, "%s: cannot open: %s", path, strerror(errno));
        return swd_fail_message(m, err);
    }
    char *buf = malloc(SWD_MAX_FILE + 1);
    const size_t n = buf ? fread(buf, 1, SWD_MAX_FILE + 1, f) : 0;
    const int bad = !buf || ferror(f);
    fclose(f);
    if (bad || n > (size_t)SWD_MAX_FILE) {
        free(buf);
        snprintf(err, sizeof err, "%s: %s", path,
                 !buf ? "out of memory" : bad ? "read error" : "file larger than 1 MiB");
        return swd_fail_message(m, err);
    }
    rd r = { path, buf, buf + n, 1, err, sizeof err };
    closure c = { NAN, { NAN, NAN, NAN, NAN }, { 0, 0, 0, 0 }, NULL, NULL, 0, 0, 0, 0 };
    int found = 0;
    int rc = read_dict(&r, 0, 0, &c, &found);
    free(buf);
    if (!rc && !found)
        rc = rfail(&r, r.line, "missing sub-dictionary 'depositionClosure { ... }'%s%s", NULL, NULL);
    if (!rc && (isnan(c.sub) || !c.tau || !c.vs))
        rc = rfail(&r, r.line, "depositionClosure: missing key '%s'%s",
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
            rc = rfail(&r, r.line, "depositionClosure: missing key '%s' (the setting it was "
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
