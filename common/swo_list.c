/* swo_list.c - the comma-list rule of every list option (swo_out.h): no empty
 * item, no value twice, a numeric list taken in ascending order. */
#include "swo_out.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Split a copy of text at its commas: *items gets the item pointers (into the
 * returned buffer), *n their count. NULL with a message for a missing value,
 * an empty item or too many items. */
static char *split(const char *opt, const char *text, int maxn, char ***items, int *n, char *err,
                   size_t errlen)
{
    *items = NULL;
    *n = 0;
    if (!text || !*text) {
        snprintf(err, errlen, "%s: missing value", opt);
        return NULL;
    }
    int count = 1;
    for (const char *s = text; *s; s++)
        count += *s == ',';
    if (maxn > 0 && count > maxn) {
        snprintf(err, errlen, "%s: '%s' has %d items; at most %d are accepted", opt, text, count,
                 maxn);
        return NULL;
    }
    const size_t len = strlen(text) + 1;
    char *buf = malloc(len);
    char **it = malloc((size_t)count * sizeof *it);
    if (!buf || !it) {
        free(buf);
        free(it);
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    memcpy(buf, text, len);
    int k = 0;
    for (char *s = buf;;) {
        char *comma = strchr(s, ',');
        if (comma)
            *comma = '\0';
        if (!*s) {
            snprintf(err, errlen, "%s: '%s' has an empty item (item %d): give the values "
                     "separated by single commas", opt, text, k + 1);
            free(buf);
            free(it);
            return NULL;
        }
        it[k++] = s;
        if (!comma)
            break;
        s = comma + 1;
    }
    *items = it;
    *n = k;
    return buf;
}

typedef struct {
    double v;
    int i;   /* item index as given */
} item;

static int by_value(const void *a, const void *b)
{
    const item *x = a, *y = b;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return x->i - y->i;
}

int swo_list_numbers(const char *opt, const char *text, double lo, double hi, int lo_open,
                     int maxn, double **out, int *n, char *note, size_t notelen,
                     char *err, size_t errlen)
{
    *out = NULL;
    *n = 0;
    if (note && notelen)
        note[0] = '\0';
    char **it;
    int k;
    char *buf = split(opt, text, maxn, &it, &k, err, errlen);
    if (!buf)
        return SWO_EREFUSED;
    item *v = malloc((size_t)k * sizeof *v);
    double *res = malloc((size_t)k * sizeof *res);
    int rc = (v && res) ? SWO_OK : (snprintf(err, errlen, "out of memory"), SWO_EFAIL);
    for (int j = 0; rc == SWO_OK && j < k; j++) {
        const char *s = it[j];
        char *end;
        errno = 0;
        /* decimal only: strtod also reads hexadecimal (0x10), which a value is not meant to be */
        const double x = strpbrk(s, "xX") ? NAN : strtod(s, &end);
        if (strpbrk(s, "xX") || end == s || *end != '\0') {
            snprintf(err, errlen, "%s: '%s' (in '%s') is not a decimal number", opt, s, text);
            rc = SWO_EREFUSED;
        } else if (!isfinite(x)) {
            snprintf(err, errlen, "%s: '%s' (in '%s') is not a finite number", opt, s, text);
            rc = SWO_EREFUSED;
        } else if (x > hi || (lo_open ? !(x > lo) : x < lo)) {
            snprintf(err, errlen, "%s: '%s' (in '%s') is out of range %s%g, %g]", opt, s, text,
                     lo_open ? "(" : "[", lo, hi);
            rc = SWO_EREFUSED;
        } else {
            v[j].v = x;
            v[j].i = j;
        }
    }
    if (rc == SWO_OK) {
        int sorted = 1;
        for (int j = 1; j < k; j++)
            sorted &= v[j].v >= v[j - 1].v;
        qsort(v, (size_t)k, sizeof *v, by_value);
        for (int j = 1; j < k && rc == SWO_OK; j++)
            if (v[j].v == v[j - 1].v) {
                const int a = v[j - 1].i < v[j].i ? v[j - 1].i : v[j].i;
                const int b = v[j - 1].i < v[j].i ? v[j].i : v[j - 1].i;
                snprintf(err, errlen, "%s: '%s' gives the value %g twice (items %d '%s' and %d "
                         "'%s'): give each value once", opt, text, v[j].v, a + 1, it[a], b + 1,
                         it[b]);
                rc = SWO_EREFUSED;
            }
        if (rc == SWO_OK && !sorted && note && notelen)
            snprintf(note, notelen, "%s: '%s' taken in ascending order", opt, text);
    }
    if (rc == SWO_OK) {
        for (int j = 0; j < k; j++)
            res[j] = v[j].v;
        *out = res;
        *n = k;
    } else {
        free(res);
    }
    free(v);
    free(it);
    free(buf);
    return rc;
}

int swo_list_words(const char *opt, const char *text, const char *const *words, int maxn,
                   int *idx, int *n, char *err, size_t errlen)
{
    *n = 0;
    char **it;
    int k;
    char *buf = split(opt, text, maxn, &it, &k, err, errlen);
    if (!buf)
        return SWO_EREFUSED;
    int rc = SWO_OK;
    for (int j = 0; j < k && rc == SWO_OK; j++) {
        int w = 0;
        while (words[w] && strcmp(words[w], it[j]))
            w++;
        if (!words[w]) {
            char list[300] = "";
            size_t used = 0;
            for (int q = 0; words[q] && used < sizeof list; q++)
                used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", q ? ", " : "",
                                         words[q]);
            snprintf(err, errlen, "%s: '%s' (in '%s') is not one of %s", opt, it[j], text, list);
            rc = SWO_EREFUSED;
            break;
        }
        for (int q = 0; q < j; q++)
            if (idx[q] == w) {
                snprintf(err, errlen, "%s: '%s' names '%s' twice (items %d and %d): give each "
                         "once", opt, text, it[j], q + 1, j + 1);
                rc = SWO_EREFUSED;
            }
        idx[j] = w;
    }
    if (rc == SWO_OK)
        *n = k;
    free(it);
    free(buf);
    return rc;
}
