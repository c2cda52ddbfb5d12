/* swe_run.c - the numbers tutorials/wedge/Allrun computes or formats (swe_run.h).
 * The formats follow the files Allrun has always written: a value read as text
 * (a time, a setting) is copied as text, a computed one printed with the
 * precision the file has always had. */
#include "swe_run.h"
#include "swo_err.h"

#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define fail(err, n, code, ...) swo_fail(code, err, n, __VA_ARGS__)  /* common/swo_err.h */

/* a text's leading number (0 when it has none), as awk reads a field */
static double num(const char *s)
{
    return s ? strtod(s, NULL) : 0;
}

/* the i-th (1-based) blank-separated field of line into out ("" when absent) */
static const char *field(const char *line, int i, char *out, size_t n)
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

static void chomp(char *s)
{
    size_t l = strlen(s);
    while (l && (s[l - 1] == '\n' || s[l - 1] == '\r'))
        s[--l] = 0;
}

/* ---- the mesh ---------------------------------------------------------------------- */
int swe_mesh_parse(const char *text, swe_mesh *m, char *err, size_t nerr)
{
    m->n = 0;
    const char *p = text;
    while (*p) {
        while (*p == ' ' || *p == ';')
            p++;
        if (!*p)
            break;
        char key[32];
        long v;
        int used;
        if (sscanf(p, "%31s %ld%n", key, &v, &used) != 2 || m->n == SWE_MESH_MAX)
            return fail(err, nerr, 2, "the mesh '%s' is not \"KEY N; KEY N; ...\"", text);
        snprintf(m->key[m->n], sizeof m->key[0], "%s", key);
        m->val[m->n++] = v;
        p += used;
        while (*p == ' ')
            p++;
        if (*p && *p != ';')
            return fail(err, nerr, 2, "the mesh '%s' is not \"KEY N; KEY N; ...\"", text);
    }
    return 0;
}

long swe_mesh_get(const swe_mesh *m, const char *key)
{
    for (int i = 0; i < m->n; i++)
        if (!strcmp(m->key[i], key))
            return m->val[i];
    return -1;
}

static double level_factor(int level)
{
    return level % 2 == 0 ? pow(2, level / 2.0) : pow(sqrt(2), level);
}

double swe_level_scale(int level)
{
    return level_factor(-level);
}

void swe_mesh_scale(swe_mesh *m, int level, int refine_wake)
{
    const double f = level_factor(level);
    for (int i = 0; i < m->n; i++) {
        if (level != 0) {
            m->val[i] = (long)(m->val[i] * f + 0.5);
            if (m->val[i] < 1)
                m->val[i] = 1;
        }
        if (refine_wake && (!strcmp(m->key[i], "nxDown") || !strcmp(m->key[i], "nBody")))
            m->val[i] = (long)(m->val[i] * 1.25 + 0.5);
    }
}

void swe_mesh_format(const swe_mesh *m, char *out, size_t n)
{
    size_t l = 0;
    out[0] = 0;
    for (int i = 0; i < m->n && l < n; i++)
        l += (size_t)snprintf(out + l, n - l, "%s%s %ld;", i ? " " : "", m->key[i], m->val[i]);
}

double swe_mesh_cells(const swe_mesh *m)
{
    const double x = (double)swe_mesh_get(m, "nxUp") + (double)swe_mesh_get(m, "nxBody") +
                     (double)swe_mesh_get(m, "nxDown");
    const double y = 2.0 * (double)swe_mesh_get(m, "nOut") + (double)swe_mesh_get(m, "nBody");
    const double b = (double)swe_mesh_get(m, "nBody");
    return x * y * y - (double)swe_mesh_get(m, "nxBody") * b * b;
}

long swe_mesh_ny(const swe_mesh *m)
{
    return swe_mesh_get(m, "nBody") + 2 * swe_mesh_get(m, "nOut");
}

/* ---- the case's spray and size classes ------------------------------------------------------ */
int swe_check_spray(const char *mvd, const char *sigma_g, const char *freeze, const char *range_lo,
                    const char *range_hi, char *err, size_t nerr)
{
    const double m = num(mvd), s = num(sigma_g), f = num(freeze), a = num(range_lo), b = num(range_hi);
    if (!(s > 1 && s <= 10 && f >= 0.5 && f <= 2 && a >= 0.1 && b <= 10000 && m >= 0.1 && m <= 1000))
        return fail(err, nerr, 2, "constant/sprayProperties: spray needs mvd in [0.1, 1000] um, sigmaG in (1, "
                    "10], freeze in [0.5, 2] and a range within [0.1, 10000] um; got mvd %s, sigmaG %s, freeze "
                    "%s, range (%s %s)", mvd, sigma_g, freeze, range_lo, range_hi);
    return 0;
}

/* the comma-separated items of a list as numbers; returns their count */
static int csv_numbers(const char *s, double *v, int max)
{
    int n = 0;
    for (const char *p = s; *p && n < max;) {
        v[n++] = strtod(p, NULL);
        p = strchr(p, ',');
        if (!p)
            break;
        p++;
    }
    return n;
}

int swe_check_classes(const char *sizes, const char *parcels, char *err, size_t nerr)
{
    double a[256], b[256];
    const int n = csv_numbers(sizes, a, 256), m = csv_numbers(parcels, b, 256);
    int ok = n == m;
    for (int i = 0; ok && i < n; i++) {
        ok = !(a[i] > 1000);
        for (int j = 0; ok && j < i; j++)
            ok = a[j] != a[i];
    }
    if (!ok)
        return fail(err, nerr, 2, "constant/sprayProperties: classes needs sizes (whole um, 1..1000, each once) "
                    "and as many parcelsPerNozzle, got (%s) and (%s)", sizes, parcels);
    return 0;
}

