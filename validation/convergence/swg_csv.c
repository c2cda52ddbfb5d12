/* swg_csv.c - the plain CSV fields of the ladder tables (see swg_csv.h). */
#include "swg_csv.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

char *swg_csv_trim(char *s)
{
    while (isspace((unsigned char)*s))
        s++;
    char *e = s + strlen(s);
    while (e > s && isspace((unsigned char)e[-1]))
        *--e = '\0';
    return s;
}

int swg_csv_split(char *s, char **f)
{
    int n = 0;
    for (char *p = s;; n++) {
        if (n >= SWG_CSV_MAX_COLS)
            return -1;
        char *c = strchr(p, ',');
        if (c)
            *c = '\0';
        f[n] = swg_csv_trim(p);
        if (!c)
            return n + 1;
        p = c + 1;
    }
}

int swg_csv_number(const char *s, double *v)
{
    char *end;
    errno = 0;
    const double x = strtod(s, &end);
    if (!*s || end == s || *end || errno == ERANGE || !isfinite(x) || strpbrk(s, "xXnN"))
        return 0;
    *v = x;
    return 1;
}

char *swg_csv_dup(const char *s)
{
    const size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}
