/* sbd_cmd_snow.c - snowbody snow-post: the snow on the Ahmed body from a run's
 * stick records and deposit tables (sbd_snow.h), written as one output set. */
#include "sbd_body.h"
#include "sbd_cmd.h"
#include "sbd_snow.h"
#include "swo_out.h"

#include <errno.h>
#include <glob.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define NPATCH 16
#define MINUTES_STEPS 30
#define MAP_NY 8    /* bins across the half rear face */
#define MAP_NZ 12   /* bins up the rear face */

typedef struct {
    char name[64];
    double area;        /* in the mesh (the half model) [m2] */
    double deposit;     /* the deposit field's integral at the last write [kg] */
    sbd_sticks st;
    sbd_window_stat w;
} patch;

typedef struct {
    const char *case_dir, *out, *flow, *ladder, *cloud;
    double fill, sample, build_up, speed, snow_seconds;
    long parcels, nozzles, processes;
    int half, force;
} options;

static swo_set *g_set;   /* freed by die() */
static int g_out_rc;     /* the exit status of the last failed out_open() */

static int die(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("snowbody: snow-post: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    swo_free(g_set);
    g_set = NULL;
    return code;
}

static int positive(const char *opt, const char *v, double lo, double hi, double *out)
{
    double x;
    if (!sbd_number(v, &x) || x < lo || x > hi)
        return die(2, "%s needs a number from %g to %g, got '%s'", opt, lo, hi, v);
    *out = x;
    return 0;
}

/* a whole number in [lo, hi] */
static int whole(const char *opt, const char *v, double lo, double hi, long *out)
{
    double x = 0;
    if (positive(opt, v, lo, hi, &x))
        return 2;
    if (x != floor(x))
        return die(2, "%s needs a whole number, got '%s'", opt, v);
    *out = (long)x;
    return 0;
}

/* "# Area : X" and the last row's value of one surfaceFieldValue table */
static int read_deposit_table(const char *path, double *area, double *last, char *err, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return snprintf(err, n, "%s: cannot read (%s)", path, strerror(errno)), -1;
    char line[1024];
    int have_area = 0, rows = 0;
    while (fgets(line, sizeof line, f)) {
        double t, v;
        if (sscanf(line, "# Area : %lf", area) == 1)
            have_area = 1;
        else if (line[0] != '#' && sscanf(line, "%lf %lf", &t, &v) == 2) {
            *last = v;
            rows++;
        }
    }
    fclose(f);
    if (!have_area || !(*area > 0) || !rows)
        return snprintf(err, n, "%s: no '# Area' header or no row", path), -1;
    return 0;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* the patches: postProcessing/deposit_<patch>/<time>/surfaceFieldValue*.dat (the last file in
 * name order, the latest restart's), their sticks from every write's <patch>.post */
static int load_patches(const options *o, patch *p, int *np)
{
    char pat[4096], err[1024];
    glob_t g;
    snprintf(pat, sizeof pat, "%s/postProcessing/deposit_*", o->case_dir);
    if (glob(pat, 0, NULL, &g) || g.gl_pathc == 0)
        return die(1, "%s: no deposit tables (postProcessing/deposit_<patch>): did the snow run finish?",
                   o->case_dir);
    if (g.gl_pathc > NPATCH) {
        globfree(&g);
        return die(1, "%s: more than %d deposit tables", o->case_dir, NPATCH);
    }
    *np = 0;
    for (size_t k = 0; k < g.gl_pathc; k++) {
        patch *q = &p[(*np)++];
        memset(q, 0, sizeof *q);
        const char *base = strrchr(g.gl_pathv[k], '/') + 1 + strlen("deposit_");
        snprintf(q->name, sizeof q->name, "%s", base);
        glob_t t;
        snprintf(pat, sizeof pat, "%s/*/surfaceFieldValue*.dat", g.gl_pathv[k]);
        if (glob(pat, 0, NULL, &t) || t.gl_pathc == 0) {
            globfree(&g);
            return die(1, "%s: no surfaceFieldValue table", pat);
        }
        int rc = read_deposit_table(t.gl_pathv[t.gl_pathc - 1], &q->area, &q->deposit, err, sizeof err);
        globfree(&t);
        if (rc) {
            globfree(&g);
            return die(1, "%s", err);
        }
        snprintf(pat, sizeof pat, "%s/postProcessing/lagrangian/%s/snowWallSticks/*/%s.post", o->case_dir, o->cloud,
                 q->name);
        int grc = glob(pat, 0, NULL, &t);
        if (grc == 0) {
            qsort(t.gl_pathv, t.gl_pathc, sizeof *t.gl_pathv, cmp_str);
            for (size_t i = 0; i < t.gl_pathc; i++)
                if (sbd_sticks_read(&q->st, t.gl_pathv[i], err, sizeof err)) {
                    globfree(&t);
                    globfree(&g);
                    return die(1, "%s", err);
                }
            globfree(&t);
        } else if (grc != GLOB_NOMATCH) {
            globfree(&g);
            return die(1, "%s: cannot list the stick records", pat);
        }
        if (q->deposit > 0 && q->st.n == 0) {
            globfree(&g);
            return die(1, "patch %s holds %g kg of deposit but no stick records (%s): is it among stickRecords?",
                       q->name, q->deposit, pat);
        }
    }
    globfree(&g);
    return 0;
}

static int find(const patch *p, int np, const char *name)
{
    for (int k = 0; k < np; k++)
        if (!strcmp(p[k].name, name))
            return k;
    return -1;
}

/* "key = value" of results/flow.txt */
static int flow_value(const char *path, const char *key, char *out, size_t n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[1024], k[256], v[512];
    int found = -1;
    while (found && fgets(line, sizeof line, f))
        if (sscanf(line, " %255s = %511s", k, v) == 2 && !strcmp(k, key) && strlen(v) < n) {
            memcpy(out, v, strlen(v) + 1);
            found = 0;
        }
    fclose(f);
    return found;
}

static FILE *out_open(const char *name)
{
    char err[1024];
    FILE *f = swo_open(g_set, name, err, sizeof err);
    if (!f)
        g_out_rc = die(swo_code(g_set), "%s", err);
    return f;
}

/* a gnuplot single-quoted string: a quote doubled */
static void gp_quoted(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', f);
        fputc(*s, f);
    }
    fputc('\'', f);
}

static int run_gnuplot(const char *script)
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        execlp("gnuplot", "gnuplot", script, (char *)NULL);
        _exit(127);
    }
    swo_signal_child(pid);
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            return -1;
    swo_signal_child(0);
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : -1;
}

