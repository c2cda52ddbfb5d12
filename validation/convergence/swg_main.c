/* swg_main.c - snowgci: the discretization error of a resolution ladder from a
 * table of levels (doc/convergence.md). */
#include "swg_gci.h"
#include "swg_csv.h"
#include "swg_table.h"
#include "swo_out.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *usage =
"NAME\n"
"    snowgci - observed order of convergence, Richardson extrapolation and grid\n"
"    convergence index of a mesh / time-step resolution ladder, with the sampling\n"
"    error of every level\n"
"\n"
"SYNOPSIS\n"
"    snowgci [options] TABLE.csv\n"
"    snowgci [options] -          (the table from standard input)\n"
"    snowgci --help\n"
"\n"
"DESCRIPTION\n"
"    TABLE.csv holds one row per quantity and resolution level, with a header\n"
"    line naming the columns (any order; more columns are ignored; blank lines\n"
"    and lines starting with # are skipped; fields hold no commas):\n"
"\n"
"        quantity  the quantity's name (Cd, St, rear-edges, class-10um, ...)\n"
"        level     the level's name, unique within a quantity\n"
"        h         representative cell size or time step, > 0, or instead\n"
"        cells     the cell count N >= 1: h = (V/N)^(1/D), --volume V, --dim D\n"
"        value     the quantity on that level\n"
"        se        its sampling standard error, >= 0 (0: a deterministic value)\n"
"\n"
"    Per quantity the levels are sorted by h, finest first (1 the finest, as in\n"
"    Celik et al. 2008). With three or more levels the finest three give the\n"
"    verdict; every further consecutive triple is listed too. With\n"
"    e21 = phi2 - phi1, e32 = phi3 - phi2, r21 = h2/h1, r32 = h3/h2, Celik's\n"
"    R = e21/e32 and Rn = R ln r32 / ln r21 (R over its value at order 0;\n"
"    Rn = R when r21 = r32, and the order is positive exactly when\n"
"    0 < Rn < 1), the verdict is\n"
"\n"
"        monotone               0 < Rn < 1: the apparent order p from Celik's\n"
"                               equation p = |ln|e32/e21| + q(p)| / ln r21,\n"
"                               q(p) = ln((r21^p - s)/(r32^p - s)), solved by\n"
"                               GSL's Brent method on [p_min, p_max] (a bound\n"
"                               that is hit is reported); phi_ext21 =\n"
"                               (r21^p phi1 - phi2)/(r21^p - 1); e_a21 =\n"
"                               |(phi1 - phi2)/phi1|; e_ext21 = |(phi_ext21 -\n"
"                               phi1)/phi_ext21|; GCI_fine21 = Fs e_a21 /\n"
"                               (r21^p - 1), Fs 1.25 (--safety-three); the\n"
"                               sampling error carried into p and phi_ext21\n"
"                               (linearised)\n"
"        oscillatory            -1 < Rn < 0: no order; the spread max - min\n"
"        oscillatory-divergent  Rn <= -1: no order; the spread\n"
"        divergent              Rn >= 1 (or e32 = 0): no order; the spread\n"
"        zero-fine-difference   e21 = 0, e32 != 0: no order; the spread\n"
"        unchanged              all values equal, no sampling error\n"
"        not resolved by the statistics\n"
"                               e21 or e32 within K (--z) combined standard errors\n"
"                               sqrt(se_i^2 + se_j^2) of zero: no order can be\n"
"                               drawn from it; the spread and z = |e| / se\n"
"\n"
"    A quantity with two levels gets the two-level estimate with an assumed\n"
"    order (--order, default 2) and Roache's safety factor 3: verdict two-level,\n"
"    or unresolved / unchanged. The formulas and verdicts: doc/convergence.md.\n"
"\n"
"    Every result is computed before anything is written: a bad table prints\n"
"    nothing to standard output and writes no file.\n"
"\n"
"OPTIONS\n"
"    --md FILE            also write the results as markdown tables to FILE\n"
"                         (through a temporary file beside it, renamed at the end)\n"
"    --order P            assumed order of two-level quantities, [0.001, 20] (default 2)\n"
"    --p-range LO,HI      bounds of the apparent order, 0.001 <= LO < HI <= 20\n"
"                         (default 0.5,8)\n"
"    --z K                a level difference within K combined standard errors of\n"
"                         zero is not resolved, [0, 10] (default 2)\n"
"    --safety-three F     safety factor with three levels, [1, 10] (default 1.25)\n"
"    --safety-two F       safety factor with two levels, [1, 10] (default 3)\n"
"    --dim D              dimension for a cells column: 1, 2 or 3 (default 3)\n"
"    --volume V           domain volume (area, length) for a cells column, > 0\n"
"                         (default 1; the ratios do not depend on it)\n"
"    -h, --help           this text\n"
"\n"
"OUTPUT\n"
"    Per quantity: its levels (name, h, value, se), r21, r32, e21, e32 with their\n"
"    z, R, Rn, the verdict; when monotone p (+- its sampling error; Brent's\n"
"    iterations, final bracket and the residual of Celik's equation; the bound\n"
"    when hit), phi_ext21 (+- its sampling error), e_a21, e_ext21, GCI_fine21,\n"
"    the absolute GCI band, the asymptotic-range ratio GCI32 / (r21^p GCI21),\n"
"    U95 = sqrt(GCI_abs^2 + (2 se1)^2); always the spread and half of it over\n"
"    |phi1|. Relative figures need phi1 != 0 (else '-').\n"
"\n"
"EXIT STATUS\n"
"    0 success; 2 usage or input error (one line naming the input and the value:\n"
"    a missing column, a number that is not finite, fewer than two levels, h <= 0,\n"
"    two levels with the same h, a refinement ratio outside [1.001, 100]);\n"
"    1 other failure (the markdown file could not be written).\n"
"\n"
"EXAMPLES\n"
"    snowgci ladder.csv\n"
"    snowgci --md results/gci.md --p-range 0.5,4 ladder.csv\n"
"\n"
"    with ladder.csv\n"
"        quantity,level,h,value,se\n"
"        Cd,coarse,0.004,0.389,0.002\n"
"        Cd,medium,0.0032,0.352,0.002\n"
"        Cd,fine,0.0024,0.342,0.002\n";

