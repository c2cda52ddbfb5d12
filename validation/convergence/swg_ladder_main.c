/* swg_ladder_main.c - snowladder: the mean of a time series over a window with
 * its batch-means error (series), and the total error of every run of a
 * resolution ladder against its run time (total) (doc/convergence.md). */
#include "swg_gci.h"
#include "swg_csv.h"
#include "swg_ladder.h"
#include "swo_out.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *usage =
"NAME\n"
"    snowladder - a resolution ladder of runs: time-series means with their\n"
"    batch-means errors, and every run's total error (sampling and\n"
"    discretization) against its run time\n"
"\n"
"SYNOPSIS\n"
"    snowladder series --window T0,T1 [--batches B] [--column K]\n"
"                      [--minus FILE2 [--column2 K2]] [--scale S] FILE\n"
"    snowladder total --out DIR [--targets LIST] [--order P] [--p-range LO,HI]\n"
"                     [--z K] [--force] LADDER.csv\n"
"    snowladder --help\n"
"\n"
"DESCRIPTION\n"
"    series   FILE is a whitespace-separated table (lines starting with # and\n"
"             blank lines skipped; an OpenFOAM function object's .dat file) with\n"
"             the time in column 1 and the quantity in column K (default 2). With\n"
"             --minus, FILE2's column K2 (default 2) at the same times (to 1e-9\n"
"             relative) is subtracted; the difference is multiplied by S (default\n"
"             1). Prints one line \"mean SE n nbatch first last\": the mean over the\n"
"             samples with T0 < t <= T1 and its standard error by batch means (B\n"
"             consecutive batches of equal count, default 8: the standard deviation\n"
"             of the batch means over sqrt(B); it holds when a batch is longer than\n"
"             the series' correlation time). The wedge's drag coefficient (the\n"
"             forceCoeffs file, column 2) and base-pressure coefficient (the rear\n"
"             face's areaAverage(p) minus the inlet's, S = 1 / (0.5 U^2)).\n"
"\n"
"    total    LADDER.csv has a header naming its columns (any order; more columns\n"
"             ignored; # lines and blank lines skipped; no quoting; at most\n"
"             20 000 rows):\n"
"                 quantity  the quantity (Cd, St, Cp_b, face, edges, class-10um, ...)\n"
"                 run       the run's name (unique per quantity)\n"
"                 level     the run's level (runs of one level have the same cells)\n"
"                 cells     its cell count (h = cells^(-1/3), for the ratios)\n"
"                 value     the quantity in that run\n"
"                 se        its sampling standard error, >= 0\n"
"                 t_flow    the wall time of the run's flow [s], >= 0\n"
"                 t_clouds  the wall time of its clouds [s], >= 0\n"
"                 design    (optional) the run's sampling design (default, full, ...)\n"
"                 step      (optional) its mean time step [s]\n"
"             Per quantity each level is represented by its run of the smallest se;\n"
"             the finest three levels give the verdict (snowgci's: libswgci), two\n"
"             levels the two-level estimate with the assumed order (--order). The\n"
"             reference is phi_ext21 when the verdict gives an order (monotone,\n"
"             two-level: a trend the statistics resolve), with its own uncertainty\n"
"             u = (Fs - 1) |phi1 - phi_ext21|, and every level's discretization error\n"
"             is sqrt((phi_i - ref)^2 + u^2). Otherwise (steps within the sampling\n"
"             noise, oscillation, divergence) a bound over two readings (reference\n"
"             kind \"bound\"): A the finest value phi1, u_A = |phi2 - phi1| (its last\n"
"             change), B the extrapolation of the finest pair with the assumed order\n"
"             (--order), phi1 - (phi2 - phi1) / (r21^p - 1), u_B that step; every\n"
"             level's error the larger of sqrt((phi_i - ref_X)^2 + u_X^2), the\n"
"             reference the reading of the smaller magnitude (B only with A's sign).\n"
"             So a coarse level that lands near the finest value is not taken as\n"
"             accurate, and a fall the statistics do not resolve is not read as\n"
"             convergence. Every run's total error is sqrt(se^2 + disc^2) of its\n"
"             level, relative to |reference|, against its run time t_flow +\n"
"             t_clouds; per target (--targets, percent, default 10,30) the\n"
"             cheapest run whose relative total error reaches it.\n"
"\n"
"OUTPUT (total, into DIR, all or none)\n"
"    ladder.md         the runs (level, design, cells, step, wall times), every\n"
"                      quantity per run (value +- se), per quantity the verdict,\n"
"                      order, reference, GCI or the spread, and the cheapest run\n"
"                      per target; per quantity the total error of every run\n"
"    total_error.csv   quantity,run,design,level,cells,t_total_s,value,se,disc,\n"
"                      total,rel_total,reference,reference_kind\n"
"    gci.csv           the level representatives in snowgci's format\n"
"                      (quantity,level,cells,value,se): snowgci gci.csv repeats the\n"
"                      verdicts with every detail\n"
"    DIR is a SnowWall output folder (common/swo_out.h): created when missing;\n"
"    an empty folder or one holding .snowwall-output is written into; any other\n"
"    is refused (exit 2) unless --force. Files through temporaries, renamed at\n"
"    the end; nothing else in DIR is touched.\n"
"\n"
"OPTIONS\n"
"    --window T0,T1      series: the window, T0 < T1\n"
"    --batches B         series: batches, 2 to 1000 (default 8)\n"
"    --column K          series: FILE's column, 2 to 64 (default 2)\n"
"    --minus FILE2       series: subtract FILE2's column K2 at the same times\n"
"    --column2 K2        series: FILE2's column (default 2)\n"
"    --scale S           series: multiply by S, finite, not 0 (default 1)\n"
"    --out DIR           total: the output folder\n"
"    --targets LIST      total: relative total errors in percent, (0, 1000],\n"
"                        comma-separated (default 10,30)\n"
"    --order P           total: assumed order with two levels, [0.001, 20] (default 2)\n"
"    --p-range LO,HI     total: bounds of the observed order (default 0.5,8)\n"
"    --z K               total: a level difference within K combined standard\n"
"                        errors is not resolved, [0, 10] (default 2)\n"
"    --force             total: write into a folder that is not an output folder\n"
"    -h, --help          this text\n"
"\n"
"EXIT STATUS\n"
"    0 success; 2 usage or input error (one line naming the input, the line and\n"
"    the value; nothing written); 1 other failure (a file could not be written).\n"
"\n"
"EXAMPLES\n"
"    snowladder series --window 0.4,0.8 postProcessing/forceCoeffs/0/coefficient.dat\n"
"    snowladder series --window 0.4,0.8 --scale 0.00529 \\\n"
"        --minus postProcessing/inletPressure/0/surfaceFieldValue.dat \\\n"
"        postProcessing/basePressure/0/surfaceFieldValue.dat\n"
"    snowladder total --out ladder ladder.csv\n"
"    (tutorials/wedge/post/wedge-ladder gathers a ladder's runs and calls both)\n";