/* the rear-face map's bins as rows "y SEP z SEP kg/m2" (bin centres, z upwards), with a
 * half model's mirror image first (from -W/2); returns the largest value */
typedef struct {
    const double *map;  /* row-major, ny bins along y per row */
    int ny;
    double y0, dy, z0, dz;
    int mirror;
} map_grid;

static double map_rows(FILE *f, char sep, const map_grid *g)
{
    double max = 0;
    for (int j = 0; j < MAP_NZ; j++)
        for (int side = g->mirror ? -1 : 1; side <= 1; side += 2)
            for (int i = 0; i < g->ny; i++) {
                const int ii = side < 0 ? g->ny - 1 - i : i;
                const double y = g->y0 + (ii + 0.5) * g->dy, v = g->map[j * g->ny + ii];
                fprintf(f, "%.5g%c%.5g%c%.6g\n", side < 0 ? -y : y, sep, g->z0 + (j + 0.5) * g->dz, sep, v);
                max = fmax(max, v);
            }
    return max;
}

static const char usage_snow[] =
"NAME\n"
"    snowbody snow-post - the snow on the Ahmed body from a run's stick records\n"
"\n"
"SYNOPSIS\n"
"    snowbody snow-post --case DIR --fill T --sample T --build-up S --out DIR\n"
"                       [--flow FILE] [--ladder CSV] [--half-model] [--cloud NAME]\n"
"                       [--speed U] [--parcels N] [--nozzles N] [--snow-seconds S]\n"
"                       [--processes N] [--force]\n"
"\n"
"DESCRIPTION\n"
"    Reads the snow run in DIR (tutorials/ahmed/snow): every body patch's deposit\n"
"    table (postProcessing/deposit_<patch>/*/surfaceFieldValue*.dat: the patch's\n"
"    area and the deposit field's integral) and its stick records\n"
"    (postProcessing/lagrangian/<cloud>/snowWallSticks/*/<patch>.post). The\n"
"    records must add up to the deposit field (relative difference below 1e-4,\n"
"    else exit 1): no stick is missed.\n"
"\n"
"    The sticks of the counting window (T_fill, T_fill + T_sample] carry the\n"
"    deposit of the exposure (--build-up seconds; the spray's mass was scaled\n"
"    so). For every patch, for the rear face (ahmed_rear and ahmed_sensor\n"
"    together) and for the sensor: the mass (whole body with --half-model: x 2),\n"
"    the mass per area, the relative sampling error (the sticks grouped by the\n"
"    injected parcel they descend from, whose copies under parcel splitting are\n"
"    correlated: sqrt(sum of each origin's mass squared) / mass) and the halves'\n"
"    z (a steady deposit gives |z| < 2 mostly). The sensor's and the rear face's\n"
"    deposit against the exposure's minutes is the cumulative mass of the\n"
"    window at %d equal steps. The rear-face map bins the window's sticks on\n"
"    the rear face (mirrored about y = 0 with --half-model).\n"
"\n"
"    With --ladder (the resolution ladder: rows level, cells, seconds,\n"
"    rear_kg_m2, rear_rel, sensor_kg_m2, sensor_rel measured on each mesh level\n"
"    with the default snow) and --flow (results/flow.txt, its 'level'): the\n"
"    mesh error of the run's level by the rule of every resolution ladder here\n"
"    (snowladder total, libswgci: Richardson where the levels resolve a\n"
"    monotone trend, else a bound over the finest value and the extrapolation\n"
"    of the finest pair with order 2), the total error sqrt(sampling^2 +\n"
"    mesh^2), all relative to the ladder's reference, the run against the\n"
"    ladder's value of its level (z), and the error against run time of every\n"
"    level.\n"
"\n"
"OUTPUTS (in --out, a SnowWall output folder; written whole or not at all)\n"
"    snow.md          the tables: per patch, the sensor against time, the errors\n"
"    summary.txt      'key = value': the rear face's and the sensor's deposit,\n"
"                     errors, halves' z, run time\n"
"    deposit.csv      patch,area_m2,sticks,origins,mass_kg,kg_m2,rel_err,halves_z\n"
"    sensor.csv       minutes,sensor_kg_m2,sensor_sd,rear_kg_m2,rear_sd\n"
"    rear_map.csv     y_m,z_m,kg_m2 (bin centres)\n"
"    error_time.csv   level,cells,seconds,quantity,sampling,mesh,total (--ladder)\n"
"    rear_deposit.png the rear-face map with the sensor's outline (gnuplot)\n"
"    sensor.png       the sensor and the rear face: kg/m2 against minutes, 2 sigma\n"
"    error_time.png   the ladder's total and sampling errors against run time\n"
"                     (--ladder)\n"
"\n"
"OPTIONS\n"
"    --case DIR        the snow run's case folder\n"
"    --fill T, --sample T  the counting window's start and length [s]\n"
"    --build-up S      the exposure the window stands for [s] (1 .. 1e6)\n"
"    --out DIR         the output folder (created; refused if it holds other\n"
"                      files and no SnowWall marker, unless --force)\n"
"    --flow FILE       the flow's results (level, cells, mesh_seconds,\n"
"                      flow_seconds)\n"
"    --ladder CSV      the resolution ladder (above)\n"
"    --half-model      the mesh is the half body (a symmetry plane y = 0)\n"
"    --cloud NAME      the cloud (default kinematicCloud)\n"
"    --speed U, --parcels N, --nozzles N, --snow-seconds S, --processes N\n"
"                      the run's settings and cost, for the tables\n"
"    --force           write into a foreign --out folder\n"
"    -h, --help        this text\n"
"\n"
"EXIT STATUS\n"
"    0 written; 2 a usage error or refused --out; 1 unreadable or inconsistent\n"
"    records, a failed write or gnuplot. One line on standard error.\n";