/* ---- the cost estimate ----------------------------------------------------------------
 * Scaled from the default coarse run measured on the development machine:
 *   the flow      3.7e-6 s per cell and solved step on one process, x np^-0.25 on np
 *                 (x 1.64 with the rear face resolved: the same steps, more work);
 *   the particles 2.3e-3 s per spray parcel, 6.9e-3 s per split parcel, at the step
 *                 2.5e-4 s (x 2.5e-4 / dt at another), x np^-0.5;
 *   the step      dt = 2.5e-4 s x 20 / nBody (/ 2 with -halfstep), at most maxDeltaT
 *                 (1e-3 s, 5e-4 s with -halfstep); with the replay the flow is solved
 *                 only until the library is complete (replayStart + replayPeriod);
 *   the memory    2 kB per cell, the replay library (snapshots x cells x 7 values x
 *                 8 bytes x 1.1 for the boundaries) and 560 B per parcel, every parcel
 *                 alive at once and a split one split to 1 + 4 F / 3 (F = 100),
 *                 at most 2e6 per cloud;
 *   the disk      4 writes of 20 values of 8 bytes per cell, the library, and 4 x 120
 *                 + 250 bytes of records per parcel;
 *   the rear layers add 5 x nBody^2 cells; -full injects the classes at
 *                 4 (fill + 2 window) / (fill + window) times their rate over a window
 *                 twice as long; a class has at least one parcel per nozzle, the wake
 *                 source 9 points of 400 x the class factor parcels. */
int swe_estimate(const swe_estimate_in *in, swe_estimate_out *o)
{
    memset(o, 0, sizeof *o);
    const double nb = in->nbody;
    double cells = in->cells0;
    if (in->steady) {
        o->cells = cells;
        o->clouds = 1 + 3 * in->compare;
        o->parcels = in->nozzles * floor(in->ppn * in->ppn_factor + 0.5);
        o->mem_flow = cells * 2048;
        o->mem_parcels = o->parcels * 560;
        o->disk_fields = 2 * o->clouds * cells * 20 * 8;
        return 0;
    }
    if (in->rear_layers)
        cells += 5 * nb * nb;
    double samp = in->sample, cf;
    if (in->full) {
        cf = 4 * in->class_factor * (in->fill + 2 * samp) / (in->fill + samp);
        samp = 2 * samp;
    } else
        cf = in->class_factor;
    const double t1 = in->spin + in->fill + samp;
    double dt = 2.5e-4 * 20 / nb, maxdt = 1e-3;
    if (in->halfstep) {
        dt /= 2;
        maxdt = 5e-4;
    }
    if (dt > maxdt)
        dt = maxdt;
    const double steps = t1 / dt;
    const double fsteps = in->replay ? (in->replay_start + in->replay_period) / dt : steps;
    const int nspray = 1 + 3 * in->compare + in->feedback + in->rough + in->rebound + in->ndisp - 1;
    const double pspray = nspray * in->nozzles * floor(in->ppn * in->ppn_factor + 0.5);
    double pcls = 0;
    for (int i = 0; i < in->nclasses; i++) {
        double q = (double)(long)(in->class_ppn[i] * cf + 0.5);
        if (q < 1)
            q = 1;
        pcls += in->ndisp * in->nozzles * q;
    }
    double qw = (double)(long)(400 * in->class_factor + 0.5);
    if (qw < 1)
        qw = 1;
    const double pwake = in->nwake * 9 * qw;
    double tflow = fsteps * cells * 3.7e-6 / pow(in->np, 0.25);
    if (in->rear_layers)
        tflow *= 1.64;
    const double tpart = (pspray * (in->split ? 6.9e-3 : 2.3e-3) + pcls * 6.9e-3 + pwake * 2.3e-3) *
                         2.5e-4 / dt / pow(in->np, 0.5);
    const double lib =
        in->replay ? (in->replay_period / in->replay_interval) * cells * 7 * 8 * 1.1 : 0;
    const double F = 100, maxp = 2e6;
    double bspray = pspray * (in->split ? 1 + 4 * F / 3 : 1);
    if (in->split && bspray > nspray * maxp)
        bspray = nspray * maxp;
    double bcls = pcls * (1 + 4 * F / 3);
    const double ncl = in->ndisp * in->nclasses;
    if (bcls > ncl * maxp)
        bcls = ncl * maxp;
    o->cells = cells;
    o->clouds = nspray + in->ndisp * in->nclasses + in->nwake;
    o->parcels = pspray + pcls + pwake;
    o->class_parcels = pcls;
    o->steps = steps;
    o->flow_steps = fsteps;
    o->lib = lib;
    o->mem_flow = cells * 2048 + lib;
    o->mem_parcels = (bspray + bcls + pwake) * 560;
    o->disk_fields = 4 * cells * 20 * 8 + lib;
    o->disk_parcels = (bspray + bcls + pwake) * (4 * 120 + 250);
    o->t_flow = tflow;
    o->t_parcels = tpart;
    return 0;
}

static void gb(char *s, size_t n, double v, const char *unknown_or_unit)
{
    if (v < 0)
        snprintf(s, n, "%s", unknown_or_unit);
    else
        snprintf(s, n, "%.3g GB", v / 1e9);
}