#define LINE_LEN 4096
#define MAX_COLS SWG_CSV_MAX_COLS
#define MAX_ROWS 20000 /* rows of a ladder table (the checks are quadratic in it) */

static int uerr(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int uerr(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "snowladder: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n");
    va_end(ap);
    return 2;
}

static int pair(const char *opt, const char *v, double *a, double *b)
{
    char buf[256];
    if (strlen(v) >= sizeof buf)
        return uerr("%s: '%.40s...' is too long", opt, v);
    strcpy(buf, v);
    char *c = strchr(buf, ',');
    if (!c)
        return uerr("%s: '%s' is not A,B", opt, v);
    *c = '\0';
    if (!swg_csv_number(buf, a) || !swg_csv_number(c + 1, b))
        return uerr("%s: '%s' is not two finite decimal numbers A,B", opt, v);
    return 0;
}

static int whole(const char *opt, const char *v, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    const long x = strtol(v, &end, 10);
    if (!*v || *end || errno || x < lo || x > hi || !isdigit((unsigned char)v[0]))
        return uerr("%s: '%s' is not a whole number from %d to %d", opt, v, lo, hi);
    *out = (int)x;
    return 0;
}

/* ---- series ---------------------------------------------------------------- */

typedef struct {
    double *t, *x;
    size_t n, cap;
} series;