/* snow-post's inputs and results, from the command line to the tables */
typedef struct {
    options o;
    /* the run's level and cost (--flow), the resolution ladder (--ladder) */
    char level[64], cells[64], ms[64], fs[64];
    sbd_ladder lad;
    sbd_ladder_error lerr[2];
    int have_ladder, krow;
    /* the patches; kr, ks: ahmed_rear's and ahmed_sensor's */
    patch p[NPATCH];
    int np, kr, ks;
    /* the rear face (ahmed_rear and ahmed_sensor together) and the sensor in the window */
    sbd_sticks rear;
    sbd_window_stat wr, ws;
    double t0, t1, mult, area_r, area_s, minutes;
    double q_val[2], q_rel[2];          /* 0 the rear face, 1 the sensor: kg/m2, relative sampling error */
    double cum[MINUTES_STEPS + 1][4];   /* the cumulative deposit against the exposure's minutes */
    /* the rear-face map from the body's published dimensions */
    sbd_params bp;
    double ymax, z0, z1;
    double map[2 * MAP_NY * MAP_NZ];
    map_grid grid;
    double map_max;
    /* the errors, relative to the ladder's reference */
    double strip_ratio, mesh[2], samp[2], total[2], zlad[2], run_seconds;
} snow_post;

/* the command line into *op (its defaults set by the caller): 0, -1 when the help was printed,
 * or the exit status of a usage error with its message printed */
static int parse_options(int argc, char **argv, options *op)
{
    options o = *op;
    int have[3] = {0, 0, 0};
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            printf(usage_snow, MINUTES_STEPS);
            return -1;
        }
        if (!strcmp(a, "--half-model")) { o.half = 1; continue; }
        if (!strcmp(a, "--force")) { o.force = 1; continue; }
        if (i + 1 >= argc)
            return die(2, "option '%s' unknown or missing its value (see --help)", a);
        const char *v = argv[++i];
        if (!strcmp(a, "--case")) o.case_dir = v;
        else if (!strcmp(a, "--out")) o.out = v;
        else if (!strcmp(a, "--flow")) o.flow = v;
        else if (!strcmp(a, "--ladder")) o.ladder = v;
        else if (!strcmp(a, "--cloud")) o.cloud = v;
        else if (!strcmp(a, "--fill")) { if (positive(a, v, 0, 1e6, &o.fill)) return 2; have[0] = 1; }
        else if (!strcmp(a, "--sample")) { if (positive(a, v, 1e-9, 1e6, &o.sample)) return 2; have[1] = 1; }
        else if (!strcmp(a, "--build-up")) { if (positive(a, v, 1, 1e6, &o.build_up)) return 2; have[2] = 1; }
        else if (!strcmp(a, "--speed")) { if (positive(a, v, 1e-6, 1e4, &o.speed)) return 2; }
        else if (!strcmp(a, "--snow-seconds")) { if (positive(a, v, 0, 1e9, &o.snow_seconds)) return 2; }
        else if (!strcmp(a, "--parcels")) { if (whole(a, v, 1, 1e9, &o.parcels)) return 2; }
        else if (!strcmp(a, "--nozzles")) { if (whole(a, v, 1, 1e6, &o.nozzles)) return 2; }
        else if (!strcmp(a, "--processes")) { if (whole(a, v, 1, 1e6, &o.processes)) return 2; }
        else
            return die(2, "unknown option '%s' (see --help)", a);
    }
    if (!o.case_dir || !o.out || !have[0] || !have[1] || !have[2])
        return die(2, "give --case, --fill, --sample, --build-up and --out (see --help)");
    if (strpbrk(o.cloud, "/*?[") || !*o.cloud)
        return die(2, "--cloud '%s' is not a cloud name", o.cloud);
    if (strchr(o.out, '\n'))
        return die(2, "--out: a folder name with a newline is refused");
    *op = o;
    return 0;
}

/* the run's level and cost from --flow, the resolution ladder from --ladder and the run's row in
 * it: 0, or the exit status with the message printed */
static int read_flow_and_ladder(snow_post *s)
{
    const options o = s->o;
    char err[2048];
    if (o.flow) {
        if (flow_value(o.flow, "level", s->level, sizeof s->level))
            return die(1, "--flow %s: no 'level = ...' line", o.flow);
        flow_value(o.flow, "cells", s->cells, sizeof s->cells);
        flow_value(o.flow, "mesh_seconds", s->ms, sizeof s->ms);
        flow_value(o.flow, "flow_seconds", s->fs, sizeof s->fs);
    }
    if (o.ladder) {
        if (sbd_ladder_read(o.ladder, &s->lad, err, sizeof err))
            return die(1, "--ladder: %s", err);
        s->have_ladder = 1;
        s->krow = s->level[0] ? sbd_ladder_find(&s->lad, s->level) : -1;
        for (int q = 0; q < 2; q++)
            if (sbd_ladder_disc(&s->lad, q, &s->lerr[q], err, sizeof err))
                return die(1, "--ladder %s: %s", o.ladder, err);
    }
    return 0;
}

