/* swe_cmd_post.c - snowwedge's per-run post-processing commands (the tables
 * of tutorials/wedge/post/wedge-*; numbers from swe_post.h). They read the
 * case in the current folder and parse their own options; --name NAME sets
 * the prefix of their messages (the calling script's name). */
#include "swe_cli.h"
#include "swo_out.h"
#include "swe_plot.h"
#include "swe_post.h"

#include <glob.h>
#include <locale.h>
#include <sys/stat.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *prog = "snowwedge";
static const char *const patches[6] = {"rear", "nose", "top", "bottom", "sideYneg", "sideYpos"};

static void die(int code, const char *fmt, ...) __attribute__((noreturn, format(printf, 2, 3)));
static swo_set *live; /* the output file being written (common/swo_out.h), removed when the
                        command fails */

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    swo_free(live);
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

/* one output file OPT PATH, written whole or not at all: a temporary in its folder (mode
   644), renamed by out_commit(); refused (exit 2) when PATH is there and is not a regular
   file (a folder, link, device, FIFO) or its folder is missing */
static FILE *out_open(const char *opt, const char *path)
{
    char err[1024];
    const swo_spec spec = {prog, opt, NULL, 0, 0};
    if (swo_alloc(&spec, &live, err, sizeof err) != SWO_OK)
        die(2, "%s", err);
    const char *tmp = swo_add(live, path, err, sizeof err);
    if (!tmp)
        die(swo_code(live), "%s", err);
    FILE *f = fopen(tmp, "w");
    if (!f || chmod(tmp, 0644))
        die(1, "cannot write %s", path);
    return f;
}

static void out_commit(FILE *f, const char *path)
{
    char err[1024];
    if (fclose(f))
        die(1, "cannot write %s", path);
    if (swo_commit(live, err, sizeof err) != SWO_OK)
        die(swo_code(live), "%s", err);
    swo_free(live);
    live = NULL;
}

/* the options of the post commands (NULL: not given) */
typedef struct {
    const char *cloud, *gate, *what, *window, *csv, *log, *split, *sampled, *label, *soi, *level,
        *results, *mvd, *variant, *minus, *factor, *file, *time, *patch, *rel, *dispersion, *main, *others, *part,
        *threshold, *dir;
    int reasons, exact;
    const char **files;
    int nfiles;
} post_opts;

static void parse(int argc, char **argv, post_opts *o)
{
    static const char *names[] = {"--cloud", "--gate", "--what", "--window", "--csv", "--log",
                                  "--split", "--sampled", "--label", "--soi", "--level",
                                  "--results", "--mvd", "--variant", "--minus", "--factor",
                                  "--file", "--time", "--patch", "--rel", "--dispersion",
                                  "--main", "--others", "--part", "--threshold", "--dir"};
    const char **slot[] = {&o->cloud, &o->gate, &o->what, &o->window, &o->csv, &o->log,
                           &o->split, &o->sampled, &o->label, &o->soi, &o->level,
                           &o->results, &o->mvd, &o->variant, &o->minus, &o->factor,
                           &o->file, &o->time, &o->patch, &o->rel, &o->dispersion,
                           &o->main, &o->others, &o->part, &o->threshold, &o->dir};
    o->files = calloc((size_t)argc, sizeof *o->files);
    if (!o->files)
        die(1, "out of memory");
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(swe_cli_usage, stdout);
            exit(0);
        }
        if (!strcmp(a, "--reasons") || !strcmp(a, "--exact")) {
            *(a[2] == 'r' ? &o->reasons : &o->exact) = 1;
            continue;
        }
        if (strncmp(a, "--", 2)) {
            o->files[o->nfiles++] = a;
            continue;
        }
        if (i + 1 >= argc || !argv[i + 1][0])
            die(2, "%s needs a value (see --help)", a);
        const char *v = argv[++i];
        if (!strcmp(a, "--name")) {
            prog = v;
            continue;
        }
        size_t k = 0;
        while (k < sizeof names / sizeof *names && strcmp(a, names[k]))
            k++;
        if (k == sizeof names / sizeof *names)
            die(2, "%s: unknown option '%s' (see --help)", argv[1], a);
        *slot[k] = v;
    }
}

static void need(const char *v, const char *opt, const char *cmd)
{
    if (!v)
        die(2, "%s: %s is required (see --help)", cmd, opt);
}

/* a reader's failure: a missing or incomplete input of the run (exit 1) */
static void check(int rc, const char *err)
{
    if (rc)
        die(1, "%s", err);
}

/* kinematicCloud_d<digits>um: a size class's cloud */
static int is_class(const char *name)
{
    const char *p = name + 16;
    if (strncmp(name, "kinematicCloud_d", 16) || !strchr("0123456789", *p) || !*p)
        return 0;
    while (*p >= '0' && *p <= '9')
        p++;
    return !strcmp(p, "um");
}

/* "A,B" or "A,B,C" of --window, as written */
static int split_times(const char *s, char t[3][64])
{
    int n = 0;
    for (const char *p = s; n < 3; n++) {
        const char *c = strchr(p, ',');
        const size_t len = c ? (size_t)(c - p) : strlen(p);
        snprintf(t[n], 64, "%.*s", (int)(len < 63 ? len : 63), p);
        if (!c)
            return n + 1;
        p = c + 1;
    }
    return 4;
}

static char err[1024];

/* ---- rear-map: a rear-face map as CSV ----------------------------------------------- */
typedef struct {
    double y, z;
    char line[96];
} map_row;

static int by_z_then_y(const void *a, const void *b)
{
    const map_row *p = a, *q = b;
    if (p->z != q->z)
        return p->z < q->z ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return strcmp(p->line, q->line);
}

/* the map K x (RAW - MINUS) (MINUS NULL: RAW) as CSV into out */
static void write_map(const char *minus, const char *raw, double k, FILE *out)
{
    swe_post_raw a = {0}, b;
    if (minus)
        check(swe_post_raw_read(minus, &a, err, sizeof err), err);
    check(swe_post_raw_read(raw, &b, err, sizeof err), err);
    if (minus && a.n != b.n)
        die(1, "rear-face maps %s and %s differ", minus, raw);
    if (!b.n)
        die(1, "%s holds no face values", raw);
    map_row *r = malloc(b.n * sizeof *r);
    if (!r)
        die(1, "out of memory");
    for (size_t i = 0; i < b.n; i++) {
        const double v = minus ? b.v[i] - a.v[i] : b.v[i];
        snprintf(r[i].line, sizeof r[i].line, "%.9g,%.9g,%.9g", b.y[i], b.z[i], k * v);
        r[i].y = swe_post_round(b.y[i], 9);
        r[i].z = swe_post_round(b.z[i], 9);
    }
    qsort(r, b.n, sizeof *r, by_z_then_y);
    fputs("y,z,deposit_kg_m2\n", out);
    for (size_t i = 0; i < b.n; i++)
        fprintf(out, "%s\n", r[i].line);
    free(r);
    swe_post_raw_free(&a);
    swe_post_raw_free(&b);
}

static int rear_map(const post_opts *o)
{
    if (o->nfiles != 1)
        die(2, "rear-map: give one raw file (see --help)");
    write_map(o->minus, o->files[0], o->factor ? swe_cli_number("--factor", o->factor) : 1, stdout);
    return 0;
}