void swe_estimate_print(FILE *f, const swe_estimate_in *in, const swe_estimate_out *o)
{
    const double GB = 1e9;
    if (in->steady) {
        fprintf(f, "Allrun: estimate: %ld cells, %d cloud(s), %ld parcels injected each (steady route: "
                   "the converged RANS flow, then the snow in it, one frozen-flow run per gate "
                   "setting); memory about %.2g GB (flow 2 kB a cell, parcels 0.56 kB each); disk "
                   "about %.2g GB (two writes a run); time not estimated for the steady route on %d "
                   "process(es) (measured: about 15 s with -test)\n",
                (long)o->cells, o->clouds, (long)o->parcels, (o->mem_flow + o->mem_parcels) / GB,
                o->disk_fields / GB, in->np);
        return;
    }
    char av[64], fr[64];
    gb(av, sizeof av, in->avail, "unknown");
    gb(fr, sizeof fr, in->free_disk, "unknown");
    fprintf(f, "Allrun: estimate: %ld cells, %d clouds, %ld parcels injected (%ld in split classes); "
               "about %ld time steps (%ld with the flow solved); memory %.2g GB (flow %.2g GB incl. "
               "a %.2g GB replay library, parcels at most %.2g GB), %s available; disk %.2g GB "
               "(fields and the stored flow library %.2g GB, parcel records at most %.2g GB), %s "
               "free; time about %.2g min on %d process(es) (flow %.2g, particles %.2g min, and "
               "about 2 min of set-up and post-processing; scaled from the default run measured on "
               "this machine)\n",
            (long)o->cells, o->clouds, (long)o->parcels, (long)o->class_parcels, (long)o->steps,
            (long)o->flow_steps, (o->mem_flow + o->mem_parcels) / GB, o->mem_flow / GB, o->lib / GB,
            o->mem_parcels / GB, av, (o->disk_fields + o->disk_parcels) / GB, o->disk_fields / GB,
            o->disk_parcels / GB, fr, (o->t_flow + o->t_parcels) / 60 + 2, in->np, o->t_flow / 60,
            o->t_parcels / 60);
}

int swe_estimate_refuse(const swe_estimate_in *in, const swe_estimate_out *o, char *msg, size_t n)
{
    const double GB = 1e9;
    if (in->steady)
        return 0;
    if (in->avail >= 0 && o->mem_flow > in->avail)
        return fail(msg, n, 2,
                    "the flow and its replay library need about %.3g GB (%ld cells x 2 kB, "
                    "and %ld snapshots x %ld cells x 7 values x 8 bytes x 1.1), more than the %.3g "
                    "GB available (MemAvailable): refused; use -coupled, a longer "
                    "transient/replayInterval or a shorter replayPeriod, or a coarser mesh",
                    o->mem_flow / GB, (long)o->cells,
                    (long)(in->replay_period / in->replay_interval), (long)o->cells,
                    in->avail / GB);
    if (in->free_disk >= 0 && o->disk_fields > in->free_disk)
        return fail(msg, n, 2,
                    "the fields written and the stored flow library need about %.3g GB, "
                    "more than the %.3g GB free in the case folder: refused",
                    o->disk_fields / GB, in->free_disk / GB);
    return 0;
}

/* ---- the transient route's times ----------------------------------------------------------- */
static void awk_print(char *s, size_t n, double v);

/* a number as text with %.10g / %.12g, and such a text read back */
#define G10(buf, x) snprintf(buf, sizeof buf, "%.10g", (double)(x))
#define G12(buf, x) snprintf(buf, sizeof buf, "%.12g", (double)(x))

int swe_times(const swe_times_in *in, swe_times_out *o, char *err, size_t nerr)
{
    memset(o, 0, sizeof *o);
    const double s = num(in->spin), f = num(in->fill), c = num(in->class_factor);
    double w = num(in->sample);
    /* -full: the window twice as long, the classes' parcels at 4 times the rate (their
       counts are over fill + window) */
    if (in->full) {
        G10(o->class_factor, 4 * c * (f + 2 * w) / (f + w));
        G10(o->sample, 2 * w);
        w = num(o->sample);
    } else {
        snprintf(o->class_factor, sizeof o->class_factor, "%s", in->class_factor);
        snprintf(o->sample, sizeof o->sample, "%s", in->sample);
    }
    /* the writes every half window: at the window's start, middle and end */
    const double t0 = s + f, k = t0 / (w / 2);
    if (k - (long)(k + 0.5) > 1e-9 || (long)(k + 0.5) - k > 1e-9)
        return fail(err, nerr, 2, "constant/sprayProperties: spinUpTime + fillTime (%s + %s s) must be a whole "
                    "multiple of samplingTime / 2 (%s / 2 s)", in->spin, in->fill, o->sample);
    G10(o->t0, t0);
    G10(o->th, t0 + w / 2);
    G10(o->t1, t0 + w);
    G10(o->write, w / 2);
    /* the spray from the spin-up's end over fill + window, its mass scaled to the build-up time */
    G10(o->soi, s);
    G10(o->mass_total, num(in->rate) * num(in->build_up) * (f + w) / w);
    G10(o->duration, f + w);
    snprintf(o->sampled, sizeof o->sampled, "%.6g", w / (f + w));
    const char *m0 = in->halfstep ? "5e-4" : "1e-3";
    if (in->replay_interval) {
        const double a = num(in->replay_start), p = num(in->replay_period), i = num(in->replay_interval);
        const double n = p / i;
        if (!(n - (long)(n + 0.5) < 1e-6 * n && (long)(n + 0.5) - n < 1e-6 * n && n >= 2 && a + p <= num(o->t1)))
            return fail(err, nerr, 2, "constant/sprayProperties: replayPeriod (%s s) must be a whole multiple (at "
                        "least 2) of replayInterval (%s s), and the library (replayStart %s + replayPeriod %s s) "
                        "must end by the end of the run (%s s)", in->replay_period, in->replay_interval,
                        in->replay_start, in->replay_period, o->t1);
        awk_print(o->library_end, sizeof o->library_end, a + p);
        snprintf(o->replay_interval, sizeof o->replay_interval, "%s", in->replay_interval);
        if (in->level != 0) { /* a whole fraction of the period, at least 2 snapshots */
            long nn = (long)(p / (i * num(in->level_scale)) + 0.5);
            if (nn < 2)
                nn = 2;
            G12(o->replay_interval, p / nn);
        }
        /* the step scale of the interval itself, so that it stays maxDeltaT's multiple */
        G12(o->step_scale, num(o->replay_interval) / i);
    } else
        snprintf(o->step_scale, sizeof o->step_scale, "%s", in->level_scale);
    /* maxDeltaT x the step scale, at most the replay interval */
    double x = num(m0) * num(o->step_scale);
    if (in->replay_interval && x > num(o->replay_interval))
        x = num(o->replay_interval);
    G12(o->max_delta_t, x);
    /* the first step: 1e-4 s x the step scale */
    snprintf(o->delta_t, sizeof o->delta_t, "%.6g", 1e-4 * num(o->step_scale));
    if (strcmp(in->checkpoint_min, "off"))
        G10(o->checkpoint_s, 60 * num(in->checkpoint_min));
    return 0;
}