/* every patch's records against its deposit field and its window; the rear face (ahmed_rear and
 * ahmed_sensor together) and the sensor in the window: 0, or the exit status with the message
 * printed */
static int window_stats(snow_post *s)
{
    patch *p = s->p;
    const int np = s->np, kr = s->kr, ks = s->ks;
    const double t0 = s->t0, t1 = s->t1;
    /* every patch: the records against the deposit field, the window */
    for (int k = 0; k < np; k++) {
        double all = 0;
        for (size_t i = 0; i < p[k].st.n; i++)
            all += p[k].st.s[i].mass;
        const double ref = fmax(fabs(p[k].deposit), 1e-300);
        if (fabs(all - p[k].deposit) > 1e-4 * ref && fabs(all - p[k].deposit) > 1e-15)
            return die(1, "patch %s: the stick records add up to %.8g kg, the deposit field to %.8g kg", p[k].name, all,
                       p[k].deposit);
        if (sbd_window(p[k].st.s, p[k].st.n, t0, t1, &p[k].w))
            return die(1, "out of memory");
    }
    /* the rear face: ahmed_rear and ahmed_sensor together */
    sbd_sticks rear = {0};
    {
        const size_t n = p[kr].st.n + p[ks].st.n;
        rear.s = malloc((n ? n : 1) * sizeof *rear.s);
        if (!rear.s)
            return die(1, "out of memory");
        memcpy(rear.s, p[kr].st.s, p[kr].st.n * sizeof *rear.s);
        memcpy(rear.s + p[kr].st.n, p[ks].st.s, p[ks].st.n * sizeof *rear.s);
        rear.n = rear.cap = n;
    }
    s->rear = rear;
    sbd_window_stat wr, ws = p[ks].w;
    sbd_window(rear.s, rear.n, t0, t1, &wr);
    s->wr = wr;
    s->ws = ws;
    s->area_r = p[kr].area + p[ks].area;
    s->area_s = p[ks].area;
    const double area_r = s->area_r, area_s = s->area_s;
    s->q_val[0] = wr.mass / area_r;
    s->q_val[1] = ws.mass / area_s;
    s->q_rel[0] = wr.mass > 0 ? sqrt(wr.var) / wr.mass : 1;
    s->q_rel[1] = ws.mass > 0 ? sqrt(ws.var) / ws.mass : 1;
    return 0;
}

/* deposit.csv: per patch and the rear face; 0, or the exit status of a failed open */
static int write_deposit_csv(const snow_post *s)
{
    const patch *p = s->p;
    const sbd_window_stat wr = s->wr;
    const double mult = s->mult, area_r = s->area_r;
    FILE *f = out_open("deposit.csv");
    if (!f)
        return g_out_rc;
    fprintf(f, "patch,area_m2,sticks,origins,mass_kg,kg_m2,rel_err,halves_z\n");
    for (int k = 0; k < s->np; k++) {
        const sbd_window_stat *w = &p[k].w;
        fprintf(f, "%s,%.6g,%zu,%zu,%.6g,%.6g,%.4g,%.3f\n", p[k].name, p[k].area * mult, w->sticks, w->origins,
                w->mass * mult, w->mass / p[k].area, w->mass > 0 ? sqrt(w->var) / w->mass : 0, sbd_halves_z(w));
    }
    fprintf(f, "rear_face,%.6g,%zu,%zu,%.6g,%.6g,%.4g,%.3f\n", area_r * mult, wr.sticks, wr.origins, wr.mass * mult,
            s->q_val[0], s->q_rel[0], sbd_halves_z(&wr));
    return 0;
}

/* sensor.csv: the cumulative deposit against the exposure's minutes (into s->cum); 0, or the
 * exit status of a failed open */
static int write_sensor_csv(snow_post *s)
{
    const options o = s->o;
    const patch *p = s->p;
    const int ks = s->ks;
    const sbd_sticks rear = s->rear;
    const double t0 = s->t0, area_s = s->area_s, area_r = s->area_r, minutes = s->minutes;
    double (*cum)[4] = s->cum;
    for (int k = 0; k <= MINUTES_STEPS; k++) {
        const double tk = t0 + o.sample * k / MINUTES_STEPS;
        sbd_window_stat a = {0}, b = {0};
        if (k > 0) {
            sbd_window(p[ks].st.s, p[ks].st.n, t0, tk, &a);
            sbd_window(rear.s, rear.n, t0, tk, &b);
        }
        cum[k][0] = a.mass / area_s;
        cum[k][1] = sqrt(a.var) / area_s;
        cum[k][2] = b.mass / area_r;
        cum[k][3] = sqrt(b.var) / area_r;
    }
    FILE *f = out_open("sensor.csv");
    if (!f)
        return g_out_rc;
    fprintf(f, "minutes,sensor_kg_m2,sensor_sd,rear_kg_m2,rear_sd\n");
    for (int k = 0; k <= MINUTES_STEPS; k++)
        fprintf(f, "%.4g,%.6g,%.4g,%.6g,%.4g\n", minutes * k / MINUTES_STEPS, cum[k][0], cum[k][1], cum[k][2],
                cum[k][3]);
    return 0;
}

/* rear_map.csv: the window's rear-face sticks binned on the rear face from the body's published
 * dimensions (into s->map, s->grid, s->map_max); 0, or the exit status of a failed open */
