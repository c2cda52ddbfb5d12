/* swe_cmd_ladder.c - snowwedge ladder-level, ladder-rows, ladder-stored,
 * ladder-join, ladder-plot, ladder-cheapest (the resolution ladder's collector,
 * post/wedge-ladder), resolution (post/wedge-resolution), errortime-points
 * (post/wedge-errortime) and compose-table (post/wedge-compose): the numbers
 * from swe_ladder.h, the reading and writing of the runs' files here. These
 * commands parse their own options (swe_ladder_main). */
#include "swe_cli.h"

#include "swe_ladder.h"
#include "swe_spray.h"
#include "swo_out.h"

#include <ctype.h>
#include <errno.h>
#include <glob.h>
#include <regex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---- options ------------------------------------------------------------------------ */
enum { MAXOPT = 8, MAXARG = 64 };
typedef struct {
    const char *name[MAXOPT]; /* the options the command takes */
    const char *val[MAXOPT];  /* their values (NULL: not given) */
    const char *arg[MAXARG];  /* the other arguments */
    int narg;
} opts;

static void parse(int argc, char **argv, opts *o)
{
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(swe_cli_usage, stdout);
            exit(0);
        }
        if (a[0] == '-' && a[1] == '-') {
            int k = 0;
            while (k < MAXOPT && o->name[k] && strcmp(o->name[k], a))
                k++;
            if (k == MAXOPT || !o->name[k])
                swe_cli_die(2, "%s: unknown option '%s' (see --help)", argv[1], a);
            if (i + 1 >= argc)
                swe_cli_die(2, "%s needs a value (see --help)", a);
            o->val[k] = argv[++i];
        } else if (o->narg < MAXARG)
            o->arg[o->narg++] = a;
        else
            swe_cli_die(2, "%s: more than %d arguments", argv[1], MAXARG);
    }
}

static const char *opt(const opts *o, const char *name)
{
    for (int k = 0; k < MAXOPT && o->name[k]; k++)
        if (!strcmp(o->name[k], name))
            return o->val[k];
    return NULL;
}

static const char *need(const opts *o, const char *name, const char *cmd)
{
    const char *v = opt(o, name);
    swe_cli_need(name, v, cmd);
    return v;
}

/* the whole of a text file, NUL-terminated (NULL when unreadable) */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    for (size_t k; s && (k = fread(s + n, 1, cap - n - 1, f)) > 0;) {
        n += k;
        if (n + 1 == cap) {
            char *t = realloc(s, cap *= 2);
            if (!t)
                free(s);
            s = t;
        }
    }
    fclose(f);
    if (!s)
        swe_cli_die(1, "out of memory");
    s[n] = 0;
    return s;
}

/* the next line of text (its newline cut) or NULL at the end; *s moves on */
static char *next_line(char **s)
{
    if (!**s)
        return NULL;
    char *l = *s, *e = strchr(l, '\n');
    if (e) {
        *e = 0;
        *s = e + 1;
    } else
        *s = l + strlen(l);
    return l;
}

/* the fields of a line split at sep, as awk -F does (empty fields kept); the
   line is cut in place; at most max fields, the count returned */
static int split(char *line, char sep, char **f, int max)
{
    int n = 0;
    for (char *s = line;; ) {
        char *e = strchr(s, sep);
        if (n < max)
            f[n] = s;
        n++;
        if (!e)
            break;
        *e = 0;
        s = e + 1;
    }
    return n;
}

/* text with the characters of drop removed, into out */
static void squeeze(const char *s, const char *drop, char *out, size_t outlen)
{
    size_t o = 0;
    for (; *s && o + 1 < outlen; s++)
        if (!strchr(drop, *s))
            out[o++] = *s;
    out[o] = 0;
}

/* text with leading and trailing blanks removed, into out */
static void trim(const char *s, char *out, size_t outlen)
{
    while (*s == ' ')
        s++;
    size_t n = strlen(s);
    while (n && s[n - 1] == ' ')
        n--;
    snprintf(out, outlen, "%.*s", (int)n, s);
}

/* ---- a run of the ladder ------------------------------------------------------------- */
typedef struct {
    char level[64], cells[64], step[64], window[128], tf[64], tc[64], gate[128], mvd[64],
        full[64], variant[64], refine_wake[64], halfstep[64], rear_layers[64];
    char pre[512], post[256], family[1024];
    double w0, w1;
} rung;

static void read_rung(const char *dir, const char *name, rung *r)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/results/level.txt", dir);
    char *t = slurp(path);
    if (!t)
        swe_cli_die(1, "--run %s: no results/level.txt (a run of Allrun's transient route with "
                       "-level support?)", dir);
    struct {
        const char *key;
        char *v;
    } k[] = {{"level", r->level}, {"cells", r->cells}, {"mean_delta_t", r->step},
             {"window", r->window}, {"wall_flow_s", r->tf}, {"wall_clouds_s", r->tc},
             {"gate", r->gate}, {"mvd", r->mvd}, {"full", r->full}, {"variant", r->variant},
             {"refine_wake", r->refine_wake}, {"halfstep", r->halfstep}};
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        if (swe_ladder_key(t, k[i].key, k[i].v, 64))
            swe_cli_die(1, "%s: no '%s' line", path, k[i].key);
    /* rear_layers: absent in a level.txt written before -rear-layers existed (then 0) */
    char rl[64];
    if (swe_ladder_key(t, "rear_layers", rl, sizeof rl))
        snprintf(rl, sizeof rl, "0");
    sscanf(rl, "%63s", r->rear_layers);
    free(t);
    char *end;
    r->w0 = strtod(r->window, &end);
    r->w1 = strtod(end, NULL);
    snprintf(r->pre, sizeof r->pre, "%s,%s,%s,%s,%s", name, strcmp(r->full, "0") ? "full" : "default",
             r->level, r->cells, r->step);
    snprintf(r->post, sizeof r->post, ",%s,%s", r->tf, r->tc);
    snprintf(r->family, sizeof r->family,
             "variant %s;refine_wake %s;halfstep %s;rear_layers %s;gate %s;mvd %s", r->variant,
             r->refine_wake, r->halfstep, r->rear_layers, r->gate, r->mvd);
}

/* ladder-level --name NAME DIR: one tab-separated line: T0,T1 of the window, the
   scale of Cp_b, the row's columns before the value (run,design,level,cells,step)
   and after the error (,t_flow,t_clouds), the decided spray, the family */