/* ---- the progress line ----------------------------------------------------------------------- */
void swe_progress_line(char *s, size_t n, double t, double t_end, double t_flow, int replay_phase,
                       double ts, long elapsed, long phase_elapsed, long allrun)
{
    const double to = t_flow >= 0 && !replay_phase ? t_flow : t_end;
    const double r = t > ts ? phase_elapsed * (to - t) / (t - ts) : -1;
    char left[256];
    if (r < 0)
        snprintf(left, sizeof left, "time left not yet estimated");
    else if (to != t_end)
        snprintf(left, sizeof left, "about %.0f s left of the solved flow (to t = %g s; the replay after it is faster)",
                 r, to);
    else
        snprintf(left, sizeof left, "about %.0f s left", r);
    snprintf(s, n, "Allrun [%ld s]: solver at t = %.4g of %g s (%.0f %%), %ld s elapsed, %s", allrun, t, t_end,
             100 * t / t_end, elapsed, left);
}

/* ---- the nozzles ---------------------------------------------------------------------- */
static int is_num_token(const char *s)
{
    if (!*s)
        return 0;
    for (; *s; s++)
        if (!strchr("-+0123456789.eE", *s))
            return 0;
    return 1;
}

int swe_nozzle_points(const char *path, char (**pts)[128], char *err, size_t nerr)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return fail(err, nerr, -1, "cannot read %s", path);
    char line[1024];
    int n = 0, cap = 0;
    char(*p)[128] = NULL;
    while (fgets(line, sizeof line, f)) {
        chomp(line);
        char *c = strstr(line, "//");
        if (c)
            *c = 0;
        char t[1024];
        size_t l = 0;
        for (const char *s = line; *s; s++)
            if (*s != '(' && *s != ')')
                t[l++] = *s;
        t[l] = 0;
        char a[128], b[128], d[128], e[8];
        if (!*field(t, 1, a, sizeof a) || *field(t, 4, e, sizeof e) || !*field(t, 3, d, sizeof d))
            continue;
        field(t, 2, b, sizeof b);
        if (!is_num_token(a) || !is_num_token(b) || !is_num_token(d))
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 32;
            char(*q)[128] = realloc(p, (size_t)cap * sizeof *p);
            if (!q) {
                free(p);
                fclose(f);
                return fail(err, nerr, -1, "out of memory");
            }
            p = q;
        }
        if (l >= sizeof *p) {
            free(p);
            fclose(f);
            return fail(err, nerr, -1, "%s: a nozzle line longer than %zu characters", path, sizeof *p - 1);
        }
        memcpy(p[n++], t, l + 1);
    }
    fclose(f);
    *pts = p;
    return n;
}

int swe_wake_points(char (**pts)[128])
{
    char(*p)[128] = malloc(9 * sizeof *p);
    if (!p)
        return -1;
    int n = 0;
    for (int i = -1; i <= 1; i++)
        for (int j = -1; j <= 1; j++)
            snprintf(p[n++], sizeof *p, "0.36 %g %g", 0.04 * i + 0.0001, 0.04 * j + 0.0001);
    *pts = p;
    return n;
}

void swe_nozzles_write(FILE *f, char (*pts)[128], int np, long parcels, const char *soi,
                       double mass_total, const char *duration, double size_um, int wake)
{
    fprintf(f, "// generated by Allrun (write_nozzles): %d nozzles, %ld parcels each\n", np, parcels);
    for (int i = 0; i < np; i++) {
        fprintf(f, "nozzle%d\n{\n    type coneInjection;\n    SOI %s;\n    massTotal %.10g;\n", i, soi,
                mass_total / np);
        fprintf(f, "    parcelBasisType mass;\n    duration %s;\n    parcelsPerInjector %ld;\n"
                   "    flowRateProfile constant 1;\n",
                duration, parcels);
        fprintf(f, "    Umag constant %s;\n    thetaInner constant 0;\n    thetaOuter constant %s;\n",
                wake ? "1" : "19.444", wake ? "90" : "6");
        fprintf(f, "    positionAxis ( ((%s) (1 0 0)) );\n", pts[i]);
        if (size_um <= 0)
            fputs("    sizeDistribution { #include \"sprayDistribution\" }\n", f);
        else
            fprintf(f, "    sizeDistribution { type fixedValue; fixedValueDistribution { value %.6g; } }\n",
                    size_um * 1e-6);
        fputs("}\n", f);
    }
}

/* ---- the decomposition ---------------------------------------------------------------- */
typedef struct {
    int flag;
    double y;
    char line[96]; /* "index x y flag" as sort compares whole lines last (bytes) */
    size_t i;
} dcell;

static int dcell_cmp(const void *pa, const void *pb)
{
    const dcell *a = pa, *b = pb;
    if (a->flag != b->flag)
        return b->flag - a->flag;
    if (a->y != b->y)
        return a->y < b->y ? -1 : 1;
    return strcmp(a->line, b->line);
}

/* a number as awk prints it: a whole value as an integer, else %.6g */
static void awk_print(char *s, size_t n, double v)
{
    if (v == (double)(long long)v && fabs(v) < 1e15)
        snprintf(s, n, "%lld", (long long)v);
    else
        snprintf(s, n, "%.6g", v);
}