static int write_rear_map(snow_post *s)
{
    const options o = s->o;
    const sbd_sticks rear = s->rear;
    const double t0 = s->t0, t1 = s->t1;
    sbd_params_default(&s->bp);
    const sbd_params bp = s->bp;
    const double ymax = bp.width / 2, z0 = bp.clearance, z1 = bp.clearance + bp.height;
    const double ymin = o.half ? 0 : -ymax;
    const int ny = o.half ? MAP_NY : 2 * MAP_NY;
    s->ymax = ymax;
    s->z0 = z0;
    s->z1 = z1;
    double *map = s->map;
    size_t outside = 0;
    sbd_map(rear.s, rear.n, t0, t1, 1, 2, ymin, ymax, ny, z0, z1, MAP_NZ, map, &outside);
    if (outside)
        fprintf(stderr, "snowbody: snow-post: note: %zu rear-face sticks outside the face's rectangle\n", outside);
    FILE *f = out_open("rear_map.csv");
    if (!f)
        return g_out_rc;
    fprintf(f, "y_m,z_m,kg_m2\n");
    const map_grid grid = {map, ny, ymin, (ymax - ymin) / ny, z0, (z1 - z0) / MAP_NZ, o.half};
    s->grid = grid;
    s->map_max = map_rows(f, ',', &s->grid);
    return 0;
}

/* the half model's symmetry-plane ratio; this run's sampling error and its level's
 * discretization error, both relative to the ladder's reference (so that the total is their root
 * sum of squares); the run's time */
static void errors(snow_post *s)
{
    const options o = s->o;
    const sbd_sticks rear = s->rear;
    const double t0 = s->t0, t1 = s->t1, ymax = s->ymax;
    const double *q_val = s->q_val, *q_rel = s->q_rel;
    const int krow = s->krow;
    /* the half model's symmetry plane: the rear face's deposit per area within 5 mm of it
       against the rest of the face (1 for a deposit that does not see the plane) */
    double strip_ratio = NAN;
    if (o.half) {
        double m_in = 0, m_out = 0;
        for (size_t i = 0; i < rear.n; i++)
            if (rear.s[i].t > t0 && rear.s[i].t <= t1)
                *(rear.s[i].x[1] < 0.005 ? &m_in : &m_out) += rear.s[i].mass;
        if (m_out > 0)
            strip_ratio = (m_in / 0.005) / (m_out / (ymax - 0.005));
    }
    s->strip_ratio = strip_ratio;

    /* the errors: this run's sampling error and its level's discretization error, both
       relative to the ladder's reference (so that the total is their root sum of squares) */
    double *mesh = s->mesh, *samp = s->samp, *total = s->total, *zlad = s->zlad;
    for (int q = 0; q < 2; q++)
        mesh[q] = samp[q] = total[q] = zlad[q] = NAN;
    if (s->have_ladder && krow >= 0)
        for (int q = 0; q < 2; q++) {
            mesh[q] = s->lerr[q].disc[krow];
            samp[q] = q_rel[q] * q_val[q] / fabs(s->lerr[q].ref);
            total[q] = hypot(samp[q], mesh[q]);
            const sbd_ladder_row *r = &s->lad.row[krow];
            const double sa = q_rel[q] * q_val[q], sb = r->rel[q] * r->value[q];
            zlad[q] = (q_val[q] - r->value[q]) / sqrt(sa * sa + sb * sb);
            if (fabs(zlad[q]) < 0.005)
                zlad[q] = 0;   /* printed as 0.00, not -0.00 */
        }
    s->run_seconds = atof(s->ms) + atof(s->fs) + o.snow_seconds;
}

/* error_time.csv (with --ladder) and summary.txt; 0, or the exit status of a failed open */
static int write_error_time_and_summary(const snow_post *s)
{
    const options o = s->o;
    const sbd_ladder *lad = &s->lad;
    const sbd_ladder_error *lerr = s->lerr;
    const double *q_val = s->q_val, *q_rel = s->q_rel, *mesh = s->mesh, *total = s->total, *zlad = s->zlad;
    const double minutes = s->minutes, t0 = s->t0, t1 = s->t1;
    const char *level = s->level;
    FILE *f;
    /* error_time.csv */
    if (s->have_ladder) {
        if (!(f = out_open("error_time.csv")))
            return g_out_rc;
        fprintf(f, "level,cells,seconds,quantity,sampling,mesh,total\n");
        for (int k = 0; k < lad->n; k++)
            for (int q = 0; q < 2; q++) {
                fprintf(f, "%s,%ld,%.0f,%s,%.4f,%.4f,%.4f\n", lad->row[k].level, lad->row[k].cells, lad->row[k].seconds,
                        q ? "sensor" : "rear", lerr[q].sampling[k], lerr[q].disc[k], lerr[q].total[k]);
            }
    }

    /* summary.txt */
    if (!(f = out_open("summary.txt")))
        return g_out_rc;
    fprintf(f, "# snowbody snow-post: the deposit of %.4g min (the window %.6g .. %.6g s of the snow run)\n",
            minutes, t0, t1);
    fprintf(f, "level = %s\n", level[0] ? level : "-");
    for (int q = 0; q < 2; q++) {
        const char *k = q ? "sensor" : "rear";
        const sbd_window_stat *w = q ? &s->ws : &s->wr;
        fprintf(f, "%s_kg_m2 = %.6g\n%s_rel_sampling = %.4f\n%s_sticks = %zu\n%s_origins = %zu\n%s_halves_z = %.3f\n",
                k, q_val[q], k, q_rel[q], k, w->sticks, k, w->origins, k, sbd_halves_z(w));
        if (!isnan(mesh[q]))
            fprintf(f, "%s_rel_mesh = %.4f\n%s_rel_total = %.4f\n%s_z_vs_ladder = %.2f\n", k, mesh[q], k, total[q], k,
                    zlad[q]);
    }
    if (!isnan(s->strip_ratio))
        fprintf(f, "rear_symmetry_strip_ratio = %.3f\n", s->strip_ratio);
    fprintf(f, "snow_seconds = %.0f\nrun_seconds = %.0f\n", o.snow_seconds, s->run_seconds);
    return 0;
}