/* the map into DIR/NAME, whole or not at all (out_open) */
static void publish_map(const char *dir, const char *name, const char *minus, const char *raw, double k)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = out_open("--dir", path);
    write_map(minus, raw, k, f);
    out_commit(f, path);
}

/* the raw rear-face file of the cloud's field written at time T (numerically), or the latest */
static void raw_at(const char *cloud, const char *t, char *path, size_t n)
{
    char dir[256], file[512];
    snprintf(file, sizeof file, "%s:snowDeposit_patch_rear.raw", cloud);
    swe_post_time_dir("postProcessing/deposit_rear/surface", file, t, dir, sizeof dir);
    if (!dir[0])
        die(1, "no rear-face map of %s:snowDeposit at time %s in postProcessing/deposit_rear/surface/", cloud, t);
    snprintf(path, n, "postProcessing/deposit_rear/surface/%s/%s", dir, file);
}

/* rear-maps: rear_deposit.csv into --out (the window T0 .. T1, else the last write) and
   with a window its halves x2, rear_deposit_half1.csv and _half2.csv */
static int rear_maps(const post_opts *o)
{
    need(o->cloud, "--cloud", "rear-maps");
    need(o->dir, "--dir", "rear-maps");
    char r[3][4096], t[3][64];
    if (!o->window) {
        raw_at(o->cloud, "last", r[0], sizeof r[0]);
        publish_map(o->dir, "rear_deposit.csv", NULL, r[0], 1);
        return 0;
    }
    if (split_times(o->window, t) != 3)
        die(2, "rear-maps: --window '%s' is not T0,TH,T1", o->window);
    for (int i = 0; i < 3; i++)
        raw_at(o->cloud, t[i], r[i], sizeof r[i]);
    publish_map(o->dir, "rear_deposit.csv", r[0], r[2], 1);
    publish_map(o->dir, "rear_deposit_half1.csv", r[0], r[1], 2);
    publish_map(o->dir, "rear_deposit_half2.csv", r[1], r[2], 2);
    return 0;
}

/* ---- patch-table: deposit_per_patch.csv and .md ---------------------------------------- */
static void field_path(char *p, size_t n, const char *patch)
{
    snprintf(p, n, "postProcessing/deposit_%s/0/surfaceFieldValue.dat", patch);
}

static double integral(const char *cloud, const char *patch, const char *t)
{
    char p[512], col[512];
    double v;
    field_path(p, sizeof p, patch);
    snprintf(col, sizeof col, "areaIntegrate(%s:snowDeposit)", cloud);
    check(swe_post_field_at(p, col, t, &v, err, sizeof err), err);
    return v;
}

static void counts(const char *cloud, const char *patch, const char *t, double c[5])
{
    char p[512];
    snprintf(p, sizeof p, "postProcessing/%s:snowWall/0/snowWall.dat", cloud);
    check(swe_post_counts_at(p, patch, t, c, err, sizeof err), err);
}

/* the counts by reason at time t; 0 when the wall model wrote none by then */
static int reasons(const char *cloud, const char *patch, const char *t, long r[5])
{
    char parent[512], dir[256], p[1024];
    snprintf(parent, sizeof parent, "postProcessing/%s:snowWall", cloud);
    swe_post_time_dir(parent, "reasons.dat", t, dir, sizeof dir);
    if (!dir[0])
        return 0;
    snprintf(p, sizeof p, "%s/%s/reasons.dat", parent, dir);
    check(swe_post_reasons(p, patch, r, err, sizeof err), err);
    return 1;
}