static int cmd_level(const opts *o)
{
    const char *name = need(o, "--name", "ladder-level");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-level: give one run folder (see --help)");
    rung r;
    read_rung(o->arg[0], name, &r);
    char *b = strchr(r.window, ' ');
    if (b)
        *b = ',';
    printf("%s\t%.12g\t%s\t%s\t%s\t%s\n", r.window, swe_ladder_cp_scale(), r.pre, r.post, r.mvd,
           r.family);
    return 0;
}

/* the Strouhal number of convergence.md: of the solved flow when the flow was
   played back ("(Strouhal number of the solved flow = X, +- E)": X and E in
   *se), else on the first line with a "(Strouhal number f H/U = X," its last X
   (*se untouched); empty: none */
static int strouhal(const char *path, char *st, size_t stlen, double *se)
{
    char *t = slurp(path), *s = t;
    if (!t)
        return 1;
    static const char solved[] = "(Strouhal number of the solved flow = ";
    static const char key[] = "(Strouhal number f H/U = ";
    int found = 0;
    st[0] = 0;
    const char *p = strstr(t, solved);
    if (p) {
        const char *v = p + strlen(solved);
        const size_t n = strspn(v, "0123456789.eE+-");
        double e;
        if (!strncmp(v + n, ", +- ", 5) && sscanf(v + n + 5, "%lf", &e) == 1) {
            snprintf(st, stlen, "%.*s", (int)n, v);
            /* the peak's half-bin as a uniform error: its standard deviation */
            *se = e / sqrt(3);
            free(t);
            return !*st;
        }
    }
    for (char *l; !found && (l = next_line(&s));)
        for (char *q = strstr(l, key); q; q = strstr(q + 1, key)) {
            const char *v = q + strlen(key);
            const size_t n = strspn(v, "0123456789.eE+-");
            if (v[n] == ',') {
                snprintf(st, stlen, "%.*s", (int)n, v);
                found = 1;
            }
        }
    free(t);
    return !*st;
}

/* does s match awk's / *[0-9]+ *$/ */
static int blank_digits(const char *s)
{
    s += strspn(s, " ");
    const size_t n = strspn(s, "0123456789");
    return n > 0 && !s[n + strspn(s + n, " ")];
}

/* a value and its relative error in % ("-" or empty: 0) as the row's value
   (spaces removed) and its standard error */
static void value_row(const char *what, const char *pre, const char *v, const char *e,
                      const char *post)
{
    char vs[128], es[128];
    squeeze(v, " ", vs, sizeof vs);
    squeeze(e, " %", es, sizeof es);
    const double ev = (!strcmp(es, "-") || !*es) ? 0 : strtod(es, NULL);
    printf("%s,%s,%s,%.6g%s\n", what, pre, vs, strtod(vs, NULL) * ev / 100, post);
}

/* ladder-rows --name NAME DIR: the run's rows of St, the composed sprays' regions
   and the classes' capture */
static int cmd_rows(const opts *o)
{
    const char *name = need(o, "--name", "ladder-rows");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-rows: give one run folder (see --help)");
    const char *d = o->arg[0];
    rung r;
    read_rung(d, name, &r);
    char path[4096], st[128];
    snprintf(path, sizeof path, "%s/results/%s/convergence.md", d, r.gate);
    double st_se = swe_ladder_st_error(r.w0, r.w1);
    if (strouhal(path, st, sizeof st, &st_se))
        swe_cli_die(1, "--run %s: no Strouhal number in %s", d, path);
    printf("St,%s,%s,%.6g%s\n", r.pre, st, st_se, r.post);
    /* the composed sprays: per region the deposit and its error */
    snprintf(path, sizeof path, "%s/results/compose/mvd*/regions.md", d);
    glob_t g;
    int ncomp = 0;
    if (glob(path, 0, NULL, &g) == 0) {
        for (size_t i = 0; i < g.gl_pathc; i++) {
            char *t = slurp(g.gl_pathv[i]);
            if (!t)
                continue;
            /* the spray: the folder's name after "mvd" */
            char q[256], folder[4096];
            snprintf(folder, sizeof folder, "%s", g.gl_pathv[i]);
            folder[strlen(folder) - strlen("/regions.md")] = 0;
            snprintf(q, sizeof q, "%s", strrchr(folder, '/') + strlen("/mvd"));
            static const char *reg[] = {" left side ", " right side ", " centre ", " edges ",
                                        " whole face "};
            static const char *tag[] = {"left", "right", "centre", "edges", "face"};
            int n = 0;
            char *s = t;
            double lr[2][2] = {{NAN, NAN}, {NAN, NAN}}; /* left, right: value, relative error */
            for (char *l; (l = next_line(&s)) && strncmp(l, "## ", 3);) {
                char *f[8];
                const int nf = split(l, '|', f, 8);
                for (int k = 0; nf >= 2 && k < 5; k++)
                    if (!strcmp(f[1], reg[k])) {
                        char what[300];
                        snprintf(what, sizeof what, "%s-mvd%s", tag[k], q);
                        value_row(what, r.pre, nf > 2 ? f[2] : "", nf > 3 ? f[3] : "", r.post);
                        if (k < 2 && nf > 3) {
                            char vs[128], es[128];
                            squeeze(f[2], " ", vs, sizeof vs);
                            squeeze(f[3], " %", es, sizeof es);
                            lr[k][0] = strtod(vs, NULL);
                            lr[k][1] = (!strcmp(es, "-") || !*es) ? 0 : strtod(es, NULL) / 100;
                        }
                        n++;
                    }
            }
            free(t);
            if (n != 5)
                swe_cli_die(1, "--run %s: %s: not the five regions of wedge-compose", d,
                            g.gl_pathv[i]);
            /* the left/right ratio of the two equal side regions; the regions are
               disjoint, so their errors add in quadrature; none without snow on the right */
            if (lr[1][0] > 0 && lr[0][0] >= 0) {
                const double v = lr[0][0] / lr[1][0];
                printf("lr-mvd%s,%s,%.6g,%.6g%s\n", q, r.pre, v,
                       v * sqrt(lr[0][1] * lr[0][1] + lr[1][1] * lr[1][1]), r.post);
            }
            ncomp++;
        }
        globfree(&g);
    }
    if (!ncomp)
        swe_cli_die(1, "--run %s: no results/compose/mvd*/regions.md (a run with size classes)", d);
    /* the decided spray's classes: each one's rear capture and its error */
    snprintf(path, sizeof path, "%s/results/compose/mvd%s/classes.md", d, r.mvd);
    char *t = slurp(path);
    if (!t)
        swe_cli_die(1, "--run %s: no %s", d, path);
    int n = 0;
    char *s = t;
    for (char *l; (l = next_line(&s));) {
        char *f[16], dd[64], what[128];
        const int nf = split(l, '|', f, 16);
        if (nf < 8 || !blank_digits(f[1]))
            continue;
        squeeze(f[1], " ", dd, sizeof dd);
        snprintf(what, sizeof what, "capture-%sum", dd);
        value_row(what, r.pre, f[4], f[5], r.post);
        n++;
    }
    free(t);
    if (!n)
        swe_cli_die(1, "--run %s: %s: no class rows", d, path);
    return 0;
}