/* snow.md: the run, the deposit per patch, the sensor against time, the errors; 0, or the exit
 * status of a failed open */
static int write_snow_md(const snow_post *s)
{
    const options o = s->o;
    const patch *p = s->p;
    const int np = s->np, have_ladder = s->have_ladder, krow = s->krow;
    const sbd_ladder *lad = &s->lad;
    const sbd_ladder_error *lerr = s->lerr;
    const sbd_window_stat wr = s->wr;
    const double *q_val = s->q_val, *q_rel = s->q_rel, *mesh = s->mesh, *samp = s->samp, *total = s->total,
                 *zlad = s->zlad;
    const double (*cum)[4] = (const double (*)[4])s->cum;
    const double mult = s->mult, minutes = s->minutes, t0 = s->t0, t1 = s->t1, area_r = s->area_r;
    const double strip_ratio = s->strip_ratio, run_seconds = s->run_seconds;
    const char *level = s->level, *cells = s->cells;
    const char *q_name[2] = {"rear face", "sensor"};
    FILE *f;
    if (!(f = out_open("snow.md")))
        return g_out_rc;
    fprintf(f, "# Snow on the square-back Ahmed body\n\n");
    fprintf(f, "%s level%s%s cells; the snow at %.5g m/s, %ld parcels per nozzle x %ld nozzles, "
               "%ld process(es); the deposit of %.4g min of spray (the sticks of %.6g .. %.6g s). "
               "Masses are of the whole body%s.\n\n",
            level[0] ? level : "(unknown)", cells[0] ? ", " : "", cells, o.speed, o.parcels, o.nozzles, o.processes,
            minutes, t0, t1, o.half ? " (the half model's x 2)" : "");
    fprintf(f, "## Deposit per patch\n\n| patch | area [m²] | sticks | origins | deposit [g] | [kg/m²] | "
               "sampling error | halves z |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < np; k++) {
        const sbd_window_stat *w = &p[k].w;
        fprintf(f, "| %s | %.4g | %zu | %zu | %.4g | %.3g | %s%.0f %% | %.2f |\n", p[k].name, p[k].area * mult,
                w->sticks, w->origins, 1e3 * w->mass * mult, w->mass / p[k].area, w->mass > 0 ? "" : "(none) ",
                w->mass > 0 ? 100 * sqrt(w->var) / w->mass : 0, sbd_halves_z(w));
    }
    fprintf(f, "| **rear face** (rear + sensor) | %.4g | %zu | %zu | %.4g | %.3g | %.0f %% | %.2f |\n\n",
            area_r * mult, wr.sticks, wr.origins, 1e3 * wr.mass * mult, q_val[0], 100 * q_rel[0],
            sbd_halves_z(&wr));
    if (!isnan(strip_ratio))
        fprintf(f, "Half model: the rear face's deposit per area within 5 mm of the symmetry plane is %.2f times "
                   "the rest of the face's (near 1 when the plane does not bias the deposit).\n\n", strip_ratio);
    fprintf(f, "Sampling error: 1 sigma, the sticks grouped by the injected parcel they descend from. "
               "Halves z: the window's second half against its first, in sigmas (|z| < 2 for a steady deposit "
               "in 95 %% of runs).\n\n");
    fprintf(f, "## The sensor against time\n\n| minutes | sensor [kg/m²] | ± 1 sigma | rear face [kg/m²] | "
               "± 1 sigma |\n|---|---|---|---|---|\n");
    for (int k = 0; k <= MINUTES_STEPS; k += MINUTES_STEPS / 6)
        fprintf(f, "| %.3g | %.3g | %.2g | %.3g | %.2g |\n", minutes * k / MINUTES_STEPS, cum[k][0], cum[k][1],
                cum[k][2], cum[k][3]);
    fprintf(f, "\n(sensor.csv: every %.3g min; sensor.png)\n\n## The error\n\n", minutes / MINUTES_STEPS);
    if (!have_ladder)
        fprintf(f, "No resolution ladder given: the sampling error only.\n\n");
    else if (krow < 0)
        fprintf(f, "The level '%s' is not on the resolution ladder (%s): its mesh error is not known; the "
                   "sampling error only.\n\n", level[0] ? level : "-", o.ladder);
    fprintf(f, "| quantity | 30-min deposit [kg/m²] | sampling | mesh | total | vs the ladder's %s |\n"
               "|---|---|---|---|---|---|\n", krow >= 0 ? level : "level");
    for (int q = 0; q < 2; q++) {
        if (isnan(mesh[q]))
            fprintf(f, "| %s | %.3g | %.0f %% | – | ≥ %.0f %% | – |\n", q_name[q], q_val[q], 100 * q_rel[q],
                    100 * q_rel[q]);
        else
            fprintf(f, "| %s | %.3g | %.0f %% | %.0f %% (%s) | %.0f %% | z = %.2f |\n", q_name[q], q_val[q],
                    100 * samp[q], 100 * mesh[q], lerr[q].kind, 100 * total[q], zlad[q]);
    }
    if (have_ladder && krow >= 0)
        fprintf(f, "\nAll relative to the ladder's reference (rear face %.3g, sensor %.3g kg/m²). Mesh: the "
                   "discretization error of the run's level by the rule of every resolution ladder here "
                   "(snowladder total): where the levels resolve a monotone trend, its distance to the "
                   "Richardson extrapolation with that value's own uncertainty (extrapolated); where they do "
                   "not, a bound, the larger of its distances to the finest value and to the extrapolation of "
                   "the finest pair with the schemes' order 2, each with its last step as its uncertainty "
                   "(bound). Total: the root sum of squares.\n\n", lerr[0].ref, lerr[1].ref);
    if (have_ladder) {
        fprintf(f, "### The error against run time (%s)\n\n| level | cells | run time [CPU min] | rear: sampling | mesh | "
                   "total | sensor: sampling | mesh | total |\n|---|---|---|---|---|---|---|---|---|\n", o.ladder);
        for (int k = 0; k < lad->n; k++) {
            const sbd_ladder_row *r = &lad->row[k];
            fprintf(f, "| %s | %ld | %.1f", r->level, r->cells, r->seconds / 60);
            for (int q = 0; q < 2; q++) {
                fprintf(f, " | %.0f %% | %.0f %% | %.0f %%", 100 * lerr[q].sampling[k], 100 * lerr[q].disc[k],
                        100 * lerr[q].total[k]);
            }
            fprintf(f, " |\n");
        }
        fprintf(f, "| this run (%s; wall clock) | %s | %.1f | %.0f %% | | | %.0f %% | | |\n\n", level[0] ? level : "-",
                cells[0] ? cells : "-", run_seconds / 60, 100 * q_rel[0] * q_val[0] / fabs(lerr[0].ref),
                100 * q_rel[1] * q_val[1] / fabs(lerr[1].ref));
    }
    return 0;
}