static int patch_table(const post_opts *o)
{
    need(o->cloud, "--cloud", "patch-table");
    need(o->csv, "--csv", "patch-table");
    char t[3][64] = {"last", "last", ""};
    if (o->window && split_times(o->window, t) != 2)
        die(2, "patch-table: --window '%s' is not T0,T1", o->window);
    FILE *csv = out_open("--csv", o->csv);
    fputs("patch,area_m2,deposit_kg,mean_kg_m2,impacts,sticks,bounces,ripoffs,logged_kg,stuck,"
          "criterion,tangential,shear,probability\n", csv);
    puts("| patch | area [m2] | deposit [kg] | mean [kg/m2] | impacts | sticks | bounces | "
         "rip-offs | bounced by: criterion | tangential gate | probability |");
    puts("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    double total = 0;
    for (int i = 0; i < 6; i++) {
        const char *p = patches[i];
        char path[512];
        double area, c0[5] = {0}, c[5];
        long r0[5] = {0}, r[5];
        field_path(path, sizeof path, p);
        swe_post_area(path, &area);
        double mass = integral(o->cloud, p, t[1]);
        counts(o->cloud, p, t[1], c);
        int have = reasons(o->cloud, p, t[1], r);
        if (o->window) {
            mass = swe_post_round(mass - integral(o->cloud, p, t[0]), 10);
            counts(o->cloud, p, t[0], c0);
            have = reasons(o->cloud, p, t[0], r0) && have;
        }
        for (int k = 0; k < 5; k++) {
            c[k] = k < 4 ? (double)(long)(c[k] - c0[k]) : swe_post_round(c[k] - c0[k], 10);
            r[k] -= r0[k];
        }
        if (have && (r[0] + r[1] + r[2] + r[3] + r[4] != (long)c[0] || r[0] != (long)c[1] ||
                     r[1] + r[2] + r[4] != (long)c[2] || r[3] != (long)c[3]))
            die(1, "patch %s: the counts by reason (stuck %ld criterion %ld tangential %ld shear "
                   "%ld probability %ld) do not add up to impacts %ld, sticks %ld, bounces %ld, "
                   "rip-offs %ld", p, r[0], r[1], r[2], r[3], r[4], (long)c[0], (long)c[1],
                (long)c[2], (long)c[3]);
        char rs[256] = "-,-,-,-,-", row[4][32];
        if (have)
            snprintf(rs, sizeof rs, "%ld,%ld,%ld,%ld,%ld", r[0], r[1], r[2], r[3], r[4]);
        snprintf(row[0], 32, "%.6g", area);
        snprintf(row[1], 32, "%.6g", mass);
        snprintf(row[2], 32, "%.6g", area > 0 ? mass / area : 0);
        fprintf(csv, "%s,%s,%s,%s,%ld,%ld,%ld,%ld,%.10g,%s\n", p, row[0], row[1], row[2],
                (long)c[0], (long)c[1], (long)c[2], (long)c[3], c[4], rs);
        char rr[5][32] = {"-", "-", "-", "-", "-"};
        for (int k = 0; have && k < 5; k++)
            snprintf(rr[k], 32, "%ld", r[k]);
        printf("| %s | %s | %s | %s | %ld | %ld | %ld | %ld | %s | %s | %s |\n", p, row[0], row[1],
               row[2], (long)c[0], (long)c[1], (long)c[2], (long)c[3], rr[1], rr[2], rr[4]);
        total += strtod(row[1], NULL);
    }
    printf("| **all wedge faces** | | **%.6g** | | | | | | | | |\n\nGate setting: %s. Deposit = "
           "area integral of %s:snowDeposit (%s); counts of the wall model over the same time. "
           "Counts by reason from the wall model's reasons.dat (sticks = stuck, rip-offs = shear "
           "gate, bounces = criterion + tangential gate + probability draw; checked to add up; - "
           "without one).\n", total, o->gate ? o->gate : "off", o->cloud,
           o->what ? o->what : "30 min");
    out_commit(csv, o->csv);
    return 0;
}

/* ---- time-dir, deposit, map-max: single numbers of the run ---------------------------- */
static int time_dir(const post_opts *o)
{
    need(o->file, "--file", "time-dir");
    if (o->nfiles != 1)
        die(2, "time-dir: give one parent folder (see --help)");
    char dir[256];
    swe_post_time_dir(o->files[0], o->file, o->time ? o->time : "last", dir, sizeof dir);
    if (dir[0])
        puts(dir);
    return 0;
}

static int deposit(const post_opts *o)
{
    need(o->cloud, "--cloud", "deposit");
    need(o->patch, "--patch", "deposit");
    char t[3][64] = {"last", "last", ""};
    if (o->window && split_times(o->window, t) != 2)
        die(2, "deposit: --window '%s' is not T0,T1", o->window);
    const double a = o->window ? integral(o->cloud, o->patch, t[0]) : 0;
    printf("%.3g\n", integral(o->cloud, o->patch, t[1]) - a);
    return 0;
}

/* the largest value of rear-face maps (0 when none is positive), to 6 digits,
   and --rel F times it (times the exact one with --exact) */
static int map_max(const post_opts *o)
{
    double m = 0;
    char err[1024];
    if (swe_plot_map_max(o->files, o->nfiles, &m, err, sizeof err))
        swe_cli_die(1, "cannot read %s", err);
    const double r = o->rel ? swe_cli_number("--rel", o->rel) : 1;
    printf("%.6g %.6g\n", m, r * (o->exact ? m : swe_post_round(m, 6)));
    return 0;
}

/* ---- cloud-log and balance: the mass balance over the whole run ------------------------ */
static void read_log(const post_opts *o, swe_post_log *l)
{
    need(o->cloud, "--cloud", "balance");
    need(o->log, "--log", "balance");
    check(swe_post_log_read(o->log, o->cloud, l, err, sizeof err), err);
}

static int cloud_log(const post_opts *o)
{
    swe_post_log l;
    read_log(o, &l);
    printf("%ld %.6g %s\n", l.parcels, l.parcels ? l.injected / (double)l.parcels : 0,
           l.split ? "yes" : "no");
    return 0;
}

static int balance(const post_opts *o)
{
    swe_post_log l;
    read_log(o, &l);
    char pat[512];
    snprintf(pat, sizeof pat, "postProcessing/lagrangian/%s/escaped/*/*.post", o->cloud);
    glob_t g = {0};
    glob(pat, 0, NULL, &g);
    double e, logged = 0, field = 0;
    check(swe_post_post_mass((const char *const *)g.gl_pathv, (int)g.gl_pathc, &e, err,
                             sizeof err), err);
    globfree(&g);
    e = swe_post_round(e, 10);
    for (int i = 0; i < 6; i++) {
        double c[5];
        counts(o->cloud, patches[i], "last", c);
        logged = swe_post_round(logged + c[4], 12);
        field = swe_post_round(field + integral(o->cloud, patches[i], "last"), 12);
    }
    const double i = l.injected, a = l.airborne;
    printf("gate = %s\ncloud = %s\ninjected = %.8g\nescaped = %.8g\nairborne = %.8g\n",
           o->gate ? o->gate : "off", o->cloud, i, e, a);
    printf("deposited_logged = %.8g\ndeposited_field = %.8g\nbalance = %.8g\n", logged, field,
           i - e - a);
    printf("err_field_vs_logged = %.3e\n", i > 0 ? (field - logged) / i : 1);
    printf("err_logged_vs_balance = %.3e\n", i > 0 ? (logged - (i - e - a)) / i : 1);
    printf("parcels_injected = %ld\nparcel_mass = %.6g\nsplit = %s\n", l.parcels,
           l.parcels ? i / (double)l.parcels : 0, l.split ? "yes" : "no");
    return 0;
}

/* ---- rear-table: rear_statistics.md -------------------------------------------------- */
static int by_collation(const void *a, const void *b)
{
    return strcoll(*(char *const *)a, *(char *const *)b);
}

/* the rear face's records in g, sorted as ls sorts them: the wall model's stick
   records (1) when the cloud wrote them, else every impact, bounces included (0) */
static int rear_records(const char *cloud, glob_t *g)
{
    char pat[1024];
    snprintf(pat, sizeof pat, "postProcessing/lagrangian/%s/snowWallSticks/*/rear.post", cloud);
    if (!glob(pat, 0, NULL, g))
        return 1;
    globfree(g);
    snprintf(pat, sizeof pat, "postProcessing/lagrangian/%s/rearImpacts/*/rear.post", cloud);
    glob(pat, 0, NULL, g);
    snprintf(pat, sizeof pat, "postProcessing/lagrangian/%s/nearWall/*/rear.post", cloud);
    glob(pat, g->gl_pathc ? GLOB_APPEND : 0, NULL, g);
    if (g->gl_pathc)
        qsort(g->gl_pathv, g->gl_pathc, sizeof *g->gl_pathv, by_collation);
    return 0;
}

static int rear_table(const post_opts *o)
{
    need(o->cloud, "--cloud", "rear-table");
    need(o->file, "--file", "rear-table");
    char t[3][64], label[256];
    if (o->window && split_times(o->window, t) != 3)
        die(2, "rear-table: --window '%s' is not T0,TH,T1", o->window);
    glob_t g = {0};
    const int sticks = rear_records(o->cloud, &g);
    puts("| period | left side | right side | centre | edges | whole face |\n|---|---|---|---|---|---|");
    fflush(stdout);
    if (!g.gl_pathc)
        die(1, "no rear-face records postProcessing/lagrangian/%s/snowWallSticks/*/rear.post or "
               "rearImpacts/*/rear.post", o->cloud);
    swe_options s = {0};
    s.outline = o->file;
    s.kind = sticks ? "sticks" : "impacts";
    s.files = (const char **)g.gl_pathv;
    s.nfiles = (int)g.gl_pathc;
    const char *rows[3][3] = {{label, t[0], t[2]}, {"first half", t[0], t[1]},
                              {"second half", t[1], t[2]}};
    snprintf(label, sizeof label, "window %s .. %s s", t[0], t[2]);
    for (int k = 0; k < (o->window ? 3 : 1); k++) {
        s.label = o->window ? rows[k][0] : "whole run";
        s.from = o->window ? rows[k][1] : "-1";
        s.to = o->window ? rows[k][2] : "1e30";
        swe_cmd_rear_stats(&s);
        fflush(stdout);
    }
    globfree(&g);
    return 0;
}

/* ---- rear-records: the window's records of the rear face, for the blocks ------------ */
static int rear_records_cmd(const post_opts *o)
{
    need(o->cloud, "--cloud", "rear-records");
    char t[3][64];
    if (o->window && split_times(o->window, t) != 3)
        die(2, "rear-records: --window '%s' is not T0,TH,T1", o->window);
    glob_t g = {0};
    rear_records(o->cloud, &g);
    if (!g.gl_pathc)
        die(1, "no rear-face records postProcessing/lagrangian/%s/snowWallSticks/*/rear.post or "
               "rearImpacts/*/rear.post", o->cloud);
    swe_options s = {0};
    s.files = (const char **)g.gl_pathv;
    s.nfiles = (int)g.gl_pathc;
    s.from = o->window ? t[0] : "-1";
    s.to = o->window ? t[2] : "1e30";
    const int rc = swe_cmd_rear_records(&s);
    globfree(&g);
    return rc;
}

/* ---- convergence: convergence.md up to the flow's forces --------------------------- */
/* the solver's time steps over the window T0 < t <= T1 */
static void flow_steps(const char *log, double a, double b)
{
    FILE *f = swe_cli_open(log);
    double cm = 0, cx = 0, dt = 0, sdt = 0, scm = 0, mx = 0, v;
    long n = 0;
    static char line[16384];
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "Courant Number mean: %lf max: %lf", &cm, &cx) >= 1)
            continue;
        if (!strncmp(line, "deltaT = ", 9))
            dt = strtod(line + 9, NULL);
        else if (!strncmp(line, "Time = ", 7) && (v = strtod(line + 7, NULL)) > a + 1e-12 &&
                 v <= b + 1e-12) {
            n++;
            sdt += dt;
            mx = cx > mx ? cx : mx;
            scm += cm;
        }
    }
    fclose(f);
    if (n)
        printf("Time steps in the window: %ld, mean deltaT %.3g s, mean Courant number %.3g (cell "
               "mean), largest %.3g.\n", n, sdt / n, scm / n, mx);
}