typedef struct {
    const char *md;
    const char *in;
    double order;
    int dim;
    double volume;
    swg_settings s;
} opts;

/* the results of one quantity: its levels sorted finest first, the headline
   (three or two levels) and the further triples */
typedef struct {
    const swg_quantity *q;
    swg_level *lv;
    size_t *idx; /* row of each sorted level */
    size_t n;
    swg_result *res; /* n - 2 triples, or one two-level result */
    size_t nres;
} qres;

static int usage_error(const char *fmt, const char *a, const char *b)
{
    fprintf(stderr, "snowgci: ");
    fprintf(stderr, fmt, a, b);
    fprintf(stderr, " (see snowgci --help)\n");
    return 2;
}

/* an option's value: the tables' strict decimal number (swg_csv_number) */
static int number(const char *opt, const char *s, double *v)
{
    if (!swg_csv_number(s, v))
        return usage_error("%s: '%s' is not a finite decimal number", opt, s);
    return 0;
}

static int parse(int argc, char **argv, opts *o)
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            exit(0);
        }
        if (a[0] != '-' || !strcmp(a, "-")) {
            if (o->in)
                return usage_error("one table only: '%s' after '%s'", a, o->in);
            o->in = a;
            continue;
        }
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v)
            return usage_error("%s needs a value%s", a, "");
        double x;
        i++;
        if (!strcmp(a, "--md")) {
            if (!*v)
                return usage_error("%s: an empty file name%s", a, "");
            o->md = v;
        } else if (!strcmp(a, "--order")) {
            if (number(a, v, &x))
                return 2;
            if (!(x >= 1e-3 && x <= SWG_P_LIMIT))
                return usage_error("%s: %s is outside [0.001, 20]", a, v);
            o->order = x;
        } else if (!strcmp(a, "--p-range")) {
            char buf[256];
            if (strlen(v) >= sizeof buf)
                return usage_error("%s: '%.40s...' is too long", a, v);
            strcpy(buf, v);
            char *c = strchr(buf, ',');
            if (!c)
                return usage_error("%s: '%s' is not LO,HI", a, v);
            *c = '\0';
            if (number(a, buf, &o->s.p_min) || number(a, c + 1, &o->s.p_max))
                return 2;
            if (!(o->s.p_min >= 1e-3 && o->s.p_min < o->s.p_max && o->s.p_max <= SWG_P_LIMIT))
                return usage_error("%s: '%s' is not 0.001 <= LO < HI <= 20", a, v);
        } else if (!strcmp(a, "--z")) {
            if (number(a, v, &x))
                return 2;
            if (!(x >= 0.0 && x <= 10.0))
                return usage_error("%s: %s is outside [0, 10]", a, v);
            o->s.z = x;
        } else if (!strcmp(a, "--safety-three") || !strcmp(a, "--safety-two")) {
            if (number(a, v, &x))
                return 2;
            if (!(x >= 1.0 && x <= 10.0))
                return usage_error("%s: %s is outside [1, 10]", a, v);
            *(a[9] == 't' && a[10] == 'h' ? &o->s.fs3 : &o->s.fs2) = x;
        } else if (!strcmp(a, "--dim")) {
            if (strcmp(v, "1") && strcmp(v, "2") && strcmp(v, "3"))
                return usage_error("%s: '%s' is not 1, 2 or 3", a, v);
            o->dim = v[0] - '0';
        } else if (!strcmp(a, "--volume")) {
            if (number(a, v, &x))
                return 2;
            if (!(x >= 1e-100 && x <= 1e100))
                return usage_error("%s: %s is outside [1e-100, 1e100]", a, v);
            o->volume = x;
        } else {
            return usage_error("unknown option '%s'%s", a, "");
        }
    }
    if (!o->in)
        return usage_error("no table given%s%s", "", "");
    return 0;
}