/* the gnuplot script of the pictures into g, the data inline (the set's files are not final
 * yet): the rear-face map, the sensor against time, the ladder's errors against run time
 * (png_err, with --ladder) */
static void pictures_script(FILE *g, const snow_post *s, const char *png_map, const char *png_sensor,
                            const char *png_err)
{
    const sbd_params bp = s->bp;
    const sbd_ladder *lad = &s->lad;
    const sbd_ladder_error *lerr = s->lerr;
    const double (*cum)[4] = (const double (*)[4])s->cum;
    const double minutes = s->minutes, ymax = s->ymax, z0 = s->z0, z1 = s->z1, map_max = s->map_max;
    const char *level = s->level;
    fprintf(g, "set terminal pngcairo size 900,700 font 'sans,11'\nset output ");
    gp_quoted(g, png_map);
    fprintf(g, "\n$map << EOD\n");
    map_rows(g, ' ', &s->grid);
    fprintf(g, "EOD\n");
    fprintf(g, "set title \"Snow on the rear face, %.3g min (%s level; kg/m^2)\"\n", minutes,
            level[0] ? level : "?");
    fprintf(g, "set xlabel 'y [m]'\nset ylabel 'z [m]'\nset size ratio -1\nset xrange [%g:%g]\nset yrange [%g:%g]\n",
            -ymax, ymax, z0, z1);
    fprintf(g, "set cblabel 'kg/m^2'\nset cbrange [0:%g]\nset palette defined (0 'white', 1 '#9ecae1', 2 '#3182bd', "
               "3 '#08306b')\n", map_max > 0 ? map_max : 1);
    fprintf(g, "set object 1 rect from %g,%g to %g,%g front fillstyle empty border lc rgb 'red' lw 2\n",
            bp.sensor_y - bp.sensor_width / 2, bp.sensor_z - bp.sensor_height / 2,
            bp.sensor_y + bp.sensor_width / 2, bp.sensor_z + bp.sensor_height / 2);
    fprintf(g, "set label 1 'sensor' at %g,%g front tc rgb 'red'\n", bp.sensor_y + bp.sensor_width / 2 + 0.005,
            bp.sensor_z);
    fprintf(g, "plot $map using 1:2:3 with image notitle\n");
    fprintf(g, "set output\nunset object 1\nunset label 1\nset size noratio\nset autoscale\nset output ");
    gp_quoted(g, png_sensor);
    fprintf(g, "\n$cum << EOD\n");
    for (int k = 0; k <= MINUTES_STEPS; k++)
        fprintf(g, "%.5g %.6g %.6g %.6g %.6g\n", minutes * k / MINUTES_STEPS, cum[k][0], cum[k][1], cum[k][2],
                cum[k][3]);
    fprintf(g, "EOD\nset title \"Deposit against time (%s level; band: 2 sigma of sampling)\"\n",
            level[0] ? level : "?");
    fprintf(g, "set xlabel 'minutes of spray'\nset ylabel 'kg/m^2'\nset key top left\nset grid\n"
               "set style fill transparent solid 0.25 noborder\n");
    fprintf(g, "plot $cum using 1:($2-2*$3 > 0 ? $2-2*$3 : 0):($2+2*$3) with filledcurves lc rgb '#e6550d' notitle, "
               "$cum using 1:2 with lines lw 2 lc rgb '#e6550d' title 'sensor', "
               "$cum using 1:($4-2*$5 > 0 ? $4-2*$5 : 0):($4+2*$5) with filledcurves lc rgb '#3182bd' notitle, "
               "$cum using 1:4 with lines lw 2 lc rgb '#3182bd' title 'rear face (mean)'\n");
    fprintf(g, "set output\n");
    if (png_err) {   /* the ladder's total error against its run time, log-log */
        fprintf(g, "unset style\nset style fill solid\nset output ");
        gp_quoted(g, png_err);
        fprintf(g, "\n$err << EOD\n");
        for (int k = 0; k < lad->n; k++) {
            const sbd_ladder_row *r = &lad->row[k];
            fprintf(g, "%.6g", r->seconds / 60);
            for (int q = 0; q < 2; q++)
                fprintf(g, " %.6g %.6g", 100 * lerr[q].total[k], 100 * lerr[q].sampling[k]);
            fprintf(g, " %s\n", r->level);
        }
        fprintf(g, "EOD\nset title \"Error of the 30-min deposit against run time (the resolution ladder)\"\n"
                   "set xlabel 'run time: mesh, flow and snow [CPU min]' offset 0,-1\nset ylabel 'error [%%]'\n"
                   "set logscale xy\nset key outside right top vertical\nset grid\nset autoscale xfix\n"
                   "set offsets graph 0.1, graph 0.1, 0, 0\nset yrange [*:*]\nset bmargin 6\n");
        /* the levels named on the run-time axis at their run times (each tic "level\n
           minutes"), the key right of the data: no label over a point */
        fprintf(g, "plot $err using 1:2:xtic(sprintf(\"%%s\\n%%.3g\", strcol(6), $1)) with linespoints lw 2 pt 7 "
                   "lc rgb '#3182bd' title 'rear face, total', "
                   "$err using 1:3 with linespoints dt 2 pt 6 lc rgb '#3182bd' title 'rear face, sampling', "
                   "$err using 1:4 with linespoints lw 2 pt 7 lc rgb '#e6550d' title 'sensor, total', "
                   "$err using 1:5 with linespoints dt 2 pt 6 lc rgb '#e6550d' title 'sensor, sampling'\n"
                   "set output\n");
    }
}