/* column k (1-based; 1 the time) of a whitespace table; 2 with a message */
static int read_series(const char *fname, int k, series *s)
{
    FILE *f = fopen(fname, "r");
    if (!f)
        return uerr("%s: cannot open (%s)", fname, strerror(errno));
    char line[LINE_LEN];
    int ln = 0, rc = 0;
    memset(s, 0, sizeof *s);
    while (fgets(line, sizeof line, f)) {
        ln++;
        if (!strchr(line, '\n') && !feof(f)) {
            rc = uerr("%s:%d: a line longer than %d characters", fname, ln, LINE_LEN - 1);
            break;
        }
        char *p = line;
        while (isspace((unsigned char)*p))
            p++;
        if (!*p || *p == '#')
            continue;
        double t = 0, x = 0;
        int col = 0, got = 0;
        for (char *tok = strtok(p, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n")) {
            col++;
            if (col == 1 || col == k) {
                double v;
                if (!swg_csv_number(tok, &v)) {
                    rc = uerr("%s:%d: column %d: '%s' is not a finite decimal number", fname, ln,
                              col, tok);
                    break;
                }
                if (col == 1)
                    t = v;
                else
                    x = v;
                got += col == k;
            }
        }
        if (rc)
            break;
        if (!got) {
            rc = uerr("%s:%d: %d columns, no column %d", fname, ln, col, k);
            break;
        }
        if (s->n == s->cap) {
            const size_t c = s->cap ? 2 * s->cap : 1024;
            double *nt = realloc(s->t, c * sizeof *nt);
            if (nt)
                s->t = nt;
            double *nx = nt ? realloc(s->x, c * sizeof *nx) : NULL;
            if (!nt || !nx) {
                rc = 1;
                fprintf(stderr, "snowladder: out of memory\n");
                break;
            }
            s->x = nx;
            s->cap = c;
        }
        s->t[s->n] = t;
        s->x[s->n] = x;
        s->n++;
    }
    fclose(f);
    if (!rc && s->n == 0)
        rc = uerr("%s: no data line", fname);
    if (rc) {
        free(s->t);
        free(s->x);
        memset(s, 0, sizeof *s);
    }
    return rc;
}

static int cmd_series(int argc, char **argv)
{
    const char *file = NULL, *minus = NULL;
    double t0 = 0, t1 = 0, scale = 1.0;
    int have_window = 0, nb = 8, k = 2, k2 = 2;
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            return 0;
        }
        if (a[0] != '-') {
            if (file)
                return uerr("series: one file only: '%s' after '%s'", a, file);
            file = a;
            continue;
        }
        const char *v = i + 1 < argc ? argv[++i] : NULL;
        if (!v)
            return uerr("%s needs a value (see snowladder --help)", a);
        if (!strcmp(a, "--window")) {
            if (pair(a, v, &t0, &t1))
                return 2;
            if (!(t0 < t1))
                return uerr("--window: '%s' is not T0,T1 with T0 < T1", v);
            have_window = 1;
        } else if (!strcmp(a, "--batches")) {
            if (whole(a, v, 2, 1000, &nb))
                return 2;
        } else if (!strcmp(a, "--column")) {
            if (whole(a, v, 2, MAX_COLS, &k))
                return 2;
        } else if (!strcmp(a, "--column2")) {
            if (whole(a, v, 2, MAX_COLS, &k2))
                return 2;
        } else if (!strcmp(a, "--minus")) {
            minus = v;
        } else if (!strcmp(a, "--scale")) {
            if (!swg_csv_number(v, &scale) || scale == 0.0 || fabs(scale) > 1e100)
                return uerr("--scale: '%s' is not a finite decimal number other than 0", v);
        } else {
            return uerr("series: unknown option '%s' (see snowladder --help)", a);
        }
    }
    if (!file)
        return uerr("series: no file given (see snowladder --help)");
    if (!have_window)
        return uerr("series: --window T0,T1 is required");
    series s, m;
    int rc = read_series(file, k, &s);
    if (rc)
        return rc;
    if (minus) {
        rc = read_series(minus, k2, &m);
        if (rc) {
            free(s.t);
            free(s.x);
            return rc;
        }
        if (m.n != s.n)
            rc = uerr("--minus %s: %zu samples against %zu in %s", minus, m.n, s.n, file);
        for (size_t i = 0; !rc && i < s.n; i++)
            if (fabs(m.t[i] - s.t[i]) > 1e-9 * fmax(fabs(s.t[i]), 1e-300))
                rc = uerr("--minus %s: sample %zu at time %.10g against %.10g in %s", minus,
                          i + 1, m.t[i], s.t[i], file);
        for (size_t i = 0; !rc && i < s.n; i++)
            s.x[i] -= m.x[i];
        free(m.t);
        free(m.x);
    }
    for (size_t i = 0; !rc && i < s.n; i++)
        s.x[i] *= scale;
    swg_series_stat st;
    char err[512];
    if (!rc && swg_series_mean(s.t, s.x, s.n, t0, t1, nb, &st, err, sizeof err))
        rc = uerr("%s: %s", file, err);
    free(s.t);
    free(s.x);
    if (rc)
        return rc;
    printf("%.10g %.6g %zu %d %.10g %.10g\n", st.mean, st.se, st.n, st.nbatch, st.first, st.last);
    return fflush(stdout) ? 1 : 0;
}

/* ---- total ------------------------------------------------------------------- */

typedef struct {
    char *quantity, *run, *level, *design;
    double cells, value, se, t_flow, t_clouds, step;
    int has_step, line;
    /* results */
    double disc, total, rel;
    int has_rel;
} row;

typedef struct {
    const char *name;
    size_t *rows;   /* indices of its rows */
    size_t n;
    swg_level *lv;  /* its levels, finest first (representatives) */
    size_t *rep;    /* the representative row of each level */
    size_t nl;
    double *disc;
    swg_disc d;
} quantity;