/* finest first; ties are refused by the caller */
static const swg_level *sort_base;
static int by_h(const void *a, const void *b)
{
    const double x = sort_base[*(const size_t *)a].h, y = sort_base[*(const size_t *)b].h;
    return x < y ? -1 : x > y;
}

static void qres_free(qres *r, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        free(r[i].lv);
        free(r[i].idx);
        free(r[i].res);
    }
    free(r);
}

/* levels, sorting and the computation of one quantity; 2 with a message on bad input */
static int compute(const opts *o, const char *fname, const swg_table *t, const swg_quantity *q,
                   qres *r)
{
    char err[512];
    r->q = q;
    r->n = q->n;
    if (q->n < 2) {
        fprintf(stderr, "snowgci: %s: quantity '%s' has %zu level (need at least 2)\n", fname,
                q->name, q->n);
        return 2;
    }
    swg_level *raw = calloc(q->n, sizeof *raw);
    r->lv = calloc(q->n, sizeof *r->lv);
    r->idx = calloc(q->n, sizeof *r->idx);
    r->nres = q->n >= 3 ? q->n - 2 : 1;
    r->res = calloc(r->nres, sizeof *r->res);
    if (!raw || !r->lv || !r->idx || !r->res) {
        free(raw);
        fprintf(stderr, "snowgci: out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < q->n; i++) {
        const swg_row *w = &q->rows[i];
        raw[i].value = w->value;
        raw[i].se = w->se;
        if (t->has_cells) {
            if (swg_cell_size(o->volume, w->size, o->dim, &raw[i].h, err, sizeof err)) {
                fprintf(stderr, "snowgci: %s:%d: %s\n", fname, w->line, err);
                free(raw);
                return 2;
            }
        } else {
            raw[i].h = w->size;
        }
        r->idx[i] = i;
    }
    sort_base = raw;
    qsort(r->idx, q->n, sizeof *r->idx, by_h);
    for (size_t i = 0; i < q->n; i++)
        r->lv[i] = raw[r->idx[i]];
    free(raw);
    for (size_t i = 1; i < q->n; i++)
        if (r->lv[i].h == r->lv[i - 1].h) {
            fprintf(stderr, "snowgci: %s: quantity '%s': levels '%s' and '%s' have the same %s "
                    "(%g)\n", fname, q->name, q->rows[r->idx[i - 1]].label,
                    q->rows[r->idx[i]].label, t->has_cells ? "cells" : "h", r->lv[i].h);
            return 2;
        }
    int rc = 0;
    if (q->n == 2)
        rc = swg_two_level(r->lv, o->order, &o->s, &r->res[0], err, sizeof err);
    else
        for (size_t k = 0; k + 2 < q->n && !rc; k++)
            rc = swg_three_level(r->lv + k, &o->s, &r->res[k], err, sizeof err);
    if (rc) {
        fprintf(stderr, "snowgci: %s: quantity '%s': %s\n", fname, q->name, err);
        return rc == SWG_ENOMEM ? 1 : 2;
    }
    return 0;
}

static const char *bound_name(swg_bound b)
{
    return b == SWG_BOUND_LOW ? "lower" : b == SWG_BOUND_HIGH ? "upper" : "none";
}

/* a difference's combined standard error and z, or "exact" without one */
static void print_se(FILE *f, double se, double z, int resolved)
{
    if (se == 0.0)
        fprintf(f, " (exact)");
    else
        fprintf(f, " (se %.3g, z %.3g%s)", se, z, resolved ? "" : ", not resolved");
}

static void print_result(FILE *f, const qres *q, const swg_result *r, size_t k, const opts *o)
{
    const swg_level *l = q->lv + k;
    const char *n1 = q->q->rows[q->idx[k]].label, *n2 = q->q->rows[q->idx[k + 1]].label;
    if (r->nlevels == 3)
        fprintf(f, "  levels %s / %s / %s: r21 %.6g, r32 %.6g%s\n", n1, n2,
                q->q->rows[q->idx[k + 2]].label, r->r21, r->r32,
                r->ratio_below_1_3 ? " (a ratio below 1.3, Celik's advice)" : "");
    else
        fprintf(f, "  levels %s / %s: r21 %.6g%s\n", n1, n2, r->r21,
                r->ratio_below_1_3 ? " (below 1.3, Celik's advice)" : "");
    fprintf(f, "  e21 %.6g", r->e21);
    print_se(f, r->se21, r->z21, r->resolved21);
    if (r->nlevels == 3) {
        fprintf(f, ", e32 %.6g", r->e32);
        print_se(f, r->se32, r->z32, r->resolved32);
        fprintf(f, ", R %.6g, Rn %.6g", r->R, r->Rn);
    }
    fprintf(f, "\n  verdict: %s", swg_verdict_name(r->verdict));
    if (r->verdict == SWG_UNRESOLVED)
        fprintf(f, " (the values alone: %s; a difference within %g combined standard errors "
                "of zero gives no order)", swg_verdict_name(r->pattern), o->s.z);
    fputc('\n', f);
    if (r->has_order) {
        if (r->verdict == SWG_TWO_LEVEL)
            fprintf(f, "  p %.6g assumed, safety factor %g\n", r->order.p, o->s.fs2);
        else
            fprintf(f, "  p %.6g +- %.3g (Brent %d iterations, bracket %.3g, %s; residual %.3g; "
                    "bound %s of [%g, %g])\n", r->order.p, r->se_p, r->order.iterations,
                    r->order.width, r->order.converged ? "converged" : "NOT converged",
                    r->order.residual, bound_name(r->order.bound), o->s.p_min, o->s.p_max);
        fprintf(f, "  phi_ext21 %.8g +- %.3g", r->phi_ext21, r->se_phi_ext21);
        if (r->has_rel)
            fprintf(f, ", e_a21 %.4g %%, e_ext21 %.4g %%, GCI_fine21 %.4g %%", 100 * r->e_a21,
                    100 * r->e_ext21, 100 * r->gci_fine21);
        fprintf(f, "\n  GCI band +- %.6g (absolute), U95 +- %.6g (with 2 se of %.6g)", r->gci_abs,
                r->u95_abs, l[0].se);
        if (r->nlevels == 3)
            fprintf(f, ", asymptotic ratio %.4g", r->asymptotic);
        fputc('\n', f);
    }
    fprintf(f, "  spread %.6g (%.6g .. %.6g), half of it %.4g %% of |phi1|\n", r->spread,
            r->phi_min, r->phi_max, 100 * r->half_spread_rel);
}

static void print_all(FILE *f, const qres *qs, size_t n, const opts *o, int has_cells)
{
    for (size_t i = 0; i < n; i++) {
        const qres *q = &qs[i];
        fprintf(f, "quantity %s: %zu levels, finest first\n", q->q->name, q->n);
        fprintf(f, "  %-16s %14s %16s %12s\n", "level", has_cells ? "h (from cells)" : "h",
                "value", "se");
        for (size_t j = 0; j < q->n; j++)
            fprintf(f, "  %-16s %14.6g %16.8g %12.4g\n", q->q->rows[q->idx[j]].label, q->lv[j].h,
                    q->lv[j].value, q->lv[j].se);
        for (size_t k = 0; k < q->nres; k++) {
            if (k == 1)
                fprintf(f, "  coarser triples:\n");
            print_result(f, q, &q->res[k], k, o);
        }
        fputc('\n', f);
    }
}

static void md_pct(FILE *f, int ok, double x)
{
    if (ok)
        fprintf(f, " %.3g %% |", 100 * x);
    else
        fprintf(f, " - |");
}

static void write_md(FILE *f, const qres *qs, size_t n, const opts *o, const char *in)
{
    fprintf(f, "<!-- written by snowgci from %s (doc/convergence.md) -->\n\n", in);
    fprintf(f, "| quantity | levels | verdict | p | phi_1 | phi_ext21 | e_a21 | e_ext21 | "
               "GCI_fine21 | U95 (abs) | spread/2 over phi_1 | notes |\n");
    fprintf(f, "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (size_t i = 0; i < n; i++) {
        const qres *q = &qs[i];
        const swg_result *r = &q->res[0];
        fprintf(f, "| %s | %zu | %s |", q->q->name, q->n, swg_verdict_name(r->verdict));
        if (r->has_order && r->verdict == SWG_TWO_LEVEL)
            fprintf(f, " %.3g (assumed) |", r->order.p);
        else if (r->has_order)
            fprintf(f, " %.3g +- %.2g |", r->order.p, r->se_p);
        else
            fprintf(f, " - |");
        fprintf(f, " %.6g +- %.2g |", q->lv[0].value, q->lv[0].se);
        if (r->has_order)
            fprintf(f, " %.6g +- %.2g |", r->phi_ext21, r->se_phi_ext21);
        else
            fprintf(f, " - |");
        md_pct(f, r->has_order && r->has_rel, r->e_a21);
        md_pct(f, r->has_order && r->has_rel, r->e_ext21);
        md_pct(f, r->has_order && r->has_rel, r->gci_fine21);
        if (r->has_order)
            fprintf(f, " %.3g |", r->u95_abs);
        else
            fprintf(f, " - |");
        md_pct(f, q->lv[0].value != 0.0, r->half_spread_rel);
        const char *sep = " ";
        if (!r->resolved21) {
            fprintf(f, "%se21 z %.2g", sep, r->z21);
            sep = "; ";
        }
        if (r->nlevels == 3 && !r->resolved32) {
            fprintf(f, "%se32 z %.2g", sep, r->z32);
            sep = "; ";
        }
        if (r->has_order && r->order.bound != SWG_BOUND_NONE) {
            fprintf(f, "%sp at the %s bound", sep, bound_name(r->order.bound));
            sep = "; ";
        }
        if (r->ratio_below_1_3) {
            fprintf(f, "%sr < 1.3", sep);
            sep = "; ";
        }
        if (r->verdict == SWG_TWO_LEVEL)
            fprintf(f, "%ssafety factor %g", sep, o->s.fs2);
        fprintf(f, " |\n");
    }
    fprintf(f, "\n| quantity | level | h | value | se |\n|---|---|---:|---:|---:|\n");
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < qs[i].n; j++)
            fprintf(f, "| %s | %s | %.6g | %.8g | %.4g |\n", qs[i].q->name,
                    qs[i].q->rows[qs[i].idx[j]].label, qs[i].lv[j].h, qs[i].lv[j].value,
                    qs[i].lv[j].se);
}

