/* swe_run.c - the numbers tutorials/wedge/Allrun computes or formats (swe_run.h).
 * The formats follow the files Allrun has always written: a value read as text
 * (a time, a setting) is copied as text, a computed one printed with the
 * precision the file has always had. */
#include "swe_run.h"
#include "swe_run_text.h"
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
 *   the memory    2 kB per cell, the replay library (snapshots x cells x 10 values x
 *                 8 bytes x 1.1 for the boundaries: U p k omega nut, 7 a cell, and
 *                 phi, one a face, about 3 a cell; streamed from disk, two snapshots in
 *                 memory, when the flow, the library and the parcels would exceed 80 % of
 *                 the available memory) and 560 B per parcel, every parcel
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
        in->replay ? (in->replay_period / in->replay_interval) * cells * 10 * 8 * 1.1 : 0;
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
    o->mem_parcels = (bspray + bcls + pwake) * 560;
    /* a library that would take the flow and the parcels above 80 % of the memory is
       streamed from its stored snapshots (Allrun: stream yes), two of them in memory */
    o->streamed =
        in->replay && in->avail >= 0 && cells * 2048 + lib + o->mem_parcels > 0.8 * in->avail;
    o->mem_flow = cells * 2048 + (o->streamed ? 2 * lib / (in->replay_period / in->replay_interval) : lib);
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
               "%s%.2g GB replay library%s, parcels at most %.2g GB), %s available; disk %.2g GB "
               "(fields and the stored flow library %.2g GB, parcel records at most %.2g GB), %s "
               "free; time about %.2g min on %d process(es) (flow %.2g, particles %.2g min, and "
               "about 2 min of set-up and post-processing; scaled from the default run measured on "
               "this machine)\n",
            (long)o->cells, o->clouds, (long)o->parcels, (long)o->class_parcels, (long)o->steps,
            (long)o->flow_steps, (o->mem_flow + o->mem_parcels) / GB, o->mem_flow / GB,
            o->streamed ? "two snapshots of a " : "a ", o->lib / GB,
            o->streamed ? " streamed from disk: it does not fit" : "", o->mem_parcels / GB, av, (o->disk_fields + o->disk_parcels) / GB, o->disk_fields / GB,
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
                    "and %ld snapshots x %ld cells x 10 values x 8 bytes x 1.1), more than the %.3g "
                    "GB available (MemAvailable), even with the library streamed: refused; use -coupled, a longer "
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

int swe_last_time(const char *path, char *out, size_t n)
{
    FILE *f = fopen(path, "r");
    out[0] = '\0';
    if (!f)
        return 1;
    /* backwards from the end in blocks, each overlapping the next by a line's length */
    enum { BLOCK = 1 << 16, OVERLAP = 1 << 10 };
    char *buf = malloc(BLOCK + 1);
    long end = fseek(f, 0, SEEK_END) ? -1 : ftell(f);
    while (buf && end > 0 && !out[0]) {
        const long start = end > BLOCK ? end - BLOCK : 0;
        const size_t len = (size_t)(end - start);
        if (fseek(f, start, SEEK_SET) || fread(buf, 1, len, f) != len)
            break;
        buf[len] = '\0';
        /* the last "Time = " at the start of a line wholly inside the block */
        for (long i = (long)len - 1; i >= 0 && !out[0]; i--) {
            if ((i > 0 && buf[i - 1] != '\n') || (i == 0 && start > 0) || strncmp(buf + i, "Time = ", 7))
                continue;
            const char *eol = strchr(buf + i, '\n');
            if (!eol && start + (long)len < end)
                continue;
            char line[256];
            snprintf(line, sizeof line, "%.*s", (int)(eol ? eol - (buf + i) : (long)strlen(buf + i)), buf + i);
            char *save = NULL, *f1 = strtok_r(line, " \t", &save), *f2 = strtok_r(NULL, " \t", &save);
            const char *f3 = f1 && f2 ? strtok_r(NULL, " \t", &save) : NULL;
            snprintf(out, n, "%s", f3 ? f3 : "");
            if (!f3) /* "Time =" alone: awk's $3 is empty, the reading skipped */
                break;
        }
        if (out[0] || start == 0)
            break;
        end = start + OVERLAP;
    }
    free(buf);
    fclose(f);
    return 0;
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
                       double mass_total, const char *duration, double size_um, int wake, const char *speed)
{
    fprintf(f, "// generated by Allrun (write_nozzles): %d nozzles, %ld parcels each\n", np, parcels);
    for (int i = 0; i < np; i++) {
        fprintf(f, "nozzle%d\n{\n    type coneInjection;\n    SOI %s;\n    massTotal %.10g;\n", i, soi,
                mass_total / np);
        fprintf(f, "    parcelBasisType mass;\n    duration %s;\n    parcelsPerInjector %ld;\n"
                   "    flowRateProfile constant 1;\n",
                duration, parcels);
        fprintf(f, "    Umag constant %s;\n    thetaInner constant 0;\n    thetaOuter constant %s;\n",
                wake ? "1" : speed ? speed : "19.444", wake ? "90" : "6");
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