int swe_decompose(const double *x, const double *y, size_t nc, int nproc, double x_nozzle,
                  int *proc, char *err, size_t nerr)
{
    char xs[32], ys[32];
    double xa = 0;
    int have = 0;
    dcell *c = malloc(nc * sizeof *c);
    if (!c)
        return fail(err, nerr, 1, "out of memory");
    /* the centres as printed (6 significant digits) and read back */
    for (size_t i = 0; i < nc; i++) {
        awk_print(xs, sizeof xs, x[i]);
        const double xr = strtod(xs, NULL);
        if (xr > x_nozzle && (!have || xr < xa)) {
            xa = xr;
            have = 1;
        }
    }
    if (!have) {
        free(c);
        return fail(err, nerr, 2, "no cell centre downstream of the nozzles");
    }
    for (size_t i = 0; i < nc; i++) {
        awk_print(xs, sizeof xs, x[i]);
        awk_print(ys, sizeof ys, y[i]);
        c[i].flag = strtod(xs, NULL) <= xa + 1e-9;
        c[i].y = strtod(ys, NULL);
        c[i].i = i;
        snprintf(c[i].line, sizeof c[i].line, "%zu %s %s %d", i + 1, xs, ys, c[i].flag);
    }
    qsort(c, nc, sizeof *c, dcell_cmp);
    for (size_t k = 0; k < nc; k++) {
        int p = (int)((double)k * nproc / (double)nc);
        if (p >= nproc)
            p = nproc - 1;
        proc[c[k].i] = p;
    }
    free(c);
    return 0;
}

/* ---- the rung's record ---------------------------------------------------------------- */
int swe_level_write(FILE *log, const swe_level_in *in, FILE *out, char *err, size_t nerr)
{
    static char line[1 << 16], wall[1 << 16];
    char tok[128];
    double dt = 0, sdt = 0;
    long n = 0, nw = 0;
    wall[0] = 0;
    while (fgets(line, sizeof line, log)) {
        if (!strncmp(line, "deltaT = ", 9))
            dt = num(field(line, 3, tok, sizeof tok));
        else if (!strncmp(line, "Time = ", 7)) {
            n++;
            const double t = num(field(line, 3, tok, sizeof tok));
            if (t > in->t0 + 1e-12 && t <= in->t1 + 1e-12) {
                nw++;
                sdt += dt;
            }
        } else if (!strncmp(line, "Wall time [s]", 13)) {
            chomp(line);
            snprintf(wall, sizeof wall, "%s", line);
        }
    }
    /* the entries after the first colon: "flow T, cloud T, ..." */
    char flow[128] = "";
    double clouds = 0;
    int has_flow = 0;
    char *p = strchr(wall, ':');
    p = p ? p + 1 : wall + strlen(wall);
    while (*p == ' ')
        p++;
    while (*p) {
        char *e = strchr(p, ',');
        if (e)
            *e = 0;
        char name[128], val[128];
        field(p, 1, name, sizeof name);
        field(p, 2, val, sizeof val);
        if (!strcmp(name, "flow")) {
            snprintf(flow, sizeof flow, "%s", val);
            has_flow = 1;
        } else
            clouds += num(val);
        if (!e)
            break;
        p = e + 1;
        while (*p == ' ')
            p++;
    }
    if (!has_flow || !flow[0] || !nw)
        return fail(err, nerr, 2, "no 'Wall time' line with the flow, or no step in the window");
    fprintf(out, "# written by tutorials/wedge/Allrun -level (post/wedge-ladder reads it)\n");
    fprintf(out, "level %s\nvariant %s\nrefine_wake %s\nhalfstep %s\nfull %s\nstep_scale %s\ncells %s\n",
            in->level, in->variant, in->refine_wake, in->halfstep, in->full, in->step_scale, in->cells);
    fprintf(out, "max_delta_t %s\nreplay_interval %s\ntime_steps %ld\nwindow %.*s %.*s\nwindow_steps %ld\n"
                 "mean_delta_t %.6g\n",
            in->max_delta_t, in->replay_interval && *in->replay_interval ? in->replay_interval : "-", n,
            64, in->window0, 64, in->window1, nw, sdt / nw);
    fprintf(out, "wall_flow_s %s\nwall_clouds_s %.6g\ngate %s\nmvd %s\n", flow, clouds, in->gate, in->mvd);
    fprintf(out, "rear_layers %s\nrear_yplus %s\n", in->rear_layers,
            in->rear_yplus && *in->rear_yplus ? in->rear_yplus : "-");
    return 0;
}

int swe_yplus_rear(FILE *const *tables, int n, double *mn, double *mean, double *mx)
{
    static char line[4096];
    int rows = 0;
    double s = 0;
    *mn = 0;
    *mx = 0;
    for (int i = 0; i < n; i++)
        while (fgets(line, sizeof line, tables[i])) {
            chomp(line);
            /* tab-separated: time, patch (blank-padded), min, max, average */
            char *f[6] = {0};
            int k = 0;
            f[k++] = line;
            for (char *c = line; *c && k < 6; c++)
                if (*c == '\t') {
                    *c = 0;
                    f[k++] = c + 1;
                }
            if (f[0][0] == '#' || k < 2)
                continue;
            char patch[64];
            size_t l = 0;
            for (const char *c = f[1]; *c && l < sizeof patch - 1; c++)
                if (*c != ' ')
                    patch[l++] = *c;
            patch[l] = 0;
            if (strcmp(patch, "rear"))
                continue;
            const double a = num(k > 2 ? f[2] : NULL), b = num(k > 3 ? f[3] : NULL),
                         c = num(k > 4 ? f[4] : NULL);
            s += c;
            if (!rows || a < *mn)
                *mn = a;
            if (b > *mx)
                *mx = b;
            rows++;
        }
    *mean = rows ? s / rows : 0;
    return rows;
}

/* ---- a resumed run ---------------------------------------------------------------------- */
#define SWE_JOIN_MAXC 256
typedef struct {
    char name[SWE_JOIN_MAXC][64];
    double v[SWE_JOIN_MAXC];
    int n;
} wall_set;

static double *wall_slot(wall_set *w, const char *name)
{
    for (int i = 0; i < w->n; i++)
        if (!strcmp(w->name[i], name))
            return &w->v[i];
    if (w->n == SWE_JOIN_MAXC)
        return NULL;
    snprintf(w->name[w->n], sizeof w->name[0], "%s", name);
    w->v[w->n] = 0;
    return &w->v[w->n++];
}