/* the replay library of the solver log (its "Replay: snapshots every I s from A s
   over P s" line): 1 with A and P, else 0 */
static int replay_library(const char *log, double *a, double *p)
{
    FILE *f = fopen(log, "r");
    if (!f)
        return 0;
    static char line[16384];
    int found = 0;
    double iv;
    while (!found && fgets(line, sizeof line, f))
        found = sscanf(line, "Replay: snapshots every %lf s from %lf s over %lf s", &iv, a, p) == 3 &&
                *p > 0;
    fclose(f);
    return found;
}

/* the y+ line of convergence.md: per patch (in the order of the table) min / max /
   mean of the last row of the latest postProcessing/yPlus/<time>/yPlus.dat; nothing
   when there is none */
static void yplus_line(void)
{
    glob_t g = {0};
    if (glob("postProcessing/yPlus/*/yPlus.dat", 0, NULL, &g) || !g.gl_pathc) {
        globfree(&g);
        return;
    }
    const size_t skip = strlen("postProcessing/yPlus/"); /* to the time folder's name */
    size_t last = 0;
    for (size_t i = 1; i < g.gl_pathc; i++)
        if (strtod(g.gl_pathv[i] + skip, NULL) >= strtod(g.gl_pathv[last] + skip, NULL))
            last = i;
    FILE *f = fopen(g.gl_pathv[last], "r");
    globfree(&g);
    if (!f)
        return;
    enum { MAXP = 64 };
    static char patch[MAXP][128], row[MAXP][256];
    char line[4096], t[128] = "";
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        char *w[5], *save = NULL;
        int k = 0;
        if (line[0] == '#')
            continue;
        for (char *p = strtok_r(line, " \t\r\n", &save); p && k < 5; p = strtok_r(NULL, " \t\r\n", &save))
            w[k++] = p;
        if (k < 5)
            continue;
        int i = 0;
        while (i < n && strcmp(patch[i], w[1]))
            i++;
        if (i == n && n < MAXP)
            snprintf(patch[n++], sizeof patch[0], "%s", w[1]);
        if (i < n)
            snprintf(row[i], sizeof row[0], "%s %.3g / %.3g / %.3g", w[1], strtod(w[2], NULL),
                     strtod(w[3], NULL), strtod(w[4], NULL));
        snprintf(t, sizeof t, "%s", w[0]);
    }
    fclose(f);
    printf("y+ of the first cells at t = %s s (min / max / mean):", t);
    for (int i = 0; i < n; i++)
        printf(" %s;", row[i]);
    printf("\n");
}

static int convergence(const post_opts *o)
{
    need(o->window, "--window", "convergence");
    need(o->file, "--file", "convergence");
    glob_t g = {0};
    const int sticks = rear_records(o->cloud, &g);
    globfree(&g);
    char t[3][64];
    if (split_times(o->window, t) != 3)
        die(2, "convergence: --window '%s' is not T0,TH,T1", o->window);
    swe_post_log l;
    read_log(o, &l);
    printf("# Convergence of the sampling window (%s, cloud %s)\n\nWindow %s .. %s s, halves %s .. "
           "%s s and %s .. %s s; every deposit is scaled\nto 30 min (a half x2). Parcel mass %.6g "
           "kg (mean of the %ld injected).\n\n## Per patch\n\n| patch | impacts (window) | sticks "
           "(window) | deposit window [kg] | first half x2 [kg] | second half x2 [kg] | halves "
           "differ by | Poisson error of the window (1/sqrt(sticks), equal-mass parcels) |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|\n", o->gate ? o->gate : "off", o->cloud, t[0],
           t[2], t[0], t[1], t[1], t[2], l.parcels ? l.injected / (double)l.parcels : 0, l.parcels);
    for (int i = 0; i < 6; i++) {
        double c0[5], ch[5], c1[5];
        counts(o->cloud, patches[i], t[0], c0);
        counts(o->cloud, patches[i], t[1], ch);
        counts(o->cloud, patches[i], t[2], c1);
        swe_post_halves_t h;
        swe_post_halves(c0, ch, c1, &h);
        char dif[32] = "-", e[32] = "n/a (split)";
        const double d = swe_post_halves_diff(&h), p = swe_post_poisson(h.sticks);
        if (!isnan(d))
            snprintf(dif, sizeof dif, "%.0f %%", d);
        if (!l.split && isinf(p))
            snprintf(e, sizeof e, "inf");
        else if (!l.split)
            snprintf(e, sizeof e, "%.1f %%", p);
        printf("| %s | %ld | %ld | %.4g | %.4g | %.4g | %s | %s |\n", patches[i], (long)h.impacts,
               (long)h.sticks, h.window, h.half1, h.half2, dif, e);
    }
    printf("\n## Rear-face statistics\n\n%s\nthe independent injected parcels they come from "
           "(copies made by -split share\ntheir origin), their mass (30-min scale) and the "
           "effective sample size\nn_eff = (sum W)^2 / sum W^2 over the origins' masses W, with "
           "the relative\nstatistical error 1/sqrt(n_eff) of the region's mass.\n\n",
           sticks
               ? "Every parcel that stuck on the rear face (the wall model's stick records, "
                 "`snowWallSticks`), per region: sticks,"
               : "Every parcel impact on the rear face (`rearImpacts` records, and the parcels the "
                 "sublayer closure of snowNearWall brought there; bounces included: the cloud "
                 "wrote no stick records), per region: impacts,");
    FILE *f = swe_cli_open(o->file);
    char line[4096];
    while (fgets(line, sizeof line, f))
        fputs(line, stdout);
    fclose(f);
    printf("\n## Flow over the window\n\n");
    flow_steps(o->log, strtod(t[0], NULL), strtod(t[2], NULL));
    /* mean drag and the side force's and lift's dominant frequency; the probes' Ux */
    char w[160];
    const char *fc = "postProcessing/forceCoeffs/0/coefficient.dat", *pu = "postProcessing/wakeProbes/0/U";
    snprintf(w, sizeof w, "%s,%s", t[0], t[2]);
    swe_options s = {0};
    s.window = w;
    s.nfiles = 1;
    struct stat st;
    fflush(stdout);
    if (!stat(fc, &st) && S_ISREG(st.st_mode)) {
        s.files = &fc;
        swe_cmd_forces(&s);
        fflush(stdout);
        /* a played-back flow: its spectrum over the solved library too */
        double ra, rp;
        if (replay_library(o->log, &ra, &rp)) {
            swe_forces_solved(fc, ra, ra + rp, rp);
            fflush(stdout);
        }
    }
    if (!stat(pu, &st) && S_ISREG(st.st_mode)) {
        s.files = &pu;
        swe_cmd_probes(&s);
        fflush(stdout);
    }
    yplus_line();
    if (o->threshold) /* the head of the regions table (rows: snowphoto regions) */
        printf("\n## Rear-face regions\n\nThreshold %s kg/m2 (10 %% of the window map's maximum) for "
               "all three rows; each\ncell: holds snow (bold) when >= 30 %% of the region's faces "
               "reach it, that fraction\nand the region's mean deposit (its statistics: \"Rear-face "
               "statistics\" above).\n\n| map | left side | right side | centre | edges | threshold "
               "[kg/m2] |\n|---|---|---|---|---|---:|\n",
               o->threshold);
    return 0;
}