enum { C_Q, C_RUN, C_LEVEL, C_CELLS, C_VALUE, C_SE, C_TF, C_TC, C_DESIGN, C_STEP, C_N };
static const char *colname[C_N] = {"quantity", "run",    "level",    "cells",  "value",
                                   "se",       "t_flow", "t_clouds", "design", "step"};

static void rows_free(row *r, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        free(r[i].quantity);
        free(r[i].run);
        free(r[i].level);
        free(r[i].design);
    }
    free(r);
}

/* the ladder table; 2 with a message on bad input */
static int read_ladder(const char *fname, row **out, size_t *nout)
{
    FILE *f = fopen(fname, "r");
    if (!f)
        return uerr("%s: cannot open (%s)", fname, strerror(errno));
    char line[LINE_LEN];
    int ln = 0, rc = 0, ncol = 0, idx[C_N];
    for (int c = 0; c < C_N; c++)
        idx[c] = -1;
    row *r = NULL;
    size_t n = 0, cap = 0;
    while (!rc && fgets(line, sizeof line, f)) {
        ln++;
        if (!strchr(line, '\n') && !feof(f)) {
            rc = uerr("%s:%d: a line longer than %d characters", fname, ln, LINE_LEN - 1);
            break;
        }
        char *p = swg_csv_trim(line);
        if (!*p || *p == '#')
            continue;
        char *fld[MAX_COLS];
        const int nf = swg_csv_split(p, fld);
        if (nf < 0) {
            rc = uerr("%s:%d: more than %d fields", fname, ln, MAX_COLS);
            break;
        }
        if (!ncol) { /* the header */
            ncol = nf;
            for (int j = 0; j < nf; j++)
                for (int c = 0; c < C_N; c++)
                    if (!strcmp(fld[j], colname[c])) {
                        if (idx[c] >= 0) {
                            rc = uerr("%s:%d: column '%s' named twice", fname, ln, colname[c]);
                            break;
                        }
                        idx[c] = j;
                    }
            for (int c = 0; !rc && c < C_DESIGN; c++)
                if (idx[c] < 0)
                    rc = uerr("%s:%d: the header has no column '%s' (needs quantity, run, level, "
                              "cells, value, se, t_flow, t_clouds)", fname, ln, colname[c]);
            continue;
        }
        if (nf != ncol) {
            rc = uerr("%s:%d: %d fields, the header has %d", fname, ln, nf, ncol);
            break;
        }
        if (n == MAX_ROWS) {
            rc = uerr("%s:%d: more than %d rows", fname, ln, MAX_ROWS);
            break;
        }
        if (n == cap) {
            const size_t c = cap ? 2 * cap : 64;
            row *nr = realloc(r, c * sizeof *nr);
            if (!nr) {
                fprintf(stderr, "snowladder: out of memory\n");
                rc = 1;
                break;
            }
            r = nr;
            cap = c;
        }
        row *w = &r[n];
        memset(w, 0, sizeof *w);
        w->line = ln;
        n++;
        for (int c = 0; c < 3; c++)
            if (!*fld[idx[c]]) {
                rc = uerr("%s:%d: an empty %s", fname, ln, colname[c]);
                break;
            }
        if (rc)
            break;
        w->quantity = swg_csv_dup(fld[idx[C_Q]]);
        w->run = swg_csv_dup(fld[idx[C_RUN]]);
        w->level = swg_csv_dup(fld[idx[C_LEVEL]]);
        w->design = swg_csv_dup(idx[C_DESIGN] >= 0 && *fld[idx[C_DESIGN]] ? fld[idx[C_DESIGN]] : "-");
        if (!w->quantity || !w->run || !w->level || !w->design) {
            fprintf(stderr, "snowladder: out of memory\n");
            rc = 1;
            break;
        }
        double *dst[] = {&w->cells, &w->value, &w->se, &w->t_flow, &w->t_clouds};
        const int cols[] = {C_CELLS, C_VALUE, C_SE, C_TF, C_TC};
        for (int k = 0; k < 5 && !rc; k++) {
            const char *s = fld[idx[cols[k]]];
            if (!swg_csv_number(s, dst[k]))
                rc = uerr("%s:%d: %s '%s' is not a finite decimal number", fname, ln,
                          colname[cols[k]], s);
        }
        if (!rc && idx[C_STEP] >= 0 && *fld[idx[C_STEP]]) {
            if (!swg_csv_number(fld[idx[C_STEP]], &w->step) || !(w->step > 0))
                rc = uerr("%s:%d: step '%s' is not a positive decimal number", fname, ln,
                          fld[idx[C_STEP]]);
            w->has_step = 1;
        }
        if (rc)
            break;
        if (!(w->cells >= 1 && w->cells <= 1e15))
            rc = uerr("%s:%d: cells %s is outside [1, 1e15]", fname, ln, fld[idx[C_CELLS]]);
        else if (!(fabs(w->value) <= SWG_VALUE_MAX))
            rc = uerr("%s:%d: value %s is above 1e100", fname, ln, fld[idx[C_VALUE]]);
        else if (!(w->se >= 0 && w->se <= SWG_VALUE_MAX))
            rc = uerr("%s:%d: se %s is outside [0, 1e100]", fname, ln, fld[idx[C_SE]]);
        else if (!(w->t_flow >= 0 && w->t_flow <= 1e12) || !(w->t_clouds >= 0 && w->t_clouds <= 1e12))
            rc = uerr("%s:%d: t_flow %s, t_clouds %s: wall times must be in [0, 1e12] s", fname,
                      ln, fld[idx[C_TF]], fld[idx[C_TC]]);
    }
    fclose(f);
    if (!rc && !ncol)
        rc = uerr("%s: empty (no header)", fname);
    if (!rc && !n)
        rc = uerr("%s: a header and no row", fname);
    if (rc) {
        rows_free(r, n);
        return rc;
    }
    *out = r;
    *nout = n;
    return 0;
}