int swe_join_logs(FILE *const *parts, int n, FILE *out, char *err, size_t nerr)
{
    static char line[1 << 16];
    char tok[128];
    double *start = calloc((size_t)n + 1, sizeof *start);
    int *has = calloc((size_t)n + 1, sizeof *has);
    wall_set *off = calloc(1, sizeof *off), *last = calloc(1, sizeof *last);
    if (!start || !has || !off || !last) {
        free(start), free(has), free(off), free(last);
        return fail(err, nerr, 1, "out of memory");
    }
    /* first: each part's start, its first step's time less the deltaT before it */
    for (int i = 0; i < n; i++) {
        double dt = 0;
        while (fgets(line, sizeof line, parts[i])) {
            if (!strncmp(line, "deltaT = ", 9))
                dt = num(field(line, 3, tok, sizeof tok));
            else if (!strncmp(line, "Time = ", 7) && !has[i]) {
                start[i] = num(field(line, 3, tok, sizeof tok)) - dt;
                has[i] = 1;
            }
        }
        rewind(parts[i]);
    }
    for (int i = 0; i < n; i++) {
        int cut_has = 0;
        double cut = 0;
        for (int j = i + 1; j < n && !cut_has; j++)
            if (has[j]) {
                cut = start[j];
                cut_has = 1;
            }
        for (int c = 0; c < last->n; c++) {
            double *o = wall_slot(off, last->name[c]);
            if (o)
                *o += last->v[c];
        }
        last->n = 0;
        while (fgets(line, sizeof line, parts[i])) {
            if (!strncmp(line, "Time = ", 7) && cut_has &&
                num(field(line, 3, tok, sizeof tok)) > cut + 1e-9 * fabs(cut) + 1e-12)
                break;
            if (strncmp(line, "Wall time [s]", 13)) {
                fputs(line, out);
                if (!strchr(line, '\n'))
                    fputc('\n', out);
                continue;
            }
            chomp(line);
            char *colon = strchr(line, ':');
            if (!colon) { /* no entries: the line as it is */
                fprintf(out, "%s\n", line);
                continue;
            }
            fprintf(out, "%.*s", (int)(colon - line + 1), line);
            char *p = colon + 1;
            while (*p == ' ')
                p++;
            for (int k = 0; *p; k++) {
                char *e = strchr(p, ',');
                if (e)
                    *e = 0;
                char name[64], val[128];
                field(p, 1, name, sizeof name);
                field(p, 2, val, sizeof val);
                double *l = wall_slot(last, name), *o = wall_slot(off, name);
                if (l)
                    *l = num(val);
                fprintf(out, "%s%s %.10g", k ? ", " : " ", name, num(val) + (o ? *o : 0));
                if (!e)
                    break;
                p = e + 1;
                while (*p == ' ')
                    p++;
            }
            fputc('\n', out);
        }
    }
    free(start), free(has), free(off), free(last);
    return 0;
}

int swe_join_table(FILE *base, FILE *add, double t, FILE *out)
{
    static char line[1 << 16];
    char tok[128];
    while (fgets(line, sizeof line, base))
        if (line[0] == '#' || num(field(line, 1, tok, sizeof tok)) <= t + 1e-9 * t + 1e-12)
            fputs(line, out);
    while (fgets(line, sizeof line, add))
        if (line[0] != '#')
            fputs(line, out);
    return 0;
}

/* a time folder's name: a digit, then digits, '.', 'e', '+', '-' */
static int is_time_name(const char *s)
{
    if (*s < '0' || *s > '9')
        return 0;
    for (; *s; s++)
        if (!strchr("0123456789.e+-", *s))
            return 0;
    return 1;
}

typedef struct {
    char name[256];
    double v;
} tname;

static int tname_desc(const void *a, const void *b)
{
    const tname *x = a, *y = b;
    return x->v < y->v ? 1 : x->v > y->v ? -1 : -strcmp(x->name, y->name);
}

/* the time folders (names) of dir, latest first; returns their count, -1 unreadable */
static int time_names(const char *dir, tname **out)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0, cap = 0;
    tname *t = NULL;
    for (struct dirent *e; (e = readdir(d));) {
        if (!is_time_name(e->d_name) || strlen(e->d_name) >= sizeof t->name)
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            tname *u = realloc(t, (size_t)cap * sizeof *t);
            if (!u)
                break;
            t = u;
        }
        snprintf(t[n].name, sizeof t[n].name, "%s", e->d_name);
        t[n].v = strtod(e->d_name, NULL);
        n++;
    }
    closedir(d);
    if (n)
        qsort(t, (size_t)n, sizeof *t, tname_desc);
    *out = t;
    return n;
}

static int nonempty_file(const char *path)
{
    struct stat st;
    return !stat(path, &st) && st.st_size > 0;
}

int swe_resume_time(const char *case_dir, int nproc, char *t, size_t n, char *err, size_t nerr)
{
    char root[4096], path[8192];
    t[0] = 0;
    for (int r = 0; nproc > 1 && r < nproc; r++) {
        struct stat st;
        snprintf(root, sizeof root, "%s/processor%d", case_dir, r);
        if (stat(root, &st) || !S_ISDIR(st.st_mode))
            return fail(err, nerr, 2, "-resume: processor%d is missing (the run was on %d processes; nothing "
                        "to resume)", r, nproc);
    }
    if (nproc > 1)
        snprintf(root, sizeof root, "%s/processor0", case_dir);
    else
        snprintf(root, sizeof root, "%s", case_dir);
    tname *tn = NULL;
    const int k = time_names(root, &tn);
    const char *fields[] = {"uniform/time", "U", "p", "k", "omega", "nut"};
    for (int i = 0; i < k && !t[0]; i++) {
        if (!(tn[i].v > 0))
            continue;
        int ok = 1;
        for (int r = 0; ok && r < (nproc > 1 ? nproc : 1); r++)
            for (size_t f = 0; ok && f < sizeof fields / sizeof *fields; f++) {
                if (nproc > 1)
                    snprintf(path, sizeof path, "%s/processor%d/%s/%s", case_dir, r, tn[i].name, fields[f]);
                else
                    snprintf(path, sizeof path, "%s/%s/%s", case_dir, tn[i].name, fields[f]);
                ok = nonempty_file(path);
            }
        if (ok)
            snprintf(t, n, "%s", tn[i].name);
    }
    free(tn);
    return 0;
}