/* FILE through the project's output writer (common/swo_out.h): a temporary
   beside it, renamed at the end; never over a folder, device, FIFO or link */
static int md_file(const opts *o, const qres *qs, size_t n)
{
    char err[600];
    const swo_spec spec = { "snowgci", "--md", NULL, 0, 0 };
    swo_set *set = NULL;
    int rc = swo_alloc(&spec, &set, err, sizeof err);
    FILE *f = rc == SWO_OK ? swo_open(set, o->md, err, sizeof err) : NULL;
    if (rc == SWO_OK && !f)
        rc = swo_code(set);
    if (f) {
        write_md(f, qs, n, o, o->in);
        rc = swo_commit(set, err, sizeof err);
    }
    swo_free(set);
    if (rc != SWO_OK)
        fprintf(stderr, "snowgci: %s\n", err);
    return rc;
}

int main(int argc, char **argv)
{
    opts o;
    memset(&o, 0, sizeof o);
    o.order = 2.0;
    o.dim = 3;
    o.volume = 1.0;
    swg_settings_default(&o.s);
    int rc = parse(argc, argv, &o);
    if (rc)
        return rc;
    char err[512];
    if (swg_settings_check(&o.s, err, sizeof err)) {
        fprintf(stderr, "snowgci: %s\n", err);
        return 2;
    }
    FILE *in = strcmp(o.in, "-") ? fopen(o.in, "r") : stdin;
    if (!in) {
        fprintf(stderr, "snowgci: %s: cannot open (%s)\n", o.in, strerror(errno));
        return 2;
    }
    const char *fname = strcmp(o.in, "-") ? o.in : "(stdin)";
    swg_table t;
    rc = swg_table_read(in, fname, &t, err, sizeof err);
    if (in != stdin)
        fclose(in);
    if (rc) {
        fprintf(stderr, "snowgci: %s\n", err);
        return 2;
    }
    qres *qs = calloc(t.n, sizeof *qs);
    if (!qs) {
        swg_table_free(&t);
        fprintf(stderr, "snowgci: out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < t.n && !rc; i++)
        rc = compute(&o, fname, &t, &t.q[i], &qs[i]);
    /* the file first: when it cannot be written, nothing is printed */
    if (!rc && o.md)
        rc = md_file(&o, qs, t.n);
    if (!rc) {
        print_all(stdout, qs, t.n, &o, t.has_cells);
        if (fflush(stdout) != 0) {
            fprintf(stderr, "snowgci: standard output: %s\n", strerror(errno));
            rc = 1;
        }
    }
    qres_free(qs, t.n);
    swg_table_free(&t);
    return rc;
}