static void quantities_free(quantity *q, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        free(q[i].rows);
        free(q[i].lv);
        free(q[i].rep);
        free(q[i].disc);
    }
    free(q);
}

static const row *sort_rows;
static int by_cells_desc(const void *a, const void *b)
{
    const double x = sort_rows[*(const size_t *)a].cells, y = sort_rows[*(const size_t *)b].cells;
    return x > y ? -1 : x < y;
}

/* group the rows by quantity, check them, pick the levels' representatives,
   compute the discretization error and every row's total error */
static int analyse(const char *fname, row *r, size_t n, double p_two, const swg_settings *s,
                   quantity **qout, size_t *nq)
{
    quantity *q = calloc(n, sizeof *q);
    if (!q) {
        fprintf(stderr, "snowladder: out of memory\n");
        return 1;
    }
    size_t m = 0;
    int rc = 0;
    /* the quantities and their row counts first, so that each gets its size */
    size_t *qi = calloc(n, sizeof *qi);
    if (!qi) {
        free(q);
        fprintf(stderr, "snowladder: out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < n; i++) {
        size_t j = 0;
        while (j < m && strcmp(q[j].name, r[i].quantity))
            j++;
        if (j == m)
            q[m++].name = r[i].quantity;
        qi[i] = j;
        q[j].nl++; /* the count of rows for now */
    }
    for (size_t j = 0; j < m && !rc; j++) {
        const size_t k = q[j].nl;
        q[j].nl = 0;
        q[j].rows = calloc(k, sizeof *q[j].rows);
        q[j].lv = calloc(k, sizeof *q[j].lv);
        q[j].rep = calloc(k, sizeof *q[j].rep);
        q[j].disc = calloc(k, sizeof *q[j].disc);
        if (!q[j].rows || !q[j].lv || !q[j].rep || !q[j].disc) {
            fprintf(stderr, "snowladder: out of memory\n");
            rc = 1;
        }
    }
    for (size_t i = 0; i < n && !rc; i++) {
        quantity *Q = &q[qi[i]];
        for (size_t k = 0; k < Q->n && !rc; k++) {
            const row *o = &r[Q->rows[k]];
            if (!strcmp(o->run, r[i].run))
                rc = uerr("%s:%d: quantity '%s': run '%s' given twice (line %d)", fname,
                          r[i].line, Q->name, r[i].run, o->line);
            else if (!strcmp(o->level, r[i].level) && o->cells != r[i].cells)
                rc = uerr("%s:%d: quantity '%s': level '%s' with %.15g cells, %.15g in line %d",
                          fname, r[i].line, Q->name, r[i].level, r[i].cells, o->cells, o->line);
            else if (strcmp(o->level, r[i].level) && o->cells == r[i].cells)
                rc = uerr("%s:%d: quantity '%s': levels '%s' and '%s' have the same cells "
                          "(%.15g)", fname, r[i].line, Q->name, o->level, r[i].level, r[i].cells);
        }
        if (rc)
            break;
        /* the level's representative: its run with the smallest se */
        size_t l = 0;
        while (l < Q->nl && strcmp(r[Q->rep[l]].level, r[i].level))
            l++;
        if (l == Q->nl)
            Q->rep[Q->nl++] = i;
        else if (r[i].se < r[Q->rep[l]].se)
            Q->rep[l] = i;
        Q->rows[Q->n++] = i;
    }
    free(qi);
    char err[512];
    for (size_t j = 0; j < m && !rc; j++) {
        quantity *Q = &q[j];
        if (Q->nl < 2) {
            rc = uerr("%s: quantity '%s' has %zu level (need at least 2)", fname, Q->name, Q->nl);
            break;
        }
        sort_rows = r;
        qsort(Q->rep, Q->nl, sizeof *Q->rep, by_cells_desc);
        for (size_t l = 0; l < Q->nl; l++) {
            const row *w = &r[Q->rep[l]];
            Q->lv[l].value = w->value;
            Q->lv[l].se = w->se;
            if (swg_cell_size(1.0, w->cells, 3, &Q->lv[l].h, err, sizeof err)) {
                rc = uerr("%s:%d: %s", fname, w->line, err);
                break;
            }
        }
        if (rc)
            break;
        const int e = swg_discretization(Q->lv, Q->nl, p_two, s, &Q->d, Q->disc, err, sizeof err);
        if (e) {
            rc = e == SWG_ENOMEM ? 1 : uerr("%s: quantity '%s': %s", fname, Q->name, err);
            break;
        }
        for (size_t k = 0; k < Q->n && !rc; k++) {
            row *w = &r[Q->rows[k]];
            size_t l = 0;
            while (strcmp(r[Q->rep[l]].level, w->level))
                l++;
            w->disc = Q->disc[l];
            if (swg_total_error(w->se, w->disc, Q->d.ref, &w->total, &w->rel, &w->has_rel, err,
                                sizeof err))
                rc = uerr("%s:%d: %s", fname, w->line, err);
        }
    }
    if (rc) {
        quantities_free(q, m);
        return rc;
    }
    *qout = q;
    *nq = m;
    return 0;
}

static void pct(FILE *f, int ok, double x)
{
    if (ok)
        fprintf(f, " %.3g %% |", 100 * x);
    else
        fprintf(f, " - |");
}

/* the runs in the order they first appear */
static size_t run_list(const row *r, size_t n, size_t *first)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = 0;
        while (j < k && strcmp(r[first[j]].run, r[i].run))
            j++;
        if (j == k)
            first[k++] = i;
    }
    return k;
}