/* ---- capture: a row of the capture table per diameter ---------------------------------- */
/* the value of "KEY = VALUE" in a key = value file; 0 when absent */
static double key_value(const char *path, const char *key)
{
    FILE *f = swe_cli_open(path);
    char line[1024], k[256], v[256];
    double r = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%255s %*s %255s", k, v) == 2 && !strcmp(k, key))
            r = strtod(v, NULL);
    fclose(f);
    return r;
}

/* a per-patch CSV (deposit_per_patch.csv) */
typedef struct {
    int n;
    char patch[64][64], dep[64][64], fields[64][16][64];
    int nf[64];
} patch_csv;

static void read_csv(const char *path, patch_csv *t)
{
    FILE *f = swe_cli_open(path);
    char line[4096];
    t->n = 0;
    for (int ln = 0; fgets(line, sizeof line, f) && t->n < 64; ln++) {
        if (!ln)
            continue;
        line[strcspn(line, "\r\n")] = 0;
        int k = 0;
        for (char *s = line, *c; k < 16; s = c + 1) {
            c = strchr(s, ',');
            snprintf(t->fields[t->n][k++], 64, "%.*s", c ? (int)(c - s) : (int)strlen(s), s);
            if (!c)
                break;
        }
        t->nf[t->n] = k;
        memcpy(t->patch[t->n], t->fields[t->n][0], sizeof t->patch[t->n]);
        t->n++;
    }
    fclose(f);
}

/* field k (0-based) of patch p; "" when absent */
static const char *csv_get(const patch_csv *t, const char *p, int k)
{
    for (int i = 0; i < t->n; i++)
        if (!strcmp(t->patch[i], p))
            return k < t->nf[i] ? t->fields[i][k] : "";
    return NULL;
}

static double csv_num(const patch_csv *t, const char *p, int k)
{
    const char *s = csv_get(t, p, k);
    return s ? strtod(s, NULL) : 0;
}

static int by_number(const void *a, const void *b)
{
    return *(const int *)a - *(const int *)b;
}

static int capture(const post_opts *o)
{
    need(o->results, "--results", "capture");
    const double f = o->sampled ? swe_cli_number("--sampled", o->sampled) : 1;
    static patch_csv t;
    char pat[4096], p[4096];
    snprintf(pat, sizeof pat, "%s/d*um", o->results);
    glob_t g = {0};
    glob(pat, 0, NULL, &g);
    int um[256], n = 0;
    for (size_t i = 0; i < g.gl_pathc && n < 256; i++) {
        const char *s = strrchr(g.gl_pathv[i], '/') + 2;
        char *end;
        const long v = strtol(s, &end, 10);
        if (end > s && !strcmp(end, "um"))
            um[n++] = (int)v;
    }
    globfree(&g);
    if (!n)
        die(1, "no %s/d<N>um results (run Allrun -sizes LIST)", o->results);
    qsort(um, (size_t)n, sizeof *um, by_number);
    printf("# Wall impacts by particle diameter (gate setting %s%s%s)\n\n", o->gate ? o->gate : "off",
           o->dispersion ? ", dispersion " : "", o->dispersion ? o->dispersion : "");
    puts("Each diameter is its own cloud: the spray of constant/kinematicCloudProperties with\n"
         "every particle of that size, in the same transient flow. Impacts (parcels) over the\n"
         "sampling window; rear share = mass stuck on the rear face over the window per mass\n"
         "sprayed during it, in parts per million.\n\n"
         "| d [um] | Stokes number of the wake | parcels injected | nose | top | bottom | sides | "
         "rear | rear share [ppm] |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (int i = 0; i < n; i++) {
        char bal[4096];
        snprintf(bal, sizeof bal, "%s/d%dum/mass_balance.txt", o->results, um[i]);
        snprintf(p, sizeof p, "%s/d%dum/deposit_per_patch.csv", o->results, um[i]);
        FILE *a = fopen(bal, "r"), *b = fopen(p, "r");
        if (a)
            fclose(a);
        if (b)
            fclose(b);
        if (!a || !b) {
            fflush(stdout);
            die(1, "missing results in %s/d%dum", o->results, um[i]);
        }
        const double np = key_value(bal, "parcels_injected"), inj = key_value(bal, "injected");
        read_csv(p, &t);
        const double share = inj * f > 0 ? 1e6 * csv_num(&t, "rear", 2) / (inj * f) : 0;
        printf("| %d | %.3g | %ld | %ld | %ld | %ld | %ld | %ld | %.3g |\n", um[i],
               swe_post_stokes(um[i]), (long)np, (long)csv_num(&t, "nose", 4),
               (long)csv_num(&t, "top", 4), (long)csv_num(&t, "bottom", 4),
               (long)(csv_num(&t, "sideYneg", 4) + csv_num(&t, "sideYpos", 4)),
               (long)csv_num(&t, "rear", 4), share);
    }
    return 0;
}