/* the rows of a stored ladder (after '#' and blank lines the header, then rows,
   at least one, no run named as one of names " a b "), printed; or exit 2 with
   "WHAT: line N: ..." */
static void stored_rows(const char *path, const char *what, const char *names, FILE *out)
{
    char *t = slurp(path);
    if (!t)
        swe_cli_die(2, "%s: not a readable file", what);
    int h = 0, n = 0, ln = 0;
    char *s = t;
    for (char *l; (l = next_line(&s));) {
        ln++;
        if (l[0] == '#' || !l[strspn(l, " \t\r\v\f")])
            continue;
        if (!h) {
            h = 1;
            if (strcmp(l, SWE_LADDER_HEADER))
                swe_cli_die(2, "%s: line %d: not the header of post/wedge-ladder (%s): \"%s\"", what,
                            ln, SWE_LADDER_HEADER, l);
            continue;
        }
        if (!swe_ladder_row_ok(l))
            swe_cli_die(2, "%s: line %d: not a row of ten fields with a whole level and cell "
                           "count: \"%s\"", what, ln, l);
        char run[512], key[520];
        swe_ladder_field(l, ',', 1, run, sizeof run);
        snprintf(key, sizeof key, " %s ", run);
        if (names && *names && strstr(names, key))
            swe_cli_die(2, "%s: line %d: run \"%s\" is also the name of a --run folder", what, ln,
                        run);
        fprintf(out, "%s\n", l);
        n++;
    }
    free(t);
    if (!n)
        swe_cli_die(2, "%s: no row", what);
}

/* ladder-stored --what TEXT [--names " A B "] LADDER.csv: its rows, checked */
static int cmd_stored(const opts *o)
{
    const char *what = need(o, "--what", "ladder-stored");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-stored: give one ladder file (see --help)");
    stored_rows(o->arg[0], what, opt(o, "--names"), stdout);
    return 0;
}

/* ladder-join --with LADDER.csv --family FAMILY --names " A B " RUNS.csv: the
   runs' table joined with the stored ladder's rows: its family (its '# setting'
   lines) must be the runs'; a quantity of the runs that it lacks is left out
   with a note */
static int cmd_join(const opts *o)
{
    const char *with = need(o, "--with", "ladder-join"), *family = need(o, "--family", "ladder-join"),
               *names = need(o, "--names", "ladder-join");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-join: give the runs' table (see --help)");
    char fam[1024];
    snprintf(fam, sizeof fam, "%s", family);
    for (char *save = NULL, *kv = strtok_r(fam, ";", &save); kv; kv = strtok_r(NULL, ";", &save)) {
        /* the first "# setting K V" line of the stored ladder */
        char k[256], s[256] = "", w[4][256], line[4096], ks[520];
        sscanf(kv, "%255s", k);
        FILE *f = swe_cli_open(with);
        while (fgets(line, sizeof line, f)) {
            const int nw = sscanf(line, "%255s %255s %255s %255s", w[0], w[1], w[2], w[3]);
            if (nw >= 3 && !strcmp(w[0], "#") && !strcmp(w[1], "setting") && !strcmp(w[2], k)) {
                snprintf(s, sizeof s, "%s", nw == 4 ? w[3] : "");
                break;
            }
        }
        fclose(f);
        snprintf(ks, sizeof ks, "%s %s", k, s);
        if (*s && strcmp(ks, kv))
            swe_cli_die(2, "--with %s: its runs have '%s %s', the --run runs '%s': not one mesh "
                           "family", with, k, s, kv);
    }
    char what[4200];
    snprintf(what, sizeof what, "--with %s", with);
    char *rows = NULL;
    size_t rlen = 0;
    FILE *mem = open_memstream(&rows, &rlen);
    if (!mem)
        swe_cli_die(1, "out of memory");
    stored_rows(with, what, names, mem);
    fclose(mem);
    char *r = slurp(o->arg[0]);
    if (!r)
        swe_cli_die(1, "cannot read %s", o->arg[0]);
    /* the stored quantities: ",Q," looked up in a list of them */
    char *qs = malloc(rlen + 2), *rs = rows;
    size_t ql = 0;
    if (!qs)
        swe_cli_die(1, "out of memory");
    qs[ql++] = ',';
    for (char *l; (l = next_line(&rs));) {
        const size_t n = strcspn(l, ",");
        memcpy(qs + ql, l, n);
        ql += n;
        qs[ql++] = ',';
    }
    qs[ql] = 0;
    char *told = calloc(strlen(r) + 2, 1), *s = r;
    if (!told)
        swe_cli_die(1, "out of memory");
    told[0] = ',';
    for (int ln = 1; (rs = next_line(&s)); ln++) {
        char key[1024];
        snprintf(key, sizeof key, ",%.*s,", (int)strcspn(rs, ","), rs);
        if (ln == 1 || strstr(qs, key))
            printf("%s\n", rs);
        else if (!strstr(told, key)) {
            strcat(told, key + 1);
            fprintf(stderr, "snowwedge: note: quantity %.*s is not on the ladder of --with %s: "
                            "not judged\n", (int)strcspn(rs, ","), rs, with);
        }
    }
    /* the stored rows after the runs' (their text: rows cut into lines again) */
    for (size_t i = 0; i < rlen; i++)
        putchar(rows[i] ? rows[i] : '\n');
    free(qs);
    free(told);
    free(r);
    free(rows);
    return 0;
}

/* the targets "A,B,..." as numbers */
static size_t targets_of(const char *list, double *t, size_t max)
{
    size_t n = 0;
    for (const char *s = list; *s && n < max;) {
        t[n++] = strtod(s, NULL);
        s += strcspn(s, ",");
        s += (*s == ',');
    }
    return n;
}

/* TEXT into the file OPT PATH whole or not at all (common/swo_out.h): refused (exit 2)
   when PATH is there and is not a regular file or its folder is missing */