static void write_md(FILE *f, const char *in, const row *r, size_t n, const quantity *q,
                     size_t nq, const double *tg, int ntg, const size_t *runs, size_t nr,
                     double p_two)
{
    const char *base = strrchr(in, '/');
    fprintf(f, "<!-- written by snowladder total from %s (doc/convergence.md) -->\n\n",
            base ? base + 1 : in);
    fprintf(f, "## Runs\n\n| run | design | level | cells | mean step [s] | flow [s] | clouds [s] | "
               "total [s] |\n|---|---|---|---:|---:|---:|---:|---:|\n");
    for (size_t k = 0; k < nr; k++) {
        const row *w = &r[runs[k]];
        fprintf(f, "| %s | %s | %s | %.0f |", w->run, w->design, w->level, w->cells);
        if (w->has_step)
            fprintf(f, " %.4g |", w->step);
        else
            fprintf(f, " - |");
        fprintf(f, " %.4g | %.4g | %.4g |\n", w->t_flow, w->t_clouds, w->t_flow + w->t_clouds);
    }
    fprintf(f, "\n## Every quantity per run (value +- sampling standard error)\n\n| quantity |");
    for (size_t k = 0; k < nr; k++)
        fprintf(f, " %s (level %s) |", r[runs[k]].run, r[runs[k]].level);
    fprintf(f, "\n|---|");
    for (size_t k = 0; k < nr; k++)
        fprintf(f, "---:|");
    fputc('\n', f);
    for (size_t j = 0; j < nq; j++) {
        fprintf(f, "| %s |", q[j].name);
        for (size_t k = 0; k < nr; k++) {
            size_t i = 0;
            while (i < q[j].n && strcmp(r[q[j].rows[i]].run, r[runs[k]].run))
                i++;
            if (i == q[j].n)
                fprintf(f, " - |");
            else
                fprintf(f, " %.5g +- %.2g |", r[q[j].rows[i]].value, r[q[j].rows[i]].se);
        }
        fputc('\n', f);
    }
    fprintf(f, "\n## Discretization error per quantity (the finest three levels; each level's "
               "run of the smallest se)\n\n| quantity | levels | verdict | p | phi_1 | reference | "
               "GCI_fine21 | spread/2 over phi_1 |");
    for (int t = 0; t < ntg; t++)
        fprintf(f, " cheapest run <= %g %% |", tg[t]);
    fprintf(f, "\n|---|---:|---|---:|---:|---|---:|---:|");
    for (int t = 0; t < ntg; t++)
        fprintf(f, "---|");
    fputc('\n', f);
    for (size_t j = 0; j < nq; j++) {
        const quantity *Q = &q[j];
        const swg_result *g = &Q->d.gci;
        fprintf(f, "| %s | %zu | %s |", Q->name, Q->nl, swg_verdict_name(g->verdict));
        if (g->has_order && g->verdict == SWG_TWO_LEVEL)
            fprintf(f, " %.3g (assumed) |", g->order.p);
        else if (g->has_order)
            fprintf(f, " %.3g +- %.2g%s |", g->order.p, g->se_p,
                    g->order.bound == SWG_BOUND_NONE ? "" : " (at a bound)");
        else
            fprintf(f, " - |");
        fprintf(f, " %.5g +- %.2g | %.5g +- %.2g (%s) |", Q->lv[0].value, Q->lv[0].se, Q->d.ref,
                Q->d.ref_se, swg_ref_kind_name(Q->d.kind));
        pct(f, g->has_order && g->has_rel, g->gci_fine21);
        pct(f, Q->lv[0].value != 0.0, g->half_spread_rel);
        double *rel = malloc(Q->n * sizeof *rel), *cost = malloc(Q->n * sizeof *cost);
        int *ok = malloc(Q->n * sizeof *ok);
        for (int t = 0; t < ntg; t++) {
            size_t pick = 0;
            int found = 0;
            if (rel && cost && ok) {
                for (size_t i = 0; i < Q->n; i++) {
                    rel[i] = r[Q->rows[i]].rel;
                    ok[i] = r[Q->rows[i]].has_rel;
                    cost[i] = r[Q->rows[i]].t_flow + r[Q->rows[i]].t_clouds;
                }
                found = swg_pick(rel, ok, cost, Q->n, tg[t] / 100, &pick);
            }
            if (found == 1) {
                const row *w = &r[Q->rows[pick]];
                fprintf(f, " %s (level %s, %.4g s, %.3g %%) |", w->run, w->level,
                        w->t_flow + w->t_clouds, 100 * w->rel);
            } else {
                fprintf(f, " none |");
            }
        }
        free(rel);
        free(cost);
        free(ok);
        fputc('\n', f);
    }
    fprintf(f, "\nReference: phi_ext21 when the verdict gives an order (a monotone trend the "
               "statistics resolve), with its own uncertainty u = (Fs - 1) |phi_1 - phi_ext21|, "
               "and every level's discretization error sqrt((phi_i - reference)^2 + u^2). "
               "Otherwise a bound (reference kind \"bound\") over two readings: A the finest "
               "value phi_1, u_A = |phi_2 - phi_1|, and B the extrapolation of the finest pair "
               "with the schemes' order p = %g, phi_1 - (phi_2 - phi_1) / (r21^p - 1), u_B its "
               "step; every level's error the larger of sqrt((phi_i - ref_X)^2 + u_X^2), and "
               "the reference the reading of the smaller magnitude. Total error "
               "sqrt(se^2 + disc^2) over |reference|; run time = flow + clouds.\n", p_two);
    fprintf(f, "\n## Total error of every run\n\n| quantity | run | design | level | run time "
               "[s] | sampling | discretization | total | relative |\n"
               "|---|---|---|---|---:|---:|---:|---:|---:|\n");
    for (size_t j = 0; j < nq; j++)
        for (size_t i = 0; i < q[j].n; i++) {
            const row *w = &r[q[j].rows[i]];
            fprintf(f, "| %s | %s | %s | %s | %.4g | %.3g | %.3g | %.3g |", w->quantity, w->run,
                    w->design, w->level, w->t_flow + w->t_clouds, w->se, w->disc, w->total);
            pct(f, w->has_rel, w->rel);
            fputc('\n', f);
        }
    (void)n;
}