static int name_cmp(const struct dirent **a, const struct dirent **b)
{
    return strcmp((*a)->d_name, (*b)->d_name);
}

int swe_restart_tables(const char *dir, const char *t, int mode, FILE *out, char *err, size_t nerr)
{
    struct dirent **sub = NULL;
    const int ns = scandir(dir, &sub, NULL, name_cmp);
    int rc = 0;
    char tdir[4096], first[8192], add[8192], tmp[8300];
    for (int i = 0; i < ns; i++) {
        const char *name = sub[i]->d_name;
        struct stat st;
        snprintf(tdir, sizeof tdir, "%s/%s/%s", dir, name, t);
        if (!rc && name[0] != '.' && strcmp(name, "lagrangian") && !stat(tdir, &st) && S_ISDIR(st.st_mode)) {
            char named[4096];
            snprintf(named, sizeof named, "%s/%s", dir, name);
            tname *tn = NULL;
            const int k = time_names(named, &tn);
            const char *base = k > 0 ? tn[k - 1].name : NULL; /* the first (lowest) time */
            struct dirent **files = NULL;
            const int nf = base && strcmp(base, t) ? scandir(tdir, &files, NULL, name_cmp) : 0;
            for (int j = 0; j < nf; j++) {
                snprintf(add, sizeof add, "%s/%s", tdir, files[j]->d_name);
                snprintf(first, sizeof first, "%s/%s/%s", named, base, files[j]->d_name);
                struct stat sa, sb;
                if (!rc && !stat(add, &sa) && S_ISREG(sa.st_mode) && !stat(first, &sb) && S_ISREG(sb.st_mode)) {
                    if (mode == SWE_TABLES_LIST)
                        fprintf(out, "%s %s\n", first, add);
                    else if (mode == SWE_TABLES_REMOVE)
                        remove(add);
                    else {
                        snprintf(tmp, sizeof tmp, "%s.joined", add);
                        FILE *a = fopen(first, "r"), *b = fopen(add, "r"), *o = fopen(tmp, "w");
                        int ok = a && b && o && !swe_join_table(a, b, strtod(t, NULL), o);
                        if (a)
                            fclose(a);
                        if (b)
                            fclose(b);
                        if (o && fclose(o))
                            ok = 0;
                        if (!ok || rename(tmp, first) || remove(add))
                            rc = fail(err, nerr, 1, "could not join %s", add);
                    }
                }
                free(files[j]);
            }
            free(files);
            free(tn);
        }
        free(sub[i]);
    }
    free(sub);
    if (mode == SWE_TABLES_JOIN && !rc) {
        DIR *d = opendir(dir);
        for (struct dirent *e; d && (e = readdir(d));) {
            snprintf(tdir, sizeof tdir, "%s/%s/%s", dir, e->d_name, t);
            if (e->d_name[0] != '.')
                rmdir(tdir); /* only when empty */
        }
        if (d)
            closedir(d);
    }
    return rc;
}

/* ---- the total error against a resolution ladder ------------------------------------------ */
/* two values equal as awk compares them: as numbers when both are, else as text */
static int awk_equal(const char *a, const char *b)
{
    char *ea, *eb;
    const double x = strtod(a, &ea), y = strtod(b, &eb);
    if (ea != a && eb != b && !*ea && !*eb)
        return x == y;
    return !strcmp(a, b);
}

/* the CSV fields of a line (split on ','), at most max; returns their count */
static int csv_split(char *line, char **f, int max)
{
    int k = 0;
    f[k++] = line;
    for (char *c = line; *c; c++)
        if (*c == ',') {
            *c = 0;
            if (k < max)
                f[k++] = c + 1;
        }
    return k;
}

int swe_ladder_why(FILE *ladder, const char *const *settings, int nset, const char *level,
                   const char *cells, char *why, size_t n)
{
    static char line[1 << 14];
    char tok[4][256];
    size_t l = 0;
    why[0] = 0;
    for (int s = 0; s < nset; s++) {
        const char *kv = settings[s], *v = strchr(kv, ' ');
        if (!v)
            continue;
        char key[256];
        snprintf(key, sizeof key, "%.*s", (int)(v - kv), kv);
        v++;
        rewind(ladder);
        while (fgets(line, sizeof line, ladder)) {
            if (strcmp(field(line, 1, tok[0], 256), "#") || strcmp(field(line, 2, tok[1], 256), "setting") ||
                strcmp(field(line, 3, tok[2], 256), key))
                continue;
            field(line, 4, tok[3], 256);
            if (tok[3][0] && strcmp(tok[3], v))
                l += (size_t)snprintf(why + l, l < n ? n - l : 0, "%s%s %s here, %s on the ladder",
                                      l ? "; " : "", key, v, tok[3]);
            break;
        }
    }
    rewind(ladder);
    char lc[256] = "";
    int found = 0;
    while (!found && fgets(line, sizeof line, ladder)) {
        chomp(line);
        if (line[0] == '#')
            continue;
        char *f[16] = {0};
        const int k = csv_split(line, f, 16);
        if (k >= 4 && awk_equal(f[3], level)) {
            snprintf(lc, sizeof lc, "%s", k >= 5 ? f[4] : "");
            found = 1;
        }
    }
    if (!found || !lc[0])
        l += (size_t)snprintf(why + l, l < n ? n - l : 0, "%slevel %s is not on the ladder", l ? "; " : "",
                              level);
    else if (strcmp(lc, cells))
        l += (size_t)snprintf(why + l, l < n ? n - l : 0,
                              "%slevel %s has %s cells on the ladder, %s here (another mesh: -test, "
                              "-fine, -refine-wake or -no-rear-layers)",
                              l ? "; " : "", level, lc, cells);
    return 0;
}

