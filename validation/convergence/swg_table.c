/* swg_table.c - the resolution-ladder table of snowgci (see swg_table.h). */
#include "swg_table.h"
#include "swo_err.h"
#include "swg_csv.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define LINE_MAX_LEN 4096
#define MAX_ROWS 100000
#define MAX_COLS SWG_CSV_MAX_COLS

#define fail(err, errlen, ...) swo_fail(1, err, errlen, __VA_ARGS__)

void swg_table_free(swg_table *t)
{
    for (size_t i = 0; i < t->n; i++) {
        for (size_t j = 0; j < t->q[i].n; j++)
            free(t->q[i].rows[j].label);
        free(t->q[i].rows);
        free(t->q[i].name);
    }
    free(t->q);
    memset(t, 0, sizeof *t);
}

#define FAIL(...)                                                                                  \
    do {                                                                                           \
        rc = fail(err, errlen, __VA_ARGS__);                                                       \
        goto out;                                                                                  \
    } while (0)

int swg_table_read(FILE *f, const char *fname, swg_table *t, char *err, size_t errlen)
{
    memset(t, 0, sizeof *t);
    char *buf = NULL;
    size_t bufcap = 0;
    ssize_t got;
    char *fld[MAX_COLS];
    enum { C_Q, C_L, C_H, C_N, C_V, C_SE, NC };
    static const char *names[NC] = { "quantity", "level", "h", "cells", "value", "se" };
    int col[NC], ncol = 0, line = 0, header = 0;
    size_t rows = 0;
    for (int k = 0; k < NC; k++)
        col[k] = -1;
    int rc = 0;
    while ((got = getline(&buf, &bufcap, f)) >= 0) {
        line++;
        if ((size_t)got != strlen(buf)) {
            FAIL("%s:%d: the line holds a NUL byte", fname, line);
        }
        if (got > LINE_MAX_LEN) {
            FAIL("%s:%d: the line is longer than %d characters", fname, line, LINE_MAX_LEN);
        }
        buf[strcspn(buf, "\r\n")] = '\0';
        char *s = swg_csv_trim(buf);
        if (!*s || *s == '#')
            continue;
        const int n = swg_csv_split(s, fld);
        if (n < 0) {
            FAIL("%s:%d: more than %d fields", fname, line, MAX_COLS);
        }
        if (!header) {
            header = 1;
            ncol = n;
            for (int i = 0; i < n; i++)
                for (int k = 0; k < NC; k++)
                    if (!strcasecmp(fld[i], names[k])) {
                        if (col[k] >= 0)
                            FAIL("%s:%d: the header names column '%s' twice",
                                        fname, line, names[k]);
                        col[k] = i;
                    }
            if (col[C_H] >= 0 && col[C_N] >= 0)
                FAIL("%s:%d: the header has both 'h' and 'cells' (give one)",
                            fname, line);
            for (int k = 0; k < NC; k++) {
                if (k == C_H || k == C_N)
                    continue;
                if (col[k] < 0)
                    FAIL("%s:%d: the header has no column '%s' (need "
                                "quantity, level, h or cells, value, se)", fname, line, names[k]);
            }
            if (col[C_H] < 0 && col[C_N] < 0)
                FAIL("%s:%d: the header has no column 'h' or 'cells' (need "
                            "quantity, level, h or cells, value, se)", fname, line);
            t->has_cells = col[C_N] >= 0;
            continue;
        }
        if (n != ncol) {
            FAIL("%s:%d: %d fields, the header has %d", fname, line, n, ncol);
        }
        if (++rows > MAX_ROWS) {
            FAIL("%s:%d: more than %d rows", fname, line, MAX_ROWS);
        }
        const char *qn = fld[col[C_Q]], *ln = fld[col[C_L]];
        if (!*qn || !*ln) {
            FAIL("%s:%d: empty %s name", fname, line,
                        !*qn ? "quantity" : "level");
        }
        swg_row r = { NULL, 0, 0, 0, line };
        const int cs = t->has_cells ? col[C_N] : col[C_H];
        const char *sname = t->has_cells ? "cells" : "h";
        struct {
            const char *name;
            int c;
            double *v;
        } nums[3] = { { sname, cs, &r.size }, { "value", col[C_V], &r.value },
                      { "se", col[C_SE], &r.se } };
        for (int k = 0; k < 3; k++)
            if (!swg_csv_number(fld[nums[k].c], nums[k].v)) {
                FAIL("%s:%d: %s '%s' is not a finite decimal number", fname,
                            line, nums[k].name, fld[nums[k].c]);
            }
        if (t->has_cells ? !(r.size >= 1.0) : !(r.size > 0.0)) {
            FAIL("%s:%d: %s '%s' is not %s", fname, line, sname,
                        fld[cs], t->has_cells ? "at least 1" : "positive");
        }
        if (!(r.se >= 0.0)) {
            FAIL("%s:%d: se '%s' is negative", fname, line, fld[col[C_SE]]);
        }
        if (fabs(r.value) > 1e100 || r.se > 1e100) {
            FAIL("%s:%d: %s '%s' is above 1e100 in magnitude", fname, line,
                        fabs(r.value) > 1e100 ? "value" : "se",
                        fabs(r.value) > 1e100 ? fld[col[C_V]] : fld[col[C_SE]]);
        }
        swg_quantity *q = NULL;
        for (size_t i = 0; i < t->n; i++)
            if (!strcmp(t->q[i].name, qn))
                q = &t->q[i];
        if (!q) {
            if (t->n == t->cap) {
                const size_t cap = t->cap ? 2 * t->cap : 8;
                swg_quantity *nq = realloc(t->q, cap * sizeof *nq);
                if (!nq) {
                    FAIL("%s:%d: out of memory", fname, line);
                }
                t->q = nq;
                t->cap = cap;
            }
            q = &t->q[t->n];
            memset(q, 0, sizeof *q);
            if (!(q->name = swg_csv_dup(qn))) {
                FAIL("%s:%d: out of memory", fname, line);
            }
            t->n++;
        }
        for (size_t j = 0; j < q->n; j++)
            if (!strcmp(q->rows[j].label, ln)) {
                FAIL("%s:%d: quantity '%s' has level '%s' twice (also line %d)",
                            fname, line, qn, ln, q->rows[j].line);
            }
        if (q->n == q->cap) {
            const size_t cap = q->cap ? 2 * q->cap : 4;
            swg_row *nr = realloc(q->rows, cap * sizeof *nr);
            if (!nr) {
                FAIL("%s:%d: out of memory", fname, line);
            }
            q->rows = nr;
            q->cap = cap;
        }
        if (!(r.label = swg_csv_dup(ln))) {
            FAIL("%s:%d: out of memory", fname, line);
        }
        q->rows[q->n++] = r;
    }
    if (ferror(f)) {
        FAIL("%s: read error (%s)", fname, strerror(errno));
    }
    if (!header)
        FAIL("%s: no header line (need quantity, level, h or cells, value, se)",
                    fname);
    if (t->n == 0)
        FAIL("%s: no data rows after the header", fname);
out:
    free(buf);
    if (rc)
        swg_table_free(t);
    return rc;
}