static void write_total_csv(FILE *f, const row *r, const quantity *q, size_t nq)
{
    fprintf(f, "quantity,run,design,level,cells,t_total_s,value,se,disc,total,rel_total,"
               "reference,reference_kind\n");
    for (size_t j = 0; j < nq; j++)
        for (size_t i = 0; i < q[j].n; i++) {
            const row *w = &r[q[j].rows[i]];
            fprintf(f, "%s,%s,%s,%s,%.0f,%.6g,%.10g,%.6g,%.6g,%.6g,", w->quantity, w->run,
                    w->design, w->level, w->cells, w->t_flow + w->t_clouds, w->value, w->se,
                    w->disc, w->total);
            if (w->has_rel)
                fprintf(f, "%.6g", w->rel);
            fprintf(f, ",%.10g,%s\n", q[j].d.ref,
                    swg_ref_kind_name(q[j].d.kind));
        }
}

static void write_gci_csv(FILE *f, const row *r, const quantity *q, size_t nq)
{
    fprintf(f, "quantity,level,cells,value,se\n");
    for (size_t j = 0; j < nq; j++)
        for (size_t l = 0; l < q[j].nl; l++) {
            const row *w = &r[q[j].rep[l]];
            fprintf(f, "%s,%s,%.0f,%.10g,%.6g\n", w->quantity, w->level, w->cells, w->value,
                    w->se);
        }
}

