/* swe_run_text.h - the text helpers of the swe_run*.c files (internal): fields
 * and numbers read as awk reads them, so that the files Allrun writes keep
 * their format. */
#ifndef SWE_RUN_TEXT_H
#define SWE_RUN_TEXT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* a text's leading number (0 when it has none), as awk reads a field */
static inline double num(const char *s)
{
    return s ? strtod(s, NULL) : 0;
}

/* the i-th (1-based) blank-separated field of line into out ("" when absent) */
static inline const char *field(const char *line, int i, char *out, size_t n)
{
    const char *p = line;
    out[0] = 0;
    for (int k = 1;; k++) {
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')
            p++;
        if (!*p)
            return out;
        const char *e = p;
        while (*e && *e != ' ' && *e != '\t' && *e != '\n' && *e != '\r')
            e++;
        if (k == i) {
            snprintf(out, n, "%.*s", (int)(e - p), p);
            return out;
        }
        p = e;
    }
}

static inline void chomp(char *s)
{
    size_t l = strlen(s);
    while (l && (s[l - 1] == '\n' || s[l - 1] == '\r'))
        s[--l] = 0;
}

#endif