/* the pictures: one gnuplot script, its PNGs written to the set's temporaries; 0, or the exit
 * status with the message printed */
static int write_pictures(const snow_post *s)
{
    const options o = s->o;
    const int have_ladder = s->have_ladder;
    char err[2048];
    const char *png_map = swo_add(g_set, "rear_deposit.png", err, sizeof err);
    const char *png_sensor = png_map ? swo_add(g_set, "sensor.png", err, sizeof err) : NULL;
    const char *png_err = (png_sensor && have_ladder) ? swo_add(g_set, "error_time.png", err, sizeof err) : NULL;
    if (png_sensor && have_ladder && !png_err)
        png_sensor = NULL;   /* the failure is reported below */
    char script[4096];
    snprintf(script, sizeof script, "%s/.tmp-snow-post-%ld.gp", o.out, (long)getpid());
    FILE *g = png_sensor ? fopen(script, "w") : NULL;
    if (!g)
        return die(png_sensor ? 1 : swo_code(g_set), "%s", png_sensor ? "cannot write the gnuplot script" : err);
    swo_signal_scratch(script);
    pictures_script(g, s, png_map, png_sensor, png_err);
    int bad = fclose(g);
    int grc = bad ? -1 : run_gnuplot(script);
    remove(script);
    swo_signal_scratch(NULL);
    if (grc)
        return die(1, "gnuplot failed on the pictures (is gnuplot with pngcairo installed?)");
    return 0;
}

int sbd_cmd_snow_post(int argc, char **argv)
{
    snow_post s;
    memset(&s, 0, sizeof s);
    s.o = (options){.cloud = "kinematicCloud", .speed = 0, .processes = 1};
    int rc = parse_options(argc, argv, &s.o);
    if (rc < 0)
        return fflush(stdout) ? 1 : 0;
    if (rc)
        return rc;
    const options *o = &s.o;

    /* the output folder checked before the work */
    char err[2048];
    swo_spec spec = {.tool = "snowbody snow-post", .dir = o->out, .force = o->force, .parents = 1};
    rc = swo_alloc(&spec, &g_set, err, sizeof err);
    if (rc)
        return die(rc, "%s", err);
    if (swo_note(g_set))
        fprintf(stderr, "snowbody: snow-post: note: %s\n", swo_note(g_set));
    swo_signals_on();

    /* the ladder and the run's level */
    s.krow = -1;
    if ((rc = read_flow_and_ladder(&s)))
        return rc;

    if ((rc = load_patches(o, s.p, &s.np)))
        goto done;
    s.kr = find(s.p, s.np, "ahmed_rear");
    s.ks = find(s.p, s.np, "ahmed_sensor");
    if (s.kr < 0 || s.ks < 0) {
        rc = die(1, "%s: no deposit table of ahmed_rear or ahmed_sensor", o->case_dir);
        goto done;
    }
    s.t0 = o->fill;
    s.t1 = o->fill + o->sample;
    s.mult = o->half ? 2 : 1;
    s.minutes = o->build_up / 60;
    if ((rc = window_stats(&s)) || (rc = write_deposit_csv(&s)) || (rc = write_sensor_csv(&s)) ||
        (rc = write_rear_map(&s)))
        goto done;
    errors(&s);
    if ((rc = write_error_time_and_summary(&s)) || (rc = write_snow_md(&s)) || (rc = write_pictures(&s)))
        goto done;

    if ((rc = swo_commit(g_set, err, sizeof err))) {
        rc = die(rc, "%s", err);
        goto done;
    }
    printf("sensor: %.3g kg/m2 in %.4g min, sampling %.0f %%%s; rear face %.3g kg/m2, sampling %.0f %%; written to %s/\n",
           s.q_val[1], s.minutes, 100 * s.q_rel[1], "", s.q_val[0], 100 * s.q_rel[0], o->out);
    rc = 0;
done:
    sbd_sticks_free(&s.rear);
    for (int k = 0; k < s.np; k++)
        sbd_sticks_free(&s.p[k].st);
    swo_free(g_set);
    g_set = NULL;
    return rc;
}