static int cmd_total(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *targets = "10,30";
    double p_two = 2.0;
    int force = 0;
    swg_settings s;
    swg_settings_default(&s);
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            return 0;
        }
        if (!strcmp(a, "--force")) {
            force = 1;
            continue;
        }
        if (a[0] != '-') {
            if (in)
                return uerr("total: one table only: '%s' after '%s'", a, in);
            in = a;
            continue;
        }
        const char *v = i + 1 < argc ? argv[++i] : NULL;
        if (!v)
            return uerr("%s needs a value (see snowladder --help)", a);
        double x;
        if (!strcmp(a, "--out")) {
            if (!*v)
                return uerr("--out: an empty folder name");
            out = v;
        } else if (!strcmp(a, "--targets")) {
            targets = v;
        } else if (!strcmp(a, "--order")) {
            if (!swg_csv_number(v, &x) || !(x >= 1e-3 && x <= SWG_P_LIMIT))
                return uerr("--order: '%s' is not a number in [0.001, 20]", v);
            p_two = x;
        } else if (!strcmp(a, "--p-range")) {
            if (pair(a, v, &s.p_min, &s.p_max))
                return 2;
            if (!(s.p_min >= 1e-3 && s.p_min < s.p_max && s.p_max <= SWG_P_LIMIT))
                return uerr("--p-range: '%s' is not 0.001 <= LO < HI <= 20", v);
        } else if (!strcmp(a, "--z")) {
            if (!swg_csv_number(v, &x) || !(x >= 0 && x <= 10))
                return uerr("--z: '%s' is not a number in [0, 10]", v);
            s.z = x;
        } else {
            return uerr("total: unknown option '%s' (see snowladder --help)", a);
        }
    }
    if (!in)
        return uerr("total: no table given (see snowladder --help)");
    if (!out)
        return uerr("total: --out DIR is required");
    char err[512], note[256];
    double *tg = NULL;
    int ntg = 0;
    if (swo_list_numbers("--targets", targets, 0.0, 1000.0, 1, 100, &tg, &ntg, note, sizeof note,
                         err, sizeof err))
        return uerr("%s", err);
    if (*note)
        fprintf(stderr, "snowladder: note: %s\n", note);
    row *r = NULL;
    size_t n = 0, nq = 0;
    quantity *q = NULL;
    int rc = read_ladder(in, &r, &n);
    if (!rc)
        rc = analyse(in, r, n, p_two, &s, &q, &nq);
    size_t *runs = rc ? NULL : malloc(n * sizeof *runs);
    if (!rc && !runs) {
        fprintf(stderr, "snowladder: out of memory\n");
        rc = 1;
    }
    swo_set *o = NULL;
    if (!rc) {
        const swo_spec spec = {"snowladder total", "--out", out, force, 0};
        rc = swo_alloc(&spec, &o, err, sizeof err);
        if (rc)
            fprintf(stderr, "snowladder: %s\n", err);
        else if (swo_note(o))
            fprintf(stderr, "snowladder: %s\n", swo_note(o));
    }
    if (!rc) {
        swo_signals_on();
        const size_t nr = run_list(r, n, runs);
        FILE *fm = swo_open(o, "ladder.md", err, sizeof err);
        FILE *ft = fm ? swo_open(o, "total_error.csv", err, sizeof err) : NULL;
        FILE *fg = ft ? swo_open(o, "gci.csv", err, sizeof err) : NULL;
        if (!fg) {
            rc = swo_code(o);
            fprintf(stderr, "snowladder: %s\n", err);
        } else {
            write_md(fm, in, r, n, q, nq, tg, ntg, runs, nr, p_two);
            write_total_csv(ft, r, q, nq);
            write_gci_csv(fg, r, q, nq);
            rc = swo_commit(o, err, sizeof err);
            if (rc)
                fprintf(stderr, "snowladder: %s\n", err);
        }
    }
    if (!rc) {
        for (size_t j = 0; j < nq; j++)
            printf("%s: %zu levels, %s, reference %.6g (%s)\n", q[j].name, q[j].nl,
                   swg_verdict_name(q[j].d.gci.verdict), q[j].d.ref,
                   swg_ref_kind_name(q[j].d.kind));
        printf("written: %s/ladder.md, total_error.csv, gci.csv\n", out);
        if (fflush(stdout))
            rc = 1;
    }
    swo_free(o);
    free(runs);
    free(tg);
    if (q)
        quantities_free(q, nq);
    rows_free(r, n);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return uerr("a command is needed: series or total (see snowladder --help)");
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, stdout);
        return 0;
    }
    if (!strcmp(argv[1], "series"))
        return cmd_series(argc, argv);
    if (!strcmp(argv[1], "total"))
        return cmd_total(argc, argv);
    return uerr("unknown command '%s': series or total (see snowladder --help)", argv[1]);
}