static void write_whole(const char *opt, const char *path, const char *text)
{
    char err[1024];
    swo_set *set = NULL;
    const swo_spec spec = {"snowwedge", opt, NULL, 0, 0};
    int rc = swo_alloc(&spec, &set, err, sizeof err);
    if (rc != SWO_OK)
        swe_cli_die(rc, "%s", err);
    err[0] = 0;
    FILE *f = swo_open(set, path, err, sizeof err);
    if (!f || fputs(text, f) < 0 || swo_commit(set, err, sizeof err) != SWO_OK) {
        rc = swo_code(set);
        swo_free(set);
        if (err[0])
            swe_cli_die(rc ? rc : 1, "%s", err);
        swe_cli_die(1, "cannot write %s", path);
    }
    swo_free(set);
}

/* a text written into a gnuplot string: refused (exit 2) when it holds a quote, a
   backslash, a backquote or a newline, which could end the string or run a command */
static void plain(const char *what, const char *text)
{
    if (strpbrk(text, "'\"\\`\n"))
        swe_cli_die(2, "errortime-plot: %s '%s' holds a quote, backslash, backquote or newline "
                       "(not written into a gnuplot script)", what, text);
}

/* ladder-plot --quantity Q --targets LIST --points FILE --png PNG TOTAL_ERROR.csv:
   per run of Q with a relative error "time error% run(design)" into FILE, and on
   standard output the gnuplot script of the plot into PNG (log-log, the ranges
   from the points and the targets, the targets as dashed lines). Every run is
   its own point style with its name in the key, and the key sits outside the
   data, right of the plot: no label is written over a point or another label
   (runs of one level lie close together), and the key hides no point */
static int cmd_plot(const opts *o)
{
    const char *q = need(o, "--quantity", "ladder-plot"), *tg = need(o, "--targets", "ladder-plot"),
               *pf = need(o, "--points", "ladder-plot"), *png = need(o, "--png", "ladder-plot");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-plot: give one total_error.csv (see --help)");
    char *t = slurp(o->arg[0]), *cur = t, *s;
    if (!t)
        swe_cli_die(1, "cannot read %s", o->arg[0]);
    size_t n = 0, cap = 0;
    double *x = NULL, *y = NULL;
    const char **run = NULL, **design = NULL;   /* into t */
    char *pts = NULL;
    size_t plen = 0;
    FILE *mem = open_memstream(&pts, &plen);
    for (int ln = 1; mem && (s = next_line(&cur)); ln++) {
        char *f[16];
        const int nf = split(s, ',', f, 16);
        if (ln == 1 || nf < 11 || strcmp(f[0], q) || !*f[10])
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            x = realloc(x, cap * sizeof *x);
            y = realloc(y, cap * sizeof *y);
            run = realloc(run, cap * sizeof *run);
            design = realloc(design, cap * sizeof *design);
            if (!x || !y || !run || !design)
                swe_cli_die(1, "out of memory");
        }
        char ys[64];
        swe_ladder_awknum(100 * strtod(f[10], NULL), ys, sizeof ys);
        x[n] = strtod(f[5], NULL);
        run[n] = f[1];
        design[n] = f[2];
        y[n++] = strtod(ys, NULL);
        fprintf(mem, "%s %s %s(%s)\n", f[5], ys, f[1], f[2]);
    }
    if (!mem)
        swe_cli_die(1, "out of memory");
    fclose(mem);
    if (!n)
        swe_cli_die(2, "--plot %s: no such quantity with a relative error in %s", q, o->arg[0]);
    write_whole("--points", pf, pts);
    double tv[64], range[4];
    char r[4][64];
    const size_t nt = targets_of(tg, tv, 64);
    swe_ladder_plot_range(x, y, n, tv, nt, range, NULL, 0);
    for (int i = 0; i < 4; i++)
        swe_ladder_awknum(range[i], r[i], sizeof r[i]);
    printf("set terminal pngcairo size 1100,650 noenhanced\nset output \"%s\"\nset logscale xy\n"
           "set xlabel \"run time: flow + clouds [s]\"\n"
           "set ylabel \"total error of %s (sampling and discretization) [%%]\"\n"
           "set title \"Resolution ladder: total error against run time (%s); dashed: the targets "
           "%s %%\"\n"
           "set grid\nset key outside right top vertical Left reverse\nset xrange [%s:%s]\n"
           "set yrange [%s:%s]\nset ytics (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)\n",
           png, q, q, tg, r[0], r[1], r[2], r[3]);
    for (const char *a = tg; *a;) {
        const int len = (int)strcspn(a, ",");
        printf("set arrow from graph 0, first %.*s to graph 1, first %.*s nohead dt 2 lc rgb "
               "\"gray40\"\n", len, a, len, a);
        a += len + (a[len] == ',');
    }
    /* one series per run (its line of FILE), "run(design)" the key's entry; point
       types and colours cycle */
    const char *col[] = {"#3182bd", "#e6550d", "#31a354", "#756bb1", "#636363", "#d6616b"};
    const int pt[] = {7, 5, 9, 11, 13, 15, 4, 6, 8};
    printf("plot ");
    for (size_t i = 0; i < n; i++)
        printf("%s\"%s\" every ::%zu::%zu using 1:2 with points pt %d ps 1.6 lc rgb \"%s\" "
               "title \"%s(%s)\"", i ? ", \\\n     " : "", pf, i, i, pt[i % 9], col[i % 6], run[i],
               design[i]);
    printf("\n");
    free(pts);
    free(t);
    free(x);
    free(y);
    free(run);
    free(design);
    return 0;
}

/* ladder-cheapest --quantity Q --targets LIST LADDER.md: the cheapest run per
   target of Q (the last columns of its row in the table "## Discretization") */
