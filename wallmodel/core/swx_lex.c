/* swx_lex.c - the lexer of the C core's dictionary files (swx_lex.h): the
 * file read whole, then cut into tokens for sww_load.c (regime.coeffs) and
 * swd_load.c (deposition.coeffs). */
#include "swx_lex.h"

#include <sys/stat.h>

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(swx_lex *lx, int code, int line, const char *what)
{
    snprintf(lx->err, sizeof lx->err, "%s:%d: %s", lx->path, line, what);
    return code;
}

static int file_fail(swx_lex *lx, int code, const char *what, const char *why)
{
    snprintf(lx->err, sizeof lx->err, "%s: %s%s", lx->path, what, why);
    return code;
}

int swx_read(swx_lex *lx, const char *path, long max, unsigned flags)
{
    memset(lx, 0, sizeof *lx);
    lx->path = path;
    lx->flags = flags;
    lx->line = 1;
    /* a regular file only: opening a FIFO for reading would wait for a writer */
    struct stat st;
    if (stat(path, &st) != 0)
        return file_fail(lx, SWX_EIO, "cannot open: ", strerror(errno));
    if (!S_ISREG(st.st_mode))
        return file_fail(lx, SWX_EIO, "not a regular file", "");
    FILE *f = fopen(path, "rb");
    if (!f)
        return file_fail(lx, SWX_EIO, "cannot open: ", strerror(errno));
    /* read in a buffer that grows with the file (a few kB for a map), up to
     * max + 1 bytes to tell a too large file */
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
        if (n > (size_t)max) {
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
    if (n > (size_t)max)
        more = 1;
    if (!buf)
        return file_fail(lx, SWX_ENOMEM, "out of memory", "");
    if (err || more) {
        free(buf);
        if (err)
            return file_fail(lx, SWX_EIO, "read error", "");
        snprintf(lx->err, sizeof lx->err, "%s: file larger than %ld bytes", path, max);
        return SWX_EBIG;
    }
    lx->buf = buf;
    lx->p = buf;
    lx->end = buf + n;
    return SWX_OK;
}

void swx_done(swx_lex *lx)
{
    free(lx->buf);
    lx->buf = NULL;
    lx->p = lx->end = NULL;
}

/* Skip blanks and comments. A C comment without its end is an error with
 * SWX_STRICT, else it runs to the end of the file (its last byte uncounted). */
static int skip(swx_lex *lx)
{
    for (;;) {
        while (lx->p < lx->end && isspace((unsigned char)*lx->p)) {
            if (*lx->p == '\n')
                lx->line++;
            lx->p++;
        }
        if (lx->p + 1 < lx->end && lx->p[0] == '/' && lx->p[1] == '/') {
            while (lx->p < lx->end && *lx->p != '\n')
                lx->p++;
            continue;
        }
        if (lx->p + 1 < lx->end && lx->p[0] == '/' && lx->p[1] == '*') {
            const int start = lx->line;
            lx->p += 2;
            while (lx->p + 1 < lx->end && !(lx->p[0] == '*' && lx->p[1] == '/')) {
                if (*lx->p == '\n')
                    lx->line++;
                lx->p++;
            }
            if (lx->p + 1 >= lx->end) {
                if (lx->flags & SWX_STRICT)
                    return fail(lx, SWX_EPARSE, start, "unterminated /* comment");
                lx->p = lx->end;
            } else {
                lx->p += 2;
            }
            continue;
        }
        return SWX_OK;
    }
}

/* a string after its opening '"' (SWX_STRINGS) */
static int string(swx_lex *lx)
{
    size_t n = 0;
    lx->p++;
    while (lx->p < lx->end && *lx->p != '"' && *lx->p != '\n') {
        if (n + 1 >= SWX_MAX_TOK)
            return fail(lx, SWX_EPARSE, lx->tline, "string longer than 255 characters");
        lx->text[n++] = *lx->p++;
    }
    if (lx->p >= lx->end || *lx->p != '"')
        return fail(lx, SWX_EPARSE, lx->tline, "unterminated string (missing \")");
    lx->p++;
    lx->text[n] = '\0';
    lx->len = n;
    lx->kind = SWX_STRING;
    return SWX_OK;
}

/* does the byte at p end a word? */
static int word_end(const swx_lex *lx)
{
    const char *p = lx->p;
    if (isspace((unsigned char)*p) || strchr(lx->flags & SWX_STRINGS ? "(){};\"" : "(){};", *p))
        return 1; /* strchr finds a NUL byte too: it ends the word */
    return (lx->flags & SWX_STRICT) && p + 1 < lx->end && p[0] == '/' && (p[1] == '/' || p[1] == '*');
}

static int word(swx_lex *lx)
{
    const int strict = (lx->flags & SWX_STRICT) != 0;
    size_t n = 0, len = 0;
    while (lx->p < lx->end && !word_end(lx)) {
        if (strict && !isprint((unsigned char)*lx->p)) {
            char msg[64];
            snprintf(msg, sizeof msg, "unexpected byte 0x%02x", (unsigned char)*lx->p);
            return fail(lx, SWX_EPARSE, lx->line, msg);
        }
        if (n + 1 >= SWX_MAX_TOK) {
            if (strict)
                return fail(lx, SWX_EPARSE, lx->tline, "word longer than 255 characters");
        } else {
            lx->text[n++] = *lx->p;
        }
        lx->p++;
        len++;
    }
    lx->text[n] = '\0';
    lx->len = len;
    lx->kind = SWX_WORD;
    return SWX_OK;
}

int swx_next(swx_lex *lx)
{
    const int rc = skip(lx);
    if (rc)
        return rc;
    lx->tline = lx->line;
    lx->text[0] = '\0';
    lx->len = 0;
    if (lx->p >= lx->end) {
        lx->kind = SWX_EOF;
        return SWX_OK;
    }
    static const char punct[] = "(){};";
    static const swx_kind kinds[] = { SWX_LPAR, SWX_RPAR, SWX_LBRACE, SWX_RBRACE, SWX_SEMI };
    const char *q = *lx->p ? strchr(punct, *lx->p) : NULL;
    if (q) {
        lx->kind = kinds[q - punct];
        lx->text[0] = *lx->p++;
        lx->text[1] = '\0';
        lx->len = 1;
        return SWX_OK;
    }
    if (*lx->p == '"' && (lx->flags & SWX_STRINGS))
        return string(lx);
    return word(lx);
}

const char *swx_desc(const swx_lex *lx)
{
    switch (lx->kind) {
    case SWX_EOF: return "end of file";
    case SWX_LPAR: return "'('";
    case SWX_RPAR: return "')'";
    case SWX_LBRACE: return "'{'";
    case SWX_RBRACE: return "'}'";
    case SWX_SEMI: return "';'";
    default: return lx->text;
    }
}

int swx_number(const char *w, double *v)
{
    char *e;
    if (strpbrk(w, "xX"))
        return 0;
    errno = 0;
    *v = strtod(w, &e);
    return e != w && *e == '\0';
}