/* ---- fill: the age of the rear-face impacts -------------------------------------------- */
static int fill(const post_opts *o)
{
    char t[3][64];
    need(o->soi, "--soi", "fill");
    need(o->window, "--window", "fill");
    if (split_times(o->window, t) != 2)
        die(2, "fill: --window '%s' is not T0,T1", o->window);
    const double soi = swe_cli_number("--soi", o->soi), t0 = swe_cli_number("--window", t[0]),
                 t1 = swe_cli_number("--window", t[1]),
                 lev = o->level ? swe_cli_number("--level", o->level) : 0.95;
    if (!(t1 > t0))
        die(2, "fill: --window '%s': T1 must be after T0", o->window);
    if (!(lev > 0 && lev < 1))
        die(2, "fill: --level '%s' is not in (0, 1)", o->level);
    size_t n = 0, cap = 1024;
    swe_post_rec *r = malloc(cap * sizeof *r);
    static char line[16384];
    for (int k = 0; r && k < o->nfiles; k++) {
        FILE *f = swe_cli_open(o->files[k]);
        int ct = -1, cd = -1, cn = -1, cr = -1, ca = -1, head = 0;
        while (fgets(line, sizeof line, f)) {
            char *fl[512];
            int nf = 0;
            swe_cli_strip_parens(line);
            const int is_head = line[0] == '#';
            for (char *s = strtok(line + is_head, " \t\r\n"); s && nf < 512; s = strtok(NULL, " \t\r\n"))
                fl[nf++] = s;
            if (is_head) {
                for (int i = 0; !head && i < nf; i++) {
                    ct = strcmp(fl[i], "Time") ? ct : i;
                    cd = strcmp(fl[i], "d") ? cd : i;
                    cn = strcmp(fl[i], "nParticle") ? cn : i;
                    cr = strcmp(fl[i], "rho") ? cr : i;
                    ca = strcmp(fl[i], "age") ? ca : i;
                }
                head = 1;
                continue;
            }
            if (ct < 0 || cd < 0 || cn < 0 || cr < 0 || ca < 0 || ct >= nf || cd >= nf ||
                cn >= nf || cr >= nf || ca >= nf)
                die(2, "%s: a record without Time, d, nParticle, rho and age", o->files[k]);
            if (n == cap && !(r = realloc(r, (cap *= 2) * sizeof *r)))
                break;
            const double d = strtod(fl[cd], NULL);
            r[n].t = strtod(fl[ct], NULL);
            r[n].age = strtod(fl[ca], NULL);
            r[n++].mass = strtod(fl[cn], NULL) * strtod(fl[cr], NULL) * SWE_POST_PI / 6 * d * d * d;
        }
        fclose(f);
    }
    swe_post_fill_t s;
    if (!r || swe_post_fill(r, n, soi, t0, t1, lev, &s))
        die(1, "out of memory");
    free(r);
    const char *lab = o->label ? o->label : (o->cloud ? o->cloud : "");
    if (!s.n)
        printf("| %s | 0 | 0 | - | - | - | - | - | - |\n", lab);
    else
        printf("| %s | %ld | %.3g | %.3g | %.3g | %.3g | %.2f | %.2f | %.2f |\n", lab, s.n, s.mass,
               s.a50, s.aF, s.amax, s.fill, s.fill1, s.fill2);
    return 0;
}

/* ---- cost: error against run time per sampling design ---------------------------------- */
/* the number after "+- " in a table cell ("" when none) */
static void pm_value(const char *cell, char *out, size_t n)
{
    out[0] = 0;
    const char *p = NULL;
    for (const char *q = strstr(cell, "+- "); q; q = strstr(q + 1, "+- "))
        p = q;
    if (!p)
        return;
    for (p += 2; *p == ' '; p++)
        ;
    size_t len = strcspn(p, "%");
    while (len && p[len - 1] == ' ')
        len--;
    snprintf(out, n, "%.*s", (int)len, p);
}

static int cell_split(char *line, char **c, int max)
{
    int n = 0;
    for (char *s = line; n < max;) {
        c[n++] = s;
        char *b = strchr(s, '|');
        if (!b)
            break;
        *b = 0;
        s = b + 1;
    }
    return n;
}

static int cost(const post_opts *o)
{
    need(o->results, "--results", "cost");
    need(o->log, "--log", "cost");
    need(o->gate, "--gate", "cost");
    need(o->mvd, "--mvd", "cost");
    static char line[16384], times[16384];
    FILE *f = swe_cli_open(o->log);
    times[0] = 0;
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, "Wall time [s]", 13))
            memcpy(times, line, sizeof times);
    fclose(f);
    char *colon = strstr(times, ": ");
    char flow[64] = "", main_t[64] = "";
    double classes = 0;
    for (char *s = colon ? strtok(colon + 2, ",\n") : NULL; s; s = strtok(NULL, ",\n")) {
        char name[256], v[64], extra[8];
        if (sscanf(s, "%255s %63s %7s", name, v, extra) != 2)
            continue;
        if (!strcmp(name, "flow"))
            snprintf(flow, sizeof flow, "%s", v);
        else if (!strcmp(name, "kinematicCloud"))
            snprintf(main_t, sizeof main_t, "%s", v);
        else if (is_class(name))
            classes += strtod(v, NULL);
    }
    printf("design,wall_s,face,left,right,centre,edges\nflow,%s,,,,,\n", flow);
    char p[4096];
    snprintf(p, sizeof p, "%s/%s/mass_balance.txt", o->results, o->gate);
    f = swe_cli_open(p);
    const char *design = "plain";
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, "split = yes", 11))
            design = "splitting";
    fclose(f);
    snprintf(p, sizeof p, "%s/%s/rear_statistics.md", o->results, o->gate);
    f = swe_cli_open(p);
    while (fgets(line, sizeof line, f)) {
        char *c[16], e[8][64];
        line[strcspn(line, "\n")] = 0;
        if (strncmp(line, "| window", 8))
            continue;
        const int n = cell_split(line, c, 16);
        for (int i = 2; i <= 6; i++)
            if (i < n)
                pm_value(c[i], e[i], sizeof e[i]);
            else
                e[i][0] = 0;
        printf("%s,%s,%s,%s,%s,%s,%s\n", design, main_t, e[6], e[2], e[3], e[4], e[5]);
        break;
    }
    fclose(f);
    snprintf(p, sizeof p, "%s/compose/mvd%s/regions.md", o->results, o->mvd);
    if (!(f = fopen(p, "r")))
        return 0;
    static const char *reg[5] = {"whole face", "left side", "right side", "centre", "edges"};
    char E[5][64] = {"", "", "", "", ""};
    while (fgets(line, sizeof line, f) && strncmp(line, "## ", 3)) {
        char *c[16];
        line[strcspn(line, "\n")] = 0;
        const int n = cell_split(line, c, 16);
        for (int k = 0; n > 3 && k < 5; k++) {
            char want[32];
            snprintf(want, sizeof want, " %s ", reg[k]);
            if (strcmp(c[1], want))
                continue;
            int m = 0;
            for (const char *s = c[3]; *s; s++)
                if (*s != ' ' && *s != '%' && m < 63)
                    E[k][m++] = *s;
            E[k][m] = 0;
            if (!strcmp(E[k], "-"))
                E[k][0] = 0;
        }
    }
    fclose(f);
    printf("stratified,%.6g,%s,%s,%s,%s,%s\n", classes, E[0], E[1], E[2], E[3], E[4]);
    return 0;
}

/* ---- patch-columns: per-patch tables side by side -------------------------------------- */
static void by_reason(const patch_csv *t, const char *p, char *out, size_t n)
{
    int i = 0;
    while (i < t->n && strcmp(t->patch[i], p))
        i++;
    if (i == t->n) {
        out[0] = 0;
        return;
    }
    if (t->nf[i] < 14 || !strcmp(t->fields[i][9], "-"))
        snprintf(out, n, "-");
    else
        snprintf(out, n, "%s / %s / %s / %s / %s", t->fields[i][9], t->fields[i][10],
                 t->fields[i][11], t->fields[i][12], t->fields[i][13]);
}

/* rows per patch of the first table: per table its deposit and sticks / impacts,
   or its counts by reason (nothing for a table without the patch) */