void swe_ladder_notes(FILE *ladder, FILE *out)
{
    static char line[1 << 14];
    char a[16], b[16];
    int n = 0;
    rewind(ladder);
    while (fgets(line, sizeof line, ladder)) {
        chomp(line);
        if (strcmp(field(line, 1, a, sizeof a), "#") || strcmp(field(line, 2, b, sizeof b), "note"))
            continue;
        if (!n++)
            fputs("\n## Notes of the ladder file (what its total leaves out, how to read it)\n\n", out);
        fprintf(out, "* %s\n", strncmp(line, "# note ", 7) ? line : line + 7);
    }
}

/* a relative error in %: one decimal below 9.95 %, none above */
static void pc(char *s, size_t n, double x)
{
    snprintf(s, n, x < 9.95 ? "%.1f %%" : "%.0f %%", x);
}

static int ends_with(const char *s, const char *suffix)
{
    const size_t a = strlen(s), b = strlen(suffix);
    return a >= b && !strcmp(s + a - b, suffix);
}

int swe_total_error_table(FILE *csv, const char *run, const char *mvd, const char *ladder,
                          const char *level, const char *cells, FILE *out)
{
    static char line[1 << 14];
    size_t cap[3] = {4096, 4096, 4096}, len[3] = {0, 0, 0};
    char *rows[3];
    for (int i = 0; i < 3; i++) {
        rows[i] = malloc(cap[i]);
        if (!rows[i])
            return 1;
        rows[i][0] = 0;
    }
    char suffix[128], facekey[128], face[256] = "";
    snprintf(suffix, sizeof suffix, "-mvd%s", mvd);
    snprintf(facekey, sizeof facekey, "face-mvd%s", mvd);
    for (int nr = 1; fgets(line, sizeof line, csv); nr++) {
        if (nr == 1)
            continue;
        chomp(line);
        char *f[14] = {0};
        const int k = csv_split(line, f, 14);
        for (int i = k; i < 14; i++)
            f[i] = "";
        if (strcmp(f[1], run))
            continue;
        const char *q = f[0];
        char label[256];
        double scale = 1;
        int ord;
        if (ends_with(q, suffix)) {
            char r[128];
            snprintf(r, sizeof r, "%.*s", (int)(strlen(q) - strlen(suffix)), q);
            if (!strcmp(r, "face"))
                snprintf(label, sizeof label, "whole face [g / 30 min]");
            else if (!strcmp(r, "left") || !strcmp(r, "right"))
                snprintf(label, sizeof label, "%s side [g / 30 min]", r);
            else
                snprintf(label, sizeof label, "%s [g / 30 min]", r);
            scale = 1000;
            ord = 0;
        } else if (!strncmp(q, "capture-", 8)) {
            snprintf(label, sizeof label, "class %s [ppm]", q + 8);
            ord = 1;
        } else if (!strcmp(q, "Cd") || !strcmp(q, "Cp_b") || !strcmp(q, "St")) {
            snprintf(label, sizeof label, "%s", q);
            ord = 2;
        } else
            continue;
        const double ref = num(f[11]), a = ref < 0 ? -ref : ref;
        char s[32] = "-", d[32] = "-", t[32] = "-", row[1024];
        if (a > 0) {
            pc(s, sizeof s, 100 * num(f[7]) / a);
            pc(d, sizeof d, 100 * num(f[8]) / a);
        }
        if (f[10][0])
            pc(t, sizeof t, 100 * num(f[10]));
        const int l = snprintf(row, sizeof row, "| %s | %.4g | %s | %s | %s | %.4g | %s |\n", label,
                               num(f[6]) * scale, s, d, t, ref * scale, f[12]);
        if (len[ord] + (size_t)l + 1 > cap[ord]) {
            cap[ord] = 2 * (len[ord] + (size_t)l + 1);
            char *r = realloc(rows[ord], cap[ord]);
            if (!r)
                return 1;
            rows[ord] = r;
        }
        memcpy(rows[ord] + len[ord], row, (size_t)l + 1);
        len[ord] += (size_t)l;
        if (!strcmp(q, facekey) && a > 0) {
            char tt[32];
            pc(tt, sizeof tt, 100 * num(f[10]));
            snprintf(face, sizeof face, "%s (sampling %s, discretization %s)", tt, s, d);
        }
    }
    fprintf(out, "# Total error of the rear deposit\n\n");
    fprintf(out,
            "This run judged against the resolution ladder of %s: its level %s (%s cells) is on it, so "
            "its discretization error is the one of its level on the ladder: the distance of the value "
            "of the level from the reference, combined with the uncertainty of the reference itself "
            "(snowladder total: the Richardson extrapolation where the finest three levels converge "
            "monotonically, else the finest value with its last change as its uncertainty). The total "
            "error combines it with the sampling error of this run, sqrt(sampling^2 + "
            "discretization^2); all three relative to the reference. The whole judgement: "
            "results/ladder/ (ladder.md, total_error.csv, total_error.png).\n\n",
            ladder, level, cells);
    if (!face[0])
        fprintf(out, "Rear face, decided spray (MVD %s um): no relative total error (the reference is 0).\n\n",
                mvd);
    else
        fprintf(out, "Rear face, decided spray (MVD %s um): total error %s.\n\n", mvd, face);
    fprintf(out, "| quantity | this run | sampling | discretization | total | reference | reference from "
                 "|\n|---|---:|---:|---:|---:|---:|---|\n");
    for (int i = 0; i < 3; i++) {
        fputs(rows[i], out);
        free(rows[i]);
    }
    return 0;
}