static int cmd_cheapest(const opts *o)
{
    const char *q = need(o, "--quantity", "ladder-cheapest"),
               *tg = need(o, "--targets", "ladder-cheapest");
    if (o->narg != 1)
        swe_cli_die(2, "ladder-cheapest: give one ladder.md (see --help)");
    char *t = slurp(o->arg[0]), *s = t, key[512];
    if (!t)
        swe_cli_die(1, "cannot read %s", o->arg[0]);
    snprintf(key, sizeof key, " %s ", q);
    double tv[64];
    char tgs[1024];
    const int nt = (int)targets_of(tg, tv, 64);
    snprintf(tgs, sizeof tgs, "%s", tg);
    int on = 0;
    for (char *l; (l = next_line(&s));) {
        if (!strncmp(l, "## ", 3))
            on = !strncmp(l, "## Discretization", 17);
        char *f[64];
        const int nf = split(l, '|', f, 64);
        if (!on || nf < 2 || nf > 64 || strcmp(f[1], key))
            continue;
        printf("wedge-ladder: %s, the cheapest run:", q);
        char *save = NULL, *ti = strtok_r(tgs, ",", &save);
        for (int i = 1; i <= nt; i++, ti = strtok_r(NULL, ",", &save)) {
            const int k = nf - nt + i - 2; /* awk's $(NF - n + i - 1), 0-based */
            /* one blank cut at each end, as the table writes them */
            const char *c = k >= 0 ? f[k] : "";
            c += (*c == ' ');
            int len = (int)strlen(c);
            len -= (len > 0 && c[len - 1] == ' ');
            char v[256];
            snprintf(v, sizeof v, "%.*s", len, c);
            printf(" <= %s %%: %s;", ti ? ti : "", v);
        }
        printf("\n");
        snprintf(tgs, sizeof tgs, "%s", tg);
    }
    free(t);
    return 0;
}

/* ---- two resolutions: post/wedge-resolution ---------------------------------------- */
typedef struct {
    char name[128], e[64];
    double v;
} entry;

/* the rows of a table of regions.md (the first, the window's: its name, deposit,
   relative error) or of classes.md (by class "d<N>um": capture, error) */
static int table(const char *path, int classes, entry *out, int max)
{
    char *t = slurp(path), *s = t;
    if (!t)
        swe_cli_die(1, "cannot read %s", path);
    int n = 0, on = 0;
    const char *start = classes ? "| d [um] |" : "| region | deposit";
    for (char *l; (l = next_line(&s));) {
        if (!on) {
            on = !strncmp(l, start, strlen(start));
            continue;
        }
        if (!strncmp(l, "|---", 4))
            continue;
        if (l[0] != '|')
            break;
        char *f[16];
        const int nf = split(l, '|', f, 16);
        const int cv = classes ? 4 : 2;
        if (n == max)
            swe_cli_die(2, "%s: more than %d rows", path, max);
        entry *e = &out[n++];
        char nm[100];
        if (classes) {
            squeeze(nf > 1 ? f[1] : "", " ", nm, sizeof nm);
            snprintf(e->name, sizeof e->name, "d%sum", nm);
        } else
            trim(nf > 1 ? f[1] : "", e->name, sizeof e->name);
        /* the value as awk passes it on: 6 significant digits */
        char b[64];
        swe_ladder_awknum(nf > cv ? strtod(f[cv], NULL) : 0, b, sizeof b);
        e->v = strtod(b, NULL);
        squeeze(nf > cv + 1 ? f[cv + 1] : "", " %", e->e, sizeof e->e);
        if (!*e->e)
            snprintf(e->e, sizeof e->e, "-");
    }
    free(t);
    return n;
}

static const char *fmt(const entry *e, char *b, size_t len)
{
    if (!strcmp(e->e, "-"))
        snprintf(b, len, "%.4g | -", e->v);
    else
        snprintf(b, len, "%.4g | %s %%", e->v, e->e);
    return b;
}

/* the rows of the comparison; the rows with snow and those differing counted */
static void compare(const entry *b, int nb, const entry *r, int nr, int *nd, int *nw)
{
    *nd = *nw = 0;
    for (int i = 0; i < nb; i++) {
        const entry *bb = b, *rr = NULL;
        for (int j = 0; j < nb; j++) /* the last row of a name, as awk keeps it */
            if (!strcmp(b[j].name, b[i].name))
                bb = &b[j];
        for (int j = 0; j < nr; j++)
            if (!strcmp(r[j].name, b[i].name))
                rr = &r[j];
        char f1[128], f2[128];
        if (!rr) {
            printf("| %s | %s | (missing) | - | - | - | - | missing in the refined run |\n",
                   b[i].name, fmt(bb, f1, sizeof f1));
            continue;
        }
        const double sb = strcmp(bb->e, "-") ? bb->v * strtod(bb->e, NULL) / 100 : 0,
                     sr = strcmp(rr->e, "-") ? rr->v * strtod(rr->e, NULL) / 100 : 0;
        swe_change c;
        swe_ladder_change(bb->v, sb, rr->v, sr, &c);
        if (c.kind == SWE_CHANGE_NONE) {
            printf("| %s | 0 | - | 0 | - | - | - | - | no deposit |\n", b[i].name);
            continue;
        }
        (*nw)++;
        if (c.kind == SWE_CHANGE_ONE) {
            printf("| %s | %s | %s | - | - | - | deposit in one run only |\n", b[i].name,
                   fmt(bb, f1, sizeof f1), fmt(rr, f2, sizeof f2));
            (*nd)++;
            continue;
        }
        char v[128] = "differs";
        if (c.kind == SWE_CHANGE_AGREES)
            snprintf(v, sizeof v, "agrees (change within +-%.0f %% at 2 sigma)", 100 * c.bound);
        else
            (*nd)++;
        printf("| %s | %s | %s | %+.1f %% | %.1f %% | %+.1f | %s |\n", b[i].name,
               fmt(bb, f1, sizeof f1), fmt(rr, f2, sizeof f2), 100 * c.change, 100 * c.se_change,
               c.z, v);
    }
}

static int by_number(const void *a, const void *b)
{
    const char *x = *(char *const *)a, *y = *(char *const *)b;
    const double u = strtod(x, NULL), v = strtod(y, NULL);
    return u < v ? -1 : u > v ? 1 : strcmp(x, y);
}

/* the sprays of both runs: every compose/mvdUM/regions.md of the base that the
   refined run has too, by diameter, comma-separated into list */
static void shared_sprays(const char *base, const char *ref, char *list, size_t len)
{
    char path[4096];
    glob_t g;
    snprintf(path, sizeof path, "%s/compose/mvd*/regions.md", base);
    list[0] = 0;
    if (glob(path, 0, NULL, &g))
        return;
    char **m = calloc(g.gl_pathc, sizeof *m);
    size_t n = 0;
    for (size_t i = 0; m && i < g.gl_pathc; i++) {
        char *p = g.gl_pathv[i], *e = p + strlen(p) - strlen("/regions.md");
        *e = 0;
        p = strrchr(p, '/') + strlen("/mvd");
        snprintf(path, sizeof path, "%s/compose/mvd%s/regions.md", ref, p);
        FILE *f = fopen(path, "r");
        if (f) {
            fclose(f);
            m[n++] = p;
        }
    }
    if (!m)
        swe_cli_die(1, "out of memory");
    qsort(m, n, sizeof *m, by_number);
    for (size_t i = 0; i < n; i++)
        snprintf(list + strlen(list), len - strlen(list), "%s%s", i ? "," : "", m[i]);
    free(m);
    globfree(&g);
}