static void columns(const patch_csv *t, int n, int with_reasons)
{
    for (int i = 0; i < t[0].n; i++) {
        const char *p = t[0].patch[i];
        printf("| %s |", p);
        for (int j = 0; j < n; j++) {
            char r[512];
            by_reason(&t[j], p, r, sizeof r);
            if (!csv_get(&t[j], p, 0))
                continue;
            if (with_reasons)
                printf(" %s |", r);
            else
                printf(" %.4g | %ld / %ld |", csv_num(&t[j], p, 2), (long)csv_num(&t[j], p, 5),
                       (long)csv_num(&t[j], p, 4));
        }
        putchar('\n');
    }
}

/* gates_per_patch.md of the gate comparison */
static int gates(const post_opts *o)
{
    need(o->results, "--results", "gates");
    static const char *g[4] = {"off", "tangential", "shear", "regime"};
    static patch_csv t[4];
    for (int k = 0; k < 4; k++) {
        char p[4096];
        snprintf(p, sizeof p, "%s/%s/deposit_per_patch.csv", o->results, g[k]);
        read_csv(p, &t[k]);
    }
    printf("| patch |");
    for (int k = 0; k < 4; k++)
        printf(" %s: deposit [kg] | sticks / impacts |", g[k]);
    printf("\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    columns(t, 4, 0);
    puts("\nDeposit: area integral of the snowDeposit field of each gate setting's cloud (the\n"
         "same spray in the same flow). regime: the kernel's d_crit(v_n, v_t) "
         "(constant/gates/regime).\n\nWhich rule decided, per patch and gate setting (the wall "
         "model's counts by reason:\nstuck / bounced by the d_crit criterion / by the tangential "
         "gate / ripped off by the\nshear gate / bounced by the probability draw; they add up to "
         "the impacts):\n\n| patch | off | tangential | shear | regime |\n|---|---:|---:|---:|---:|");
    columns(t, 4, 1);
    return 0;
}

/* ---- variant-rows: the main cloud against a variant ------------------------------------ */
static void covered(const char *log, const char *p, char *out, size_t n)
{
    FILE *f = fopen(log, "r");
    snprintf(out, n, f ? "" : "-");
    if (!f)
        return;
    char key[256], line[4096];
    snprintf(key, sizeof key, "snowWall: patch %s: faces covered", p);
    long a, b, c;
    while (fgets(line, sizeof line, f)) {
        const char *s = strstr(line, key);
        if (!s)
            continue;
        out[0] = 0;
        const char *q = NULL;
        for (const char *x = strstr(line, "faces covered "); x; x = strstr(x + 1, "faces covered "))
            q = x;
        if (sscanf(q, "faces covered %ld, partly covered %ld, of %ld", &a, &b, &c) == 3)
            snprintf(out, n, "%ld / %ld of %ld", a, b, c);
    }
    fclose(f);
}

static const char *const variant_text[3][4] = {
    {"feedback", "Build-up feedback",
     "| patch | without: deposit [kg] | sticks / impacts | with: deposit [kg] | sticks / impacts | "
     "deposit change | faces covered / partly (end) |\n|---|---:|---:|---:|---:|---:|---|",
     "With the feedback a face decides with the snow-on-snow regime (ice on ice,\n"
     "regime/configs/ice-on-ice.conf) once its deposit reaches one monolayer\n"
     "(constant/gates/buildUp), blending the stick probabilities below that."},
    {"rebound",
     "Rebound: the kernel's tables (the default, regime.coeffs) against the earlier Thornton e_p "
     "with the tangential velocity kept (rebound classic)",
     "| patch | kernel: deposit [kg] | sticks / impacts | by reason | classic: deposit [kg] | "
     "sticks / impacts | by reason | deposit change |\n|---|---:|---:|---:|---:|---:|---:|---:|",
     "By reason: stuck / bounced by the d_crit criterion / by the tangential gate / ripped\n"
     "off by the shear gate / bounced by the probability draw (they add up to the impacts).\n"
     "Both clouds make the same stick decision at an impact; what differs is where a\n"
     "bounced parcel goes next: the kernel's e_n(d, v_n) and, with its oblique table,\n"
     "e_t(d, v_n, v_t) (friction and rolling), against e_p(V_y/v_n) with v_t kept whole."},
    {"rough", "Rough wall (the stick probability of constant/regime-rough.coeffs on every face)",
     "| patch | flat: deposit [kg] | sticks / impacts | rough: deposit [kg] | sticks / impacts | "
     "deposit change |\n|---|---:|---:|---:|---:|---:|",
     "On the rough wall (constant/roughWall: a lattice of 1 um ABS asperities) an impact\n"
     "sticks with the probability of the map (u < p_stick, one uniform number per impact);\n"
     "outside the map's range the p = 0.5 interface decides (doc/wallmodel.md)."}};

/* the variant's table against the main cloud, or (--part notes) its closing notes */
static int variant(const post_opts *o)
{
    need(o->variant, "--variant", "variant");
    need(o->results, "--results", "variant");
    need(o->gate, "--gate", "variant");
    int kv = 0;
    while (kv < 3 && strcmp(o->variant, variant_text[kv][0]))
        kv++;
    if (kv == 3)
        die(2, "--variant must be feedback, rough or rebound, got '%s'", o->variant);
    if (o->part && !strcmp(o->part, "notes")) {
        puts(variant_text[kv][3]);
        return 0;
    }
    if (o->part && !strcmp(o->part, "regions")) { /* the head of the regions table */
        need(o->threshold, "--threshold", "variant");
        if (strcmp(o->threshold, "none"))
            printf("Rear-face regions (threshold %s kg/m2 = %s x the larger maximum):\n", o->threshold,
                   o->rel ? o->rel : "0.1");
        else
            printf("Rear-face regions (no deposit on the rear face in either cloud):\n");
        printf("\n| cloud | left side | right side | centre | edges | threshold [kg/m2] |\n"
               "|---|---|---|---|---|---:|\n");
        return 0;
    }
    static patch_csv m, v;
    char p[4096];
    snprintf(p, sizeof p, "%s/%s/deposit_per_patch.csv", o->results, o->gate);
    read_csv(p, &m);
    snprintf(p, sizeof p, "%s/%s/deposit_per_patch.csv", o->results, o->variant);
    read_csv(p, &v);
    printf("%s, gate setting '%s' (the same spray in the same flow; deposits over\nthe sampling "
           "window, scaled to 30 min):\n\n%s\n", variant_text[kv][1], o->gate, variant_text[kv][2]);
    for (int i = 0; i < m.n; i++) {
        const char *p = m.patch[i];
        /* deposits to 4 digits from the CSV's decimal text, in extended precision */
        const long double x = strtold(m.fields[i][2], NULL),
                          y = csv_get(&v, p, 2) ? strtold(csv_get(&v, p, 2), NULL) : 0;
        const long sx = atol(m.fields[i][5]), ix = atol(m.fields[i][4]),
                   sy = (long)csv_num(&v, p, 5), iy = (long)csv_num(&v, p, 4);
        char ch[64] = "-", ra[512], rb[512], cov[256];
        const double xd = strtod(m.fields[i][2], NULL), yd = csv_num(&v, p, 2);
        if (xd > 0)
            snprintf(ch, sizeof ch, "%+.1f %%", 100 * (yd / xd - 1));
        if (kv == 0) {
            covered(o->log ? o->log : "log.pimpleUncoupledKinematicParcelFoam", p, cov, sizeof cov);
            printf("| %s | %.4Lg | %ld / %ld | %.4Lg | %ld / %ld | %s | %s |\n", p, x, sx, ix, y, sy,
                   iy, ch, cov);
        } else if (kv == 1) {
            by_reason(&m, p, ra, sizeof ra);
            by_reason(&v, p, rb, sizeof rb);
            printf("| %s | %.4Lg | %ld / %ld | %s | %.4Lg | %ld / %ld | %s | %s |\n", p, x, sx, ix,
                   ra, y, sy, iy, rb, ch);
        } else
            printf("| %s | %.4Lg | %ld / %ld | %.4Lg | %ld / %ld | %s |\n", p, x, sx, ix, y, sy, iy,
                   ch);
    }
    return 0;
}

/* ---- dispersion: the dispersion treatments side by side ------------------------------- */
/* the words of a blank-separated list */
static int words(const char *s, char w[][64], int max)
{
    int n = 0;
    for (const char *p = s; *p && n < max;) {
        p += strspn(p, " \t");
        const size_t len = strcspn(p, " \t");
        if (len)
            snprintf(w[n++], 64, "%.*s", (int)(len < 63 ? len : 63), p);
        p += len;
    }
    return n;
}

static void missing_file(const char *path)
{
    FILE *f = fopen(path, "r");
    if (f) {
        fclose(f);
        return;
    }
    fflush(stdout);
    die(1, "missing %s", path);
}

static int dispersion(const post_opts *o)
{
    need(o->results, "--results", "dispersion");
    need(o->main, "--main", "dispersion");
    char tr[17][64], pat[4096], path[17][4096];
    const int n = 1 + words(o->others ? o->others : "", tr + 1, 16);
    words(o->main, tr, 1);
    snprintf(pat, sizeof pat, "%s/*/deposit_per_patch.csv", o->results);
    glob_t g = {0};
    glob(pat, 0, NULL, &g);
    path[0][0] = 0;
    for (size_t i = 0; i < g.gl_pathc && !path[0][0]; i++) {
        const char *p = g.gl_pathv[i];
        if (!strstr(p, "/dispersion/") && !strstr(p, "/sizes") && !strstr(p, "/feedback/") &&
            !strstr(p, "/rough/"))
            snprintf(path[0], sizeof path[0], "%s", p);
    }
    globfree(&g);
    if (!path[0][0])
        die(1, "no main deposit_per_patch.csv in %s", o->results);
    printf("# Dispersion treatments side by side\n\nThe same spray, gate setting and flow; only the "
           "turbulent dispersion of the snow\ndiffers (Allrun -dispersion; doc/deposition.md). "
           "Over the sampling window:\ndeposit [kg / 30 min] and sticks / impacts per wedge patch."
           "\n\n| patch |");
    for (int k = 0; k < n; k++)
        printf(" %s: deposit | %s: sticks / impacts |", tr[k], tr[k]);
    printf("\n|---|");
    for (int k = 0; k < n; k++)
        printf("---:|---:|");
    putchar('\n');
    static patch_csv t[17];
    for (int k = 1; k < n; k++) {
        snprintf(path[k], sizeof path[k], "%s/dispersion/%s/deposit_per_patch.csv", o->results,
                 tr[k]);
        missing_file(path[k]);
    }
    for (int k = 0; k < n; k++)
        read_csv(path[k], &t[k]);
    for (int i = 0; i < t[0].n; i++) {
        printf("| %s |", t[0].patch[i]);
        for (int k = 0; k < n; k++)
            printf(" %.4g | %ld / %ld |", csv_num(&t[k], t[0].patch[i], 2),
                   (long)csv_num(&t[k], t[0].patch[i], 5), (long)csv_num(&t[k], t[0].patch[i], 4));
        putchar('\n');
    }
    char cap[17][4096];
    snprintf(cap[0], sizeof cap[0], "%s/capture.md", o->results);
    FILE *f = fopen(cap[0], "r");
    if (!f)
        return 0;
    fclose(f);
    printf("\nShare of the sprayed mass stuck on the rear face [ppm], per diameter (Allrun -sizes):"
           "\n\n| d [um] |");
    for (int k = 0; k < n; k++)
        printf(" %s |", tr[k]);
    printf("\n|---:|");
    for (int k = 0; k < n; k++)
        printf("---:|");
    putchar('\n');
    for (int k = 1; k < n; k++) {
        snprintf(cap[k], sizeof cap[k], "%s/capture_%s.md", o->results, tr[k]);
        missing_file(cap[k]);
    }
    /* the last cell of each diameter's row, per treatment, in the main table's order */
    static char v[17][256][128];
    int d[256], nd = 0;
    for (int k = 0; k < n; k++) {
        FILE *cf = swe_cli_open(cap[k]);
        char line[4096], *c[32];
        while (fgets(line, sizeof line, cf)) {
            line[strcspn(line, "\n")] = 0;
            const int nc = cell_split(line, c, 32);
            if (nc < 2 || strspn(c[1], " 0123456789") != strlen(c[1]) || !strpbrk(c[1], "0123456789"))
                continue;
            const int di = atoi(c[1]);
            int j = 0;
            while (j < nd && d[j] != di)
                j++;
            if (j == nd && k == 0 && nd < 256)
                d[nd++] = di;
            if (j < nd)
                snprintf(v[k][j], sizeof v[k][j], "%s", c[nc - 2]);
        }
        fclose(cf);
    }
    for (int j = 0; j < nd; j++) {
        char line[4096];
        int len = snprintf(line, sizeof line, "| %d |", d[j]);
        for (int k = 0; k < n && len < (int)sizeof line; k++)
            len += snprintf(line + len, sizeof line - (size_t)len, " %s |", v[k][j]);
        /* runs of blanks as one */
        char *w = line;
        for (const char *r = line; *r; r++)
            if (!(*r == ' ' && w > line && w[-1] == ' '))
                *w++ = *r;
        *w = 0;
        puts(line);
    }
    return 0;
}

int swe_cmd_post(int argc, char **argv)
{
    static const struct {
        const char *name;
        int (*run)(const post_opts *);
    } cmds[] = {{"rear-map", rear_map},       {"rear-maps", rear_maps},
                {"patch-table", patch_table},
                {"time-dir", time_dir},       {"deposit", deposit},
                {"map-max", map_max},
                {"cloud-log", cloud_log},     {"balance", balance},
                {"convergence", convergence}, {"rear-table", rear_table},
                {"rear-records", rear_records_cmd},
                {"capture", capture},         {"fill", fill},
                {"cost", cost},               {"gates", gates},
                {"dispersion", dispersion},
                {"variant", variant}};
    for (size_t k = 0; k < sizeof cmds / sizeof *cmds; k++)
        if (!strcmp(argv[1], cmds[k].name)) {
            setlocale(LC_COLLATE, ""); /* file lists sorted as ls sorts them */
            post_opts o = {0};
            parse(argc, argv, &o);
            const int rc = cmds[k].run(&o);
            free(o.files);
            return rc;
        }
    return -1;
}