/* resolution --base DIR --refined DIR [--mvd LIST] [--base-label A] [--refined-label B] */
static int cmd_resolution(const opts *o)
{
    const char *base = need(o, "--base", "resolution"), *ref = need(o, "--refined", "resolution");
    const char *lb = opt(o, "--base-label") ? opt(o, "--base-label") : "base",
               *lr = opt(o, "--refined-label") ? opt(o, "--refined-label") : "refined";
    enum { MAXR = 256 };
    static entry eb[MAXR], er[MAXR];
    char path[4096], list[1024], all[1024];
    int nd, nw;
    const char *dirs[2] = {base, ref};
    for (int i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/compose", dirs[i]);
        struct stat st;
        if (stat(path, &st) || !S_ISDIR(st.st_mode))
            swe_cli_die(1, "%s missing (a run with size classes: Allrun without -sizes none)", path);
    }
    if (opt(o, "--mvd"))
        snprintf(all, sizeof all, "%s", opt(o, "--mvd"));
    else {
        shared_sprays(base, ref, all, sizeof all);
        if (!*all)
            swe_cli_die(1, "the two runs share no composed spray (compose/mvd*/regions.md)");
    }
    /* every item a diameter, every table readable, before the first line */
    for (const char *m = all;; m++) {
        const size_t n = strcspn(m, ",");
        if (!n || strspn(m, "0123456789.") < n)
            swe_cli_die(2, "--mvd needs diameters in um, comma-separated, got '%s' (see --help)", all);
        for (int i = 0; i < 4; i++) {
            snprintf(path, sizeof path, "%s/compose/mvd%.*s/%s", dirs[i / 2], (int)n, m,
                     i % 2 ? "classes.md" : "regions.md");
            FILE *f = fopen(path, "r");
            if (!f)
                swe_cli_die(1, "cannot read %s", path);
            fclose(f);
        }
        m += n;
        if (!*m)
            break;
    }
    const char *mvds = all;
    printf("# Resolution: %s against %s\n\n", lr, lb);
    printf("The composed rear-face capture of the two runs (post/wedge-compose), with the\n"
           "sampling error of each. change = %s / %s - 1; z = difference / its standard error.\n"
           "Base: %s; refined: %s.\n", lr, lb, base, ref);
    snprintf(list, sizeof list, "%s", mvds);
    for (char *save = NULL, *m = strtok_r(list, ",", &save); m; m = strtok_r(NULL, ",", &save)) {
        snprintf(path, sizeof path, "%s/compose/mvd%s/regions.md", base, m);
        const int nb = table(path, 0, eb, MAXR);
        snprintf(path, sizeof path, "%s/compose/mvd%s/regions.md", ref, m);
        const int nr = table(path, 0, er, MAXR);
        if (!nb || !nr)
            swe_cli_die(1, "no region table in compose/mvd%s/regions.md of %s or %s", m, base, ref);
        printf("\n## Spray MVD %s um: rear-face regions [kg / 30 min]\n\n", m);
        printf("| region | %s | +- | %s | +- | change | +- | z | verdict |\n", lb, lr);
        printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
        compare(eb, nb, er, nr, &nd, &nw);
        printf("\nRows with snow (regions and face): %d; differing by more than 2 standard errors: "
               "%d.\n", nw, nd);
    }
    /* the classes (the same in every compose folder: the first spray's) */
    const char *m = list; /* strtok left the first item terminated */
    snprintf(path, sizeof path, "%s/compose/mvd%s/classes.md", base, m);
    const int nb = table(path, 1, eb, MAXR);
    snprintf(path, sizeof path, "%s/compose/mvd%s/classes.md", ref, m);
    const int nr = table(path, 1, er, MAXR);
    if (!nb || !nr)
        swe_cli_die(1, "no class table in compose/mvd%s/classes.md of %s or %s", m, base, ref);
    printf("\n## By size class: rear capture [ppm of the sprayed mass]\n\n");
    printf("| class | %s | +- | %s | +- | change | +- | z | verdict |\n", lb, lr);
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
    compare(eb, nb, er, nr, &nd, &nw);
    printf("\nClasses with snow: %d; differing by more than 2 standard errors: %d.\n", nw, nd);
    return 0;
}

/* ---- error against run time: post/wedge-errortime ------------------------------------ */
/* errortime-points --region R CSV LABEL [CSV LABEL ...]: "design run wall_s error"
   (tab-separated) of every design but the flow with a positive wall time and an
   error of region R in the cost tables */
static int cmd_points(const opts *o)
{
    const char *region = need(o, "--region", "errortime-points");
    static const char *regs[] = {"face", "left", "right", "centre", "edges"};
    int col = -1;
    for (int k = 0; k < 5; k++)
        if (!strcmp(region, regs[k]))
            col = k + 2;
    if (col < 0)
        swe_cli_die(2, "--region: '%s' is not face, left, right, centre or edges", region);
    if (o->narg == 0 || o->narg % 2)
        swe_cli_die(2, "errortime-points: give CSV LABEL pairs (see --help)");
    for (int i = 0; i < o->narg; i += 2) {
        char *t = slurp(o->arg[i]), *cur = t, *s;
        if (!t)
            swe_cli_die(1, "cannot read %s", o->arg[i]);
        for (int ln = 1; (s = next_line(&cur)); ln++) {
            char *f[16];
            const int nf = split(s, ',', f, 16);
            if (ln == 1 || !strcmp(f[0], "flow") || !(nf > 1 && strtod(f[1], NULL) > 0) ||
                nf <= col || !*f[col])
                continue;
            printf("%s\t%s\t%s\t%s\n", f[0], o->arg[i + 1], f[1], f[col]);
        }
        free(t);
    }
    return 0;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* errortime-plot --region R --title TEXT --dir DIR POINTS: the points of every
   design into DIR/d_DESIGN, and on standard output the gnuplot script of the
   plot into DIR/plot.png: one series per design (by name), through each point
   the line of slope -1/2 (error e at time t: e sqrt(t / x)), its run's name
   beside it, the 10 % target */
static int cmd_etplot(const opts *o)
{
    const char *region = need(o, "--region", "errortime-plot"),
               *title = need(o, "--title", "errortime-plot"), *dir = need(o, "--dir", "errortime-plot");
    if (o->narg != 1)
        swe_cli_die(2, "errortime-plot: give one POINTS file (see --help)");
    plain("--title", title);
    plain("--region", region);
    plain("--dir", dir);
    char *t = slurp(o->arg[0]), *cur = t, *l, path[4096];
    if (!t)
        swe_cli_die(1, "cannot read %s", o->arg[0]);
    enum { MAXP = 4096 };
    static char *d[MAXP], *lab[MAXP], *tt[MAXP], *e[MAXP], *names[MAXP];
    int n = 0, nn = 0;
    while ((l = next_line(&cur)) && n < MAXP) {
        char *f[4] = {"", "", "", ""};
        const int nf = split(l, '\t', f, 4);
        if (nf != 4)
            swe_cli_die(2, "%s line %d is not \"design run wall_s error\" (tab-separated)",
                        o->arg[0], n + 1);
        d[n] = f[0], lab[n] = f[1], tt[n] = f[2], e[n] = f[3];
        if (!*d[n] || strspn(d[n], "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                   "0123456789_.+-") != strlen(d[n]) || d[n][0] == '.')
            swe_cli_die(2, "%s line %d: design '%s' is not a name of letters, digits and _ . + -",
                        o->arg[0], n + 1, d[n]);
        plain("run", lab[n]);
        for (int k = 2; k < 4; k++) {
            char *end;
            const double v = strtod(f[k], &end);
            if (!*f[k] || *end || !isfinite(v))
                swe_cli_die(2, "%s line %d: %s '%s' is not a number", o->arg[0], n + 1,
                            k == 2 ? "wall_s" : "error", f[k]);
        }
        int seen = 0;
        for (int k = 0; k < nn; k++)
            seen |= !strcmp(names[k], d[n]);
        if (!seen)
            names[nn++] = d[n];
        n++;
    }
    /* every line checked: each design's file, created here (never one that was there) */
    for (int k = 0; k < nn; k++) {
        struct stat st;
        snprintf(path, sizeof path, "%s/d_%s", dir, names[k]);
        if (!lstat(path, &st))
            swe_cli_die(2, "%s exists: not replaced (--dir needs a folder without d_* files)", path);
    }
    for (int i = 0; i < n; i++) {
        int first = 1;
        for (int k = 0; k < i; k++)
            first &= strcmp(d[k], d[i]) != 0;
        snprintf(path, sizeof path, "%s/d_%s", dir, d[i]);
        FILE *df = fopen(path, first ? "wx" : "a");
        if (!df && first && errno == EEXIST)
            swe_cli_die(2, "%s exists: not replaced (--dir needs a folder without d_* files)", path);
        if (!df || fprintf(df, "%s\t%s\t%s\t%s\n", d[i], lab[i], tt[i], e[i]) < 0 || fclose(df))
            swe_cli_die(1, "cannot write %s", path);
    }
    qsort(names, (size_t)nn, sizeof *names, by_name);
    printf("set terminal pngcairo size 800,560 font ',11'\nset output '%s/plot.png'\n"
           "set logscale xy\nset xlabel 'wall time of the clouds on 2 processes [s]'\n"
           "set ylabel 'relative standard error, %s [%%]'\n"
           "set title \"%s\\n(dotted: 1/sqrt(time) through each point; 10 %% target)", dir,
           region, title);
    if (!n)
        printf("\\n(no design put snow on the %s: no error to plot)", region);
    printf("\"\nset grid\nset key top right\nset xrange [10:100000]\nset yrange [1:200]\n"
           "set samples 200\nplot 10 with lines lw 2 lc rgb 'red' title '10 %% target'");
    if (!nn) /* no design: the shell's unmatched pattern, as the plot has always had */
        printf(", '%s/d_*' using 3:4 with points pt 7 ps 1.5 title '*'", dir);
    for (int k = 0; k < nn; k++)
        printf(", '%s/d_%s' using 3:4 with points pt 7 ps 1.5 title '%s'", dir, names[k], names[k]);
    for (int i = 0; i < n; i++)
        printf(", (%s) * (%s / x) ** 2 > 0 ? %s * sqrt(%s / x) : 1/0 with lines dt 3 lc rgb "
               "'gray40' notitle, '+' using (%s):(%s):('%s') every ::0::0 with labels offset %s "
               "notitle", tt[i], e[i], e[i], tt[i], tt[i], e[i], lab[i], i % 2 ? "1,-1" : "1,1");
    printf("\n");
    free(t);
    return 0;
}

/* ---- the classes of a composition: post/wedge-compose --------------------------------- */
/* one row of rear_statistics.md (the line whose 2nd |-field starts with " LABEL"):
   per region (5 columns) mass [kg] and n_eff; 0 when absent */
static int stats_row(const char *text, const char *label, char *out, size_t outlen)
{
    char *t = strdup(text), *s = t, key[128];
    if (!t)
        swe_cli_die(1, "out of memory");
    snprintf(key, sizeof key, " %s", label);
    int found = 0;
    for (char *l; !found && (l = next_line(&s));) {
        char *f[16];
        const int nf = split(l, '|', f, 16);
        if (nf < 2 || strncmp(f[1], key, strlen(key)))
            continue;
        found = 1;
        size_t o = 0;
        for (int i = 2; i <= 6; i++) {
            double m = 0, ne = 0;
            if (i < nf && strstr(f[i], "kg"))
                for (char *save = NULL, *p = strtok_r(f[i], ",", &save); p;
                     p = strtok_r(NULL, ",", &save)) {
                    char *k = strstr(p, " kg");
                    if (k) {
                        *k = 0;
                        m = strtod(p, NULL);
                    }
                    if ((k = strstr(p, "n_eff")) && (k = strstr(p, "n_eff ")))
                        ne = strtod(k + 6, NULL);
                }
            char a[64], b[64];
            swe_ladder_awknum(m, a, sizeof a);
            swe_ladder_awknum(ne, b, sizeof b);
            o += (size_t)snprintf(out + o, outlen > o ? outlen - o : 0, "%s %s ", a, b);
        }
    }
    free(t);
    return found;
}

/* is s a plain decimal number: digits, an optional point, digits, an optional
   exponent (no sign, no blank) */
static int plain_number(const char *s)
{
    regex_t re;
    if (regcomp(&re, "^[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?$", REG_EXTENDED | REG_NOSUB))
        swe_cli_die(1, "out of memory");
    const int ok = !regexec(&re, s, 0, NULL, 0);
    regfree(&re);
    return ok;
}

/* compose-check [--mvd UM --sigma-g S --range A,B --freeze F] --sampled F: the
   options of post/wedge-compose, each a plain number in its range, or exit 2
   naming the first that is not */
static int cmd_compose_check(const opts *o)
{
    const char *mvd = opt(o, "--mvd"), *sampled = need(o, "--sampled", "compose-check");
    if (mvd) {
        const char *sg = need(o, "--sigma-g", "compose-check"), *fr = need(o, "--freeze", "compose-check"),
                   *range = need(o, "--range", "compose-check");
        double v = strtod(mvd, NULL);
        if (!plain_number(mvd) || !(v >= 0.1 && v <= 1000))
            swe_cli_die(2, "--mvd: '%s' is not a diameter in [0.1, 1000] um (see --help)", mvd);
        v = strtod(sg, NULL);
        if (!plain_number(sg) || !(v > 1 && v <= 10))
            swe_cli_die(2, "--sigma-g: '%s' is not in (1, 10] (see --help)", sg);
        v = strtod(fr, NULL);
        if (!plain_number(fr) || !(v >= 0.5 && v <= 2))
            swe_cli_die(2, "--freeze: '%s' is not in [0.5, 2] (see --help)", fr);
        /* MIN,MAX, split as the shell's read into MIN, MAX, REST does: REST
           (after a second comma) empty or one comma */
        char a[256] = "", b[256] = "";
        const char *c = strchr(range, ',');
        int ok = c != NULL;
        if (ok) {
            snprintf(a, sizeof a, "%.*s", (int)(c - range), range);
            snprintf(b, sizeof b, "%s", c + 1);
            char *rest = strchr(b, ',');
            if (rest && (!rest[1] || !strcmp(rest + 1, ",")))
                *rest = 0;
            ok = !strchr(b, ',') && plain_number(a) && plain_number(b);
        }
        const double lo = strtod(a, NULL), hi = strtod(b, NULL);
        if (!ok || !(lo > 0 && hi > lo && hi <= 10000))
            swe_cli_die(2, "--range: '%s' is not MIN,MAX with 0 < MIN < MAX <= 10000 um (see --help)",
                        range);
    }
    const double v = strtod(sampled, NULL);
    if (!plain_number(sampled) || !(v > 0 && v <= 1))
        swe_cli_die(2, "--sampled: '%s' is not in (0, 1] (see --help)", sampled);
    return 0;
}

/* compose-table --sampled F RESULTS D1 D2 ...: per class "D injected deposit" then
   mass and n_eff of the regions for the window, and the halves when every class
   has them (the --table of snowwedge classes and regions) */
static int cmd_compose_table(const opts *o)
{
    const double f = swe_cli_number("--sampled", need(o, "--sampled", "compose-table"));
    if (o->narg < 2)
        swe_cli_die(2, "compose-table: give RESULTS and the classes (see --help)");
    const char *res = o->arg[0];
    enum { MAXC = 64 };
    static char rows[MAXC][1024], halves[MAXC][1024];
    int all_halves = 1;
    for (int i = 1; i < o->narg && i <= MAXC; i++) {
        char path[4096], d[3072];
        snprintf(d, sizeof d, "%s/d%sum", res, o->arg[i]);
        snprintf(path, sizeof path, "%s/mass_balance.txt", d);
        char *mb = slurp(path), *dp, inj[64] = "", dep[256] = "";
        snprintf(path, sizeof path, "%s/deposit_per_patch.csv", d);
        dp = slurp(path);
        for (char *s = mb, *l; s && (l = next_line(&s));) {
            char w[3][256];
            if (sscanf(l, "%255s %255s %255s", w[0], w[1], w[2]) >= 1 && !strcmp(w[0], "injected"))
                snprintf(inj, sizeof inj, "%.10g", strtod(w[2], NULL) * f);
        }
        for (char *s = dp, *l; s && (l = next_line(&s));) {
            char *fl[8];
            const int nf = split(l, ',', fl, 8);
            if (!strcmp(fl[0], "rear"))
                snprintf(dep, sizeof dep, "%s", nf > 2 ? fl[2] : "");
        }
        free(mb);
        free(dp);
        if (!*inj || !*dep)
            swe_cli_die(1, "%s: no injected mass or rear deposit", d);
        snprintf(path, sizeof path, "%s/rear_statistics.md", d);
        char *st = slurp(path), w[512], h1[512], h2[512];
        if (!st)
            swe_cli_die(1, "cannot read %s", path);
        if (!stats_row(st, "window", w, sizeof w))
            swe_cli_die(1, "%s/rear_statistics.md has no window row", d);
        const int hh = stats_row(st, "first half", h1, sizeof h1) &&
                       stats_row(st, "second half", h2, sizeof h2);
        free(st);
        snprintf(rows[i - 1], sizeof rows[0], "%s %s %s %s", o->arg[i], inj, dep, w);
        snprintf(halves[i - 1], sizeof halves[0], "%s%s", hh ? h1 : "", hh ? h2 : "");
        all_halves &= hh;
    }
    for (int i = 1; i < o->narg && i <= MAXC; i++)
        printf("%s %s\n", rows[i - 1], halves[i - 1]);
    (void)all_halves;
    return 0;
}

/* ---- dispatch ------------------------------------------------------------------------ */
int swe_ladder_main(int argc, char **argv)
{
    static const struct {
        const char *cmd;
        int (*run)(const opts *);
        const char *opt[MAXOPT];
    } c[] = {
        {"ladder-level", cmd_level, {"--name"}},
        {"ladder-rows", cmd_rows, {"--name"}},
        {"ladder-stored", cmd_stored, {"--what", "--names"}},
        {"ladder-join", cmd_join, {"--with", "--family", "--names"}},
        {"ladder-plot", cmd_plot, {"--quantity", "--targets", "--points", "--png"}},
        {"ladder-cheapest", cmd_cheapest, {"--quantity", "--targets"}},
        {"resolution", cmd_resolution,
         {"--base", "--refined", "--mvd", "--base-label", "--refined-label"}},
        {"errortime-points", cmd_points, {"--region"}},
        {"errortime-plot", cmd_etplot, {"--region", "--title", "--dir"}},
        {"compose-table", cmd_compose_table, {"--sampled"}},
        {"compose-check", cmd_compose_check, {"--mvd", "--sigma-g", "--range", "--freeze", "--sampled"}},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
        if (!strcmp(argv[1], c[i].cmd)) {
            opts o = {{0}, {0}, {0}, 0};
            memcpy(o.name, c[i].opt, sizeof o.name);
            parse(argc, argv, &o);
            return c[i].run(&o);
        }
    return -1;
}
