/* swe_cmd_run.c - snowwedge spray-check, estimate, mesh, times, progress, nozzles, decompose, level, yplus,
 * join-logs, join-table, resume-time, restart-tables, resume-start, resume-join, ladder-check, total-error:
 * the numbers and files of
 * tutorials/wedge/Allrun (swe_run.h). These commands parse their own options. */
#include "swe_cli.h"
#include "swe_run.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct {
    const char *name; /* "--x" */
    int flag;         /* 1: no value */
    const char *value;
    int given;
} run_opt;

/* the options of argv[2..] into opts; the rest into pos (at most argc) */
static int run_parse(int argc, char **argv, run_opt *opts, const char **pos)
{
    int npos = 0;
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(swe_cli_usage, stdout);
            exit(0);
        }
        if (strncmp(a, "--", 2) || !a[2]) {
            pos[npos++] = a;
            continue;
        }
        run_opt *o = opts;
        while (o->name && strcmp(o->name, a))
            o++;
        if (!o->name)
            swe_cli_die(2, "%s: unknown option '%s' (see --help)", argv[1], a);
        o->given = 1;
        if (o->flag)
            continue;
        if (i + 1 >= argc)
            swe_cli_die(2, "%s needs a value (see --help)", a);
        o->value = argv[++i];
    }
    return npos;
}

static run_opt *get(run_opt *opts, const char *name)
{
    for (run_opt *o = opts; o->name; o++)
        if (!strcmp(o->name, name))
            return o;
    return NULL;
}

static const char *need(run_opt *opts, const char *name, const char *cmd)
{
    const run_opt *o = get(opts, name);
    swe_cli_need(name, o && o->given ? o->value : NULL, cmd);
    return o->value;
}

static const char *val(run_opt *opts, const char *name, const char *def)
{
    const run_opt *o = get(opts, name);
    return o && o->given ? o->value : def;
}

static int flag(run_opt *opts, const char *name)
{
    const run_opt *o = get(opts, name);
    return o && o->given;
}

static double number(run_opt *opts, const char *name, const char *cmd)
{
    return swe_cli_number(name, need(opts, name, cmd));
}

/* a number of a count or a duration: in (0, max], else exit 2 naming the option
   and the value (a negative, zero or huge count would print a nonsense estimate) */
static double positive(run_opt *opts, const char *name, const char *cmd, double max)
{
    const double v = number(opts, name, cmd);
    if (!(v > 0 && v <= max))
        swe_cli_die(2, "%s: '%s' is not in (0, %g]", name, val(opts, name, ""), max);
    return v;
}

/* the items of a list separated by blanks and commas, as numbers (awk's reading) */
static int list_numbers(const char *s, double *v, int max)
{
    int n = 0;
    const char *p = s;
    while (*p && n < max) {
        while (*p == ' ' || *p == ',')
            p++;
        if (!*p)
            break;
        v[n++] = strtod(p, NULL);
        while (*p && *p != ' ' && *p != ',')
            p++;
    }
    return n;
}

static void read_mesh(const char *text, swe_mesh *m)
{
    char err[512];
    if (swe_mesh_parse(text, m, err, sizeof err))
        swe_cli_die(2, "%s", err);
    const char *keys[] = {"nxUp", "nxBody", "nxDown", "nBody", "nOut"};
    for (int i = 0; i < 5; i++)
        if (swe_mesh_get(m, keys[i]) < 0)
            swe_cli_die(2, "the mesh '%s' has no %s", text, keys[i]);
}

/* a number through the text "%.12g" of it, as the script passed it on */
static double g12(double x)
{
    char b[64];
    snprintf(b, sizeof b, "%.12g", x);
    return strtod(b, NULL);
}

/* a command of options only: any other argument refused (exit 2) */
static void options_only(int argc, char **argv, run_opt *opts, const char *cmd)
{
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) != 0)
        swe_cli_die(2, "%s: no file arguments (see --help)", cmd);
    free(pos);
}

static int cmd_mesh(int argc, char **argv)
{
    run_opt opts[] = {{"--level", 0, 0, 0}, {"--refine-wake", 1, 0, 0}, {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) != 1)
        swe_cli_die(2, "mesh: give one mesh \"KEY N; ...\" (see --help)");
    const double lv = swe_cli_number("--level", val(opts, "--level", "0"));
    if (lv != floor(lv) || fabs(lv) > 10)
        swe_cli_die(2, "--level: '%s' is not a whole number from -10 to 10", val(opts, "--level", ""));
    swe_mesh m;
    read_mesh(pos[0], &m);
    char out[1024];
    if (lv != 0 || flag(opts, "--refine-wake")) {
        swe_mesh_scale(&m, (int)lv, flag(opts, "--refine-wake"));
        swe_mesh_format(&m, out, sizeof out);
    } else
        snprintf(out, sizeof out, "%s", pos[0]);
    printf("%s\n%ld\n%.12g\n", out, swe_mesh_ny(&m), swe_level_scale((int)lv));
    free(pos);
    return 0;
}

static int cmd_estimate(int argc, char **argv)
{
    run_opt opts[] = {{"--route", 0, 0, 0},        {"--mesh", 0, 0, 0},
                      {"--nozzle-array", 0, 0, 0}, {"--ppn", 0, 0, 0},
                      {"--ppn-factor", 0, 0, 0},   {"--sizes", 0, 0, 0},
                      {"--class-parcels", 0, 0, 0}, {"--class-factor", 0, 0, 0},
                      {"--dispersion", 0, 0, 0},   {"--spin", 0, 0, 0},
                      {"--fill", 0, 0, 0},         {"--sample", 0, 0, 0},
                      {"--replay-start", 0, 0, 0}, {"--replay-period", 0, 0, 0},
                      {"--replay-interval", 0, 0, 0}, {"--max-delta-t", 0, 0, 0},
                      {"--level-scale", 0, 0, 0},  {"--np", 0, 0, 0},
                      {"--avail", 0, 0, 0},        {"--free", 0, 0, 0},
                      {"--compare", 1, 0, 0},      {"--feedback", 1, 0, 0},
                      {"--rough", 1, 0, 0},        {"--rebound", 1, 0, 0},
                      {"--split", 1, 0, 0},        {"--full", 1, 0, 0},
                      {"--halfstep", 1, 0, 0},     {"--rear-layers", 1, 0, 0},
                      {"--replay", 1, 0, 0},       {"--wake-source", 1, 0, 0},
                      {0}};
    options_only(argc, argv, opts, "estimate");
    const char *C = "estimate";
    swe_estimate_in in = {0};
    const char *route = val(opts, "--route", "transient");
    if (strcmp(route, "transient") && strcmp(route, "steady"))
        swe_cli_die(2, "--route: '%s' is not transient or steady", route);
    in.steady = !strcmp(route, "steady");
    swe_mesh m;
    read_mesh(need(opts, "--mesh", C), &m);
    in.cells0 = swe_mesh_cells(&m);
    in.nbody = (double)swe_mesh_get(&m, "nBody");
    char err[512];
    char(*pts)[128] = NULL;
    in.nozzles = swe_nozzle_points(need(opts, "--nozzle-array", C), &pts, err, sizeof err);
    if (in.nozzles < 0)
        swe_cli_die(1, "%s", err);
    free(pts);
    in.ppn = positive(opts, "--ppn", C, 1e9);
    in.ppn_factor = positive(opts, "--ppn-factor", C, 1e6);
    const double np = swe_cli_number("--np", val(opts, "--np", "1"));
    if (!(np >= 1 && np <= 1e6 && np == (int)np))
        swe_cli_die(2, "--np: '%s' is not a whole number of processes from 1 to 1e6", val(opts, "--np", ""));
    in.np = (int)np;
    in.compare = flag(opts, "--compare");
    if (!in.steady) {
        double cls[256], sizes[256];
        const int nsizes = list_numbers(val(opts, "--sizes", ""), sizes, 256);
        /* without --class-parcels every class has the spray's parcels per nozzle */
        const char *cp = val(opts, "--class-parcels", NULL);
        in.nclasses = nsizes ? cp ? list_numbers(cp, cls, 256) : nsizes : 0;
        for (int i = 0; !cp && i < nsizes; i++)
            cls[i] = in.ppn;
        for (int i = 0; i < in.nclasses; i++)
            if (!(cls[i] > 0 && cls[i] <= 1e9))
                swe_cli_die(2, "--class-parcels: '%s': every item must be in (0, 1e+09]", cp);
        in.class_ppn = cls;
        in.class_factor = positive(opts, "--class-factor", C, 1e6);
        in.ndisp = 1;
        for (const char *d = val(opts, "--dispersion", ""); *d; d++)
            in.ndisp += *d == ',';
        in.nwake = flag(opts, "--wake-source") ? nsizes : 0;
        in.feedback = flag(opts, "--feedback");
        in.rough = flag(opts, "--rough");
        in.rebound = flag(opts, "--rebound");
        in.split = flag(opts, "--split");
        in.full = flag(opts, "--full");
        in.halfstep = flag(opts, "--halfstep");
        in.rear_layers = flag(opts, "--rear-layers");
        in.replay = flag(opts, "--replay");
        in.spin = positive(opts, "--spin", C, 1e6);
        in.fill = positive(opts, "--fill", C, 1e6);
        in.sample = positive(opts, "--sample", C, 1e6);
        in.replay_interval = 1;
        if (in.replay) {
            in.replay_start = number(opts, "--replay-start", C);
            in.replay_period = number(opts, "--replay-period", C);
            const char *ri = need(opts, "--replay-interval", C), *mdt = val(opts, "--max-delta-t", "");
            in.replay_interval = swe_cli_number("--replay-interval", ri);
            /* the solver refuses this too, at its set-up: here before anything is written */
            if (*mdt && swe_cli_number("--max-delta-t", mdt) > in.replay_interval * (1 + 1e-9))
                swe_cli_die(2, "constant/sprayProperties: replayInterval %s s is shorter than the run's "
                               "maxDeltaT %s s (system/controlDict.transient%s): a time step may then "
                               "skip snapshots of the flow library; give a replayInterval of at least "
                               "%s s (or a maxDeltaT of at most %s s there)",
                            ri, mdt, in.halfstep ? ", -halfstep" : "", mdt, ri);
        }
        /* -level N: the library's interval scales with the step */
        in.replay_interval = g12(in.replay_interval * swe_cli_number("--level-scale",
                                                                     val(opts, "--level-scale", "1")));
        const char *av = val(opts, "--avail", ""), *fr = val(opts, "--free", "");
        in.avail = *av ? swe_cli_number("--avail", av) : -1;
        in.free_disk = *fr ? swe_cli_number("--free", fr) : -1;
        swe_estimate_out out;
        swe_estimate(&in, &out);
        swe_estimate_print(stdout, &in, &out);
        if (swe_estimate_refuse(&in, &out, err, sizeof err)) {
            fflush(stdout);
            swe_cli_die(2, "%s", err);
        }
        return 0;
    }
    swe_estimate_out out;
    swe_estimate(&in, &out);
    swe_estimate_print(stdout, &in, &out);
    return 0;
}

static int cmd_spray_check(int argc, char **argv)
{
    run_opt opts[] = {{"--mvd", 0, 0, 0},   {"--sigma-g", 0, 0, 0}, {"--freeze", 0, 0, 0},
                      {"--range", 0, 0, 0}, {"--sizes", 0, 0, 0},   {"--class-parcels", 0, 0, 0},
                      {0}};
    options_only(argc, argv, opts, "spray-check");
    const char *C = "spray-check", *r = need(opts, "--range", C), *c = strchr(r, ',');
    if (!c)
        swe_cli_die(2, "--range: '%s' is not MIN,MAX", r);
    char lo[128], err[1024];
    snprintf(lo, sizeof lo, "%.*s", (int)(c - r), r);
    if (swe_check_spray(need(opts, "--mvd", C), need(opts, "--sigma-g", C), need(opts, "--freeze", C), lo, c + 1,
                        err, sizeof err))
        swe_cli_die(2, "%s", err);
    const char *sz = val(opts, "--sizes", NULL);
    if (sz && swe_check_classes(sz, need(opts, "--class-parcels", C), err, sizeof err))
        swe_cli_die(2, "%s", err);
    return 0;
}

static int cmd_times(int argc, char **argv)
{
    run_opt opts[] = {{"--spin", 0, 0, 0},          {"--fill", 0, 0, 0},           {"--sample", 0, 0, 0},
                      {"--class-factor", 0, 0, 0},  {"--rate", 0, 0, 0},           {"--build-up", 0, 0, 0},
                      {"--replay-start", 0, 0, 0},  {"--replay-period", 0, 0, 0},  {"--replay-interval", 0, 0, 0},
                      {"--level", 0, 0, 0},         {"--level-scale", 0, 0, 0},    {"--checkpoint", 0, 0, 0},
                      {"--full", 1, 0, 0},          {"--halfstep", 1, 0, 0},       {0}};
    options_only(argc, argv, opts, "times");
    const char *C = "times";
    const char *num_opts[] = {"--spin", "--fill", "--sample", "--class-factor", "--rate", "--build-up"};
    for (size_t i = 0; i < sizeof num_opts / sizeof *num_opts; i++)
        if (!(number(opts, num_opts[i], C) > 0))
            swe_cli_die(2, "%s: '%s' is not a positive number", num_opts[i], val(opts, num_opts[i], ""));
    const char *ri = val(opts, "--replay-interval", NULL);
    swe_times_in in = {.spin = val(opts, "--spin", ""), .fill = val(opts, "--fill", ""),
                       .sample = val(opts, "--sample", ""), .class_factor = val(opts, "--class-factor", ""),
                       .rate = val(opts, "--rate", ""), .build_up = val(opts, "--build-up", ""),
                       .replay_interval = ri, .level_scale = val(opts, "--level-scale", "1"),
                       .checkpoint_min = val(opts, "--checkpoint", "off"),
                       .level = (int)swe_cli_number("--level", val(opts, "--level", "0")),
                       .full = flag(opts, "--full"), .halfstep = flag(opts, "--halfstep")};
    if (ri) {
        in.replay_start = need(opts, "--replay-start", C);
        in.replay_period = need(opts, "--replay-period", C);
        if (!(swe_cli_number("--replay-interval", ri) > 0))
            swe_cli_die(2, "--replay-interval: '%s' is not a positive number", ri);
    }
    swe_times_out o;
    char err[512];
    if (swe_times(&in, &o, err, sizeof err))
        swe_cli_die(2, "%s", err);
    printf("class_factor %s\ntsample %s\nt0 %s\nth %s\nt1 %s\ntwrite %s\nsoi %s\nmass_total %s\n"
           "duration %s\nsampled %s\nstep_scale %s\nmaxdt %s\nlevel_delta_t %s\n",
           o.class_factor, o.sample, o.t0, o.th, o.t1, o.write, o.soi, o.mass_total, o.duration, o.sampled,
           o.step_scale, o.max_delta_t, o.delta_t);
    if (ri)
        printf("rint %s\nlibrary_end %s\n", o.replay_interval, o.library_end);
    if (o.checkpoint_s[0])
        printf("checkpoint_s %s\n", o.checkpoint_s);
    return 0;
}

/* --watch LOG: every --interval seconds (default 30) while the process --pid runs, the
   line for LOG's last step; with --flow-end the solved flow and the replay timed apart */
static int progress_watch(run_opt *opts, const char *log, double t_end, double t_flow)
{
    const char *C = "progress";
    const long pid = (long)number(opts, "--pid", C), t_start = (long)number(opts, "--allrun-start", C);
    const double every = positive(opts, "--interval", C, 3600);
    const time_t w0 = time(NULL);
    time_t ws = w0;
    int replay = 0;
    double ts = -1;
    const struct timespec nap = {(time_t)every, (long)((every - floor(every)) * 1e9)};
    while (!nanosleep(&nap, NULL) && !kill((pid_t)pid, 0)) {
        char t_s[128], *end, line[512];
        if (swe_last_time(log, t_s, sizeof t_s) || !t_s[0])
            continue;
        const double t = strtod(t_s, &end);
        if (*end)
            continue;
        if (t_flow >= 0 && !replay && t >= t_flow)
            replay = 1, ts = -1;
        if (ts < 0)
            ts = t, ws = time(NULL);
        const time_t now = time(NULL);
        swe_progress_line(line, sizeof line, t, t_end, t_flow, replay, ts, (long)(now - w0), (long)(now - ws),
                          (long)now - t_start);
        puts(line);
        fflush(stdout);
    }
    return 0;
}

static int cmd_progress(int argc, char **argv)
{
    run_opt opts[] = {{"--time", 0, 0, 0},        {"--end", 0, 0, 0},          {"--flow-end", 0, 0, 0},
                      {"--phase", 0, 0, 0},       {"--phase-start", 0, 0, 0},  {"--elapsed", 0, 0, 0},
                      {"--phase-elapsed", 0, 0, 0}, {"--allrun", 0, 0, 0},     {"--watch", 0, 0, 0},
                      {"--pid", 0, 0, 0},         {"--allrun-start", 0, 0, 0}, {"--interval", 0, "30", 1},
                      {0}};
    options_only(argc, argv, opts, "progress");
    const char *C = "progress", *ph = val(opts, "--phase", "flow"), *tf = val(opts, "--flow-end", "");
    if (strcmp(ph, "flow") && strcmp(ph, "replay"))
        swe_cli_die(2, "--phase: '%s' is not flow or replay", ph);
    if (flag(opts, "--watch"))
        return progress_watch(opts, val(opts, "--watch", ""), positive(opts, "--end", C, 1e9),
                              *tf ? swe_cli_number("--flow-end", tf) : -1);
    char line[512];
    swe_progress_line(line, sizeof line, number(opts, "--time", C), positive(opts, "--end", C, 1e9),
                      *tf ? swe_cli_number("--flow-end", tf) : -1, !strcmp(ph, "replay"),
                      number(opts, "--phase-start", C), (long)number(opts, "--elapsed", C),
                      (long)number(opts, "--phase-elapsed", C), (long)number(opts, "--allrun", C));
    puts(line);
    return 0;
}

static int cmd_nozzles(int argc, char **argv)
{
    run_opt opts[] = {{"--array", 0, 0, 0}, {"--wake", 1, 0, 0},   {"--derived", 0, 0, 0},
                      {"--parcels", 0, 0, 0}, {"--factor", 0, 0, 0}, {"--size", 0, 0, 0},
                      {"--speed", 0, 0, 0}, {0}};
    options_only(argc, argv, opts, "nozzles");
    const char *speed = val(opts, "--speed", NULL);
    if (speed && !(swe_cli_number("--speed", speed) > 0 && swe_cli_number("--speed", speed) < 1e4))
        swe_cli_die(2, "--speed: '%s' is not a speed in m/s (above 0, below 1e4)", speed);
    if (speed && flag(opts, "--wake"))
        swe_cli_die(2, "--speed with --wake: the wake source's speed is 1 m/s");
    const char *C = "nozzles", *size = need(opts, "--size", C);
    const int wake = flag(opts, "--wake");
    const double sz = strcmp(size, "spray") ? swe_cli_number("--size", size) : 0;
    if (strcmp(size, "spray") && !(sz > 0))
        swe_cli_die(2, "--size: '%s' is not spray or a diameter in um", size);
    long parcels = (long)(number(opts, "--parcels", C) * swe_cli_number("--factor", val(opts, "--factor", "1")) + 0.5);
    if (sz > 0 && parcels < 1) /* a class has at least one parcel per nozzle */
        parcels = 1;
    char err[512];
    char(*pts)[128] = NULL;
    const char *array = wake ? NULL : need(opts, "--array", C);
    const int np = wake ? swe_wake_points(&pts) : swe_nozzle_points(array, &pts, err, sizeof err);
    if (np < 0)
        swe_cli_die(1, "%s", wake ? "out of memory" : err);
    if (np == 0)
        swe_cli_die(2, "%s: no nozzle (x y z) found", array);
    /* constant/sprayDerived: "SOI T;", "massTotal M;", "duration T;" */
    const char *dpath = need(opts, "--derived", C);
    FILE *f = swe_cli_open(dpath);
    char line[512], soi[128] = "", mass[128] = "", dur[128] = "";
    while (fgets(line, sizeof line, f)) {
        char k[128], v[128];
        if (sscanf(line, " %127[^ ;] %127[^ ;\n]", k, v) != 2)
            continue;
        if (!strcmp(k, "SOI"))
            snprintf(soi, sizeof soi, "%s", v);
        else if (!strcmp(k, "massTotal"))
            snprintf(mass, sizeof mass, "%s", v);
        else if (!strcmp(k, "duration"))
            snprintf(dur, sizeof dur, "%s", v);
    }
    fclose(f);
    if (!soi[0] || !mass[0] || !dur[0])
        swe_cli_die(2, "%s: SOI, massTotal and duration are required", dpath);
    swe_nozzles_write(stdout, pts, np, parcels, soi, strtod(mass, NULL), dur, sz, wake, speed);
    free(pts);
    return 0;
}

/* the internalField list of a volScalarField (ASCII), one value a line */
static double *read_internal(const char *path, size_t *n)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    char line[512];
    int s = 0;
    size_t cap = 0;
    double *v = NULL;
    *n = 0;
    while (fgets(line, sizeof line, f)) {
        if (s == 0 && !strncmp(line, "internalField", 13))
            s = 1;
        else if (s == 1 && line[0] == '(')
            s = 2;
        else if (s == 2 && line[0] == ')')
            break;
        else if (s == 2) {
            if (*n == cap) {
                cap = cap ? 2 * cap : 4096;
                double *w = realloc(v, cap * sizeof *v);
                if (!w) {
                    free(v);
                    fclose(f);
                    return NULL;
                }
                v = w;
            }
            v[(*n)++] = strtod(line, NULL);
        }
    }
    fclose(f);
    return v;
}

static int cmd_decompose(int argc, char **argv)
{
    run_opt opts[] = {{"--np", 0, 0, 0}, {"--x-nozzle", 0, 0, 0}, {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) != 2)
        swe_cli_die(2, "decompose: give the files of x and y of the cell centres (see --help)");
    const double npd = number(opts, "--np", "decompose");
    if (!(npd >= 1 && npd == floor(npd) && npd < 1e6))
        swe_cli_die(2, "--np: '%s' is not a whole number of processes", val(opts, "--np", ""));
    const int np = (int)npd;
    size_t nx = 0, ny = 0;
    double *x = read_internal(pos[0], &nx), *y = read_internal(pos[1], &ny);
    int ok = x && y && nx == ny && nx >= (size_t)np;
    for (size_t i = 0; ok && i < nx; i++)
        ok = isfinite(x[i]) && isfinite(y[i]);
    if (!ok)
        swe_cli_die(1, "decompose: could not read the cell centres %s, %s", pos[0], pos[1]);
    int *proc = malloc(nx * sizeof *proc);
    char err[256];
    if (!proc)
        swe_cli_die(1, "out of memory");
    if (swe_decompose(x, y, nx, np, swe_cli_number("--x-nozzle", val(opts, "--x-nozzle", "-0.45")), proc,
                      err, sizeof err))
        swe_cli_die(1, "decompose: %s", err);
    printf("FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }\n%zu\n(\n", nx);
    for (size_t i = 0; i < nx; i++)
        printf("%d\n", proc[i]);
    puts(")");
    free(x), free(y), free(proc), free(pos);
    return 0;
}

static int cmd_level(int argc, char **argv)
{
    run_opt opts[] = {{"--log", 0, 0, 0},         {"--window", 0, 0, 0},      {"--level", 0, 0, 0},
                      {"--variant", 0, 0, 0},     {"--refine-wake", 0, 0, 0}, {"--halfstep", 0, 0, 0},
                      {"--full", 0, 0, 0},        {"--step-scale", 0, 0, 0},  {"--cells", 0, 0, 0},
                      {"--max-delta-t", 0, 0, 0}, {"--replay-interval", 0, 0, 0},
                      {"--gate", 0, 0, 0},        {"--mvd", 0, 0, 0},         {"--rear-layers", 0, 0, 0},
                      {"--rear-yplus", 0, 0, 0},  {0}};
    options_only(argc, argv, opts, "level");
    const char *C = "level", *w = need(opts, "--window", C), *c = strchr(w, ',');
    if (!c)
        swe_cli_die(2, "--window: '%s' is not T0,T1", w);
    char w0[64];
    snprintf(w0, sizeof w0, "%.*s", (int)(c - w), w);
    swe_level_in in = {
        .level = need(opts, "--level", C), .variant = need(opts, "--variant", C),
        .refine_wake = need(opts, "--refine-wake", C), .halfstep = need(opts, "--halfstep", C),
        .full = need(opts, "--full", C), .step_scale = need(opts, "--step-scale", C),
        .cells = need(opts, "--cells", C), .max_delta_t = need(opts, "--max-delta-t", C),
        .replay_interval = val(opts, "--replay-interval", ""), .gate = need(opts, "--gate", C),
        .mvd = need(opts, "--mvd", C), .rear_layers = need(opts, "--rear-layers", C),
        .rear_yplus = val(opts, "--rear-yplus", ""), .window0 = w0, .window1 = c + 1,
        .t0 = swe_cli_number("--window", w0), .t1 = swe_cli_number("--window", c + 1)};
    FILE *f = swe_cli_open(need(opts, "--log", C));
    char err[256];
    const int rc = swe_level_write(f, &in, stdout, err, sizeof err);
    fclose(f);
    if (rc)
        swe_cli_die(2, "level: %s: %s", val(opts, "--log", ""), err);
    return 0;
}

static int cmd_yplus(int argc, char **argv)
{
    run_opt opts[] = {{0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    FILE **f = calloc((size_t)argc, sizeof *f);
    if (!pos || !f)
        swe_cli_die(1, "out of memory");
    const int n = run_parse(argc, argv, opts, pos);
    for (int i = 0; i < n; i++)
        f[i] = swe_cli_open(pos[i]);
    double mn, mean, mx;
    if (swe_yplus_rear(f, n, &mn, &mean, &mx))
        printf("%.3g %.3g %.3g\n", mn, mean, mx);
    for (int i = 0; i < n; i++)
        fclose(f[i]);
    free(pos), free(f);
    return 0;
}

static int cmd_join_logs(int argc, char **argv)
{
    run_opt opts[] = {{0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    FILE **f = calloc((size_t)argc, sizeof *f);
    if (!pos || !f)
        swe_cli_die(1, "out of memory");
    const int n = run_parse(argc, argv, opts, pos);
    if (n < 1)
        swe_cli_die(2, "join-logs: give the parts of the log, first to last (see --help)");
    for (int i = 0; i < n; i++)
        f[i] = swe_cli_open(pos[i]);
    char err[256];
    if (swe_join_logs(f, n, stdout, err, sizeof err))
        swe_cli_die(1, "join-logs: %s", err);
    for (int i = 0; i < n; i++)
        fclose(f[i]);
    free(pos), free(f);
    return 0;
}

static int cmd_resume_time(int argc, char **argv)
{
    run_opt opts[] = {{"--np", 0, 0, 0}, {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) > 1)
        swe_cli_die(2, "resume-time: give at most the case folder (see --help)");
    const double np = swe_cli_number("--np", val(opts, "--np", "1"));
    if (!(np >= 1 && np == floor(np) && np < 1e6))
        swe_cli_die(2, "--np: '%s' is not a whole number of processes", val(opts, "--np", ""));
    char t[256], err[512];
    if (swe_resume_time(pos[0] ? pos[0] : ".", (int)np, t, sizeof t, err, sizeof err))
        swe_cli_die(2, "%s", err);
    if (t[0])
        printf("%s\n", t);
    free(pos);
    return 0;
}

static int cmd_restart_tables(int argc, char **argv)
{
    run_opt opts[] = {{"--time", 0, 0, 0}, {"--remove", 1, 0, 0}, {"--join", 1, 0, 0}, {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) != 1)
        swe_cli_die(2, "restart-tables: give the postProcessing folder (see --help)");
    const char *t = need(opts, "--time", "restart-tables");
    swe_cli_number("--time", t);
    const int mode = flag(opts, "--join") ? SWE_TABLES_JOIN : flag(opts, "--remove") ? SWE_TABLES_REMOVE
                                                                                      : SWE_TABLES_LIST;
    char err[8400];
    if (swe_restart_tables(pos[0], t, mode, stdout, err, sizeof err))
        swe_cli_die(1, "-resume: %s", err);
    free(pos);
    return 0;
}

/* resume-start --time T --solver S, resume-join --solver S: in the case folder */
static int cmd_resume(int argc, char **argv, int join)
{
    run_opt opts[] = {{"--time", 0, 0, 0}, {"--solver", 0, 0, 0}, {0}};
    options_only(argc, argv, opts, argv[1]);
    const char *solver = need(opts, "--solver", argv[1]);
    char msg[8400], err[8400];
    if (join ? swe_resume_join(solver, msg, sizeof msg, err, sizeof err)
             : swe_resume_start(solver, need(opts, "--time", argv[1]), msg, sizeof msg, err, sizeof err))
        swe_cli_die(1, "%s", err);
    puts(msg);
    return 0;
}

static int cmd_join_table(int argc, char **argv)
{
    run_opt opts[] = {{"--time", 0, 0, 0}, {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos || run_parse(argc, argv, opts, pos) != 2)
        swe_cli_die(2, "join-table: give the first table and the resumed one (see --help)");
    const double t = number(opts, "--time", "join-table");
    FILE *a = swe_cli_open(pos[0]), *b = swe_cli_open(pos[1]);
    swe_join_table(a, b, t, stdout);
    fclose(a), fclose(b), free(pos);
    return 0;
}

static int cmd_ladder(int argc, char **argv, int total)
{
    run_opt opts[] = {{"--ladder", 0, 0, 0}, {"--level", 0, 0, 0},      {"--cells", 0, 0, 0},
                      {"--mvd", 0, 0, 0},    {"--not-judged", 0, 0, 0}, {"--csv", 0, 0, 0},
                      {"--run", 0, 0, 0},    {0}};
    const char **pos = calloc((size_t)argc, sizeof *pos);
    if (!pos)
        swe_cli_die(1, "out of memory");
    const int n = run_parse(argc, argv, opts, pos);
    const char *C = argv[1], *lpath = need(opts, "--ladder", C);
    FILE *lad = swe_cli_open(lpath);
    if (!total) { /* ladder-check: KEY=VALUE settings */
        char **kv = calloc((size_t)n + 1, sizeof *kv);
        for (int i = 0; kv && i < n; i++) {
            kv[i] = malloc(strlen(pos[i]) + 1);
            if (kv[i])
                memcpy(kv[i], pos[i], strlen(pos[i]) + 1);
            char *e = kv[i] ? strchr(kv[i], '=') : NULL;
            if (!e)
                swe_cli_die(2, "ladder-check: '%s' is not KEY=VALUE", pos[i]);
            *e = ' ';
        }
        char why[4096];
        swe_ladder_why(lad, (const char *const *)kv, n, need(opts, "--level", C), need(opts, "--cells", C),
                       why, sizeof why);
        if (why[0])
            printf("%s\n", why);
        for (int i = 0; kv && i < n; i++)
            free(kv[i]);
        free(kv);
    } else {
        if (n)
            swe_cli_die(2, "total-error: no file arguments (see --help)");
        const char *mvd = need(opts, "--mvd", C);
        if (flag(opts, "--not-judged"))
            printf("# Total error of the rear deposit\n\nNot judged: this run is not on the resolution "
                   "ladder of %s (%s). Its sampling error alone is in results/compose/mvd%s/regions.md; "
                   "the discretization error of this mesh and these settings is not measured "
                   "(doc/wedge.md, \"Resolution ladder\").\n",
                   lpath, val(opts, "--not-judged", ""), mvd);
        else {
            FILE *csv = swe_cli_open(need(opts, "--csv", C));
            if (swe_total_error_table(csv, need(opts, "--run", C), mvd, lpath, need(opts, "--level", C),
                                      need(opts, "--cells", C), stdout))
                swe_cli_die(1, "out of memory");
            fclose(csv);
        }
        swe_ladder_notes(lad, stdout);
    }
    fclose(lad);
    free(pos);
    return 0;
}

int swe_cmd_run_is(const char *cmd)
{
    const char *c[] = {"spray-check", "estimate", "mesh", "times", "progress", "nozzles", "decompose", "level", "yplus",
                       "join-logs", "join-table", "resume-time", "restart-tables", "resume-start", "resume-join", "ladder-check",
                       "total-error"};
    for (size_t i = 0; i < sizeof c / sizeof *c; i++)
        if (!strcmp(cmd, c[i]))
            return 1;
    return 0;
}

int swe_cmd_run(int argc, char **argv)
{
    const char *c = argv[1];
    if (!strcmp(c, "estimate"))
        return cmd_estimate(argc, argv);
    if (!strcmp(c, "spray-check"))
        return cmd_spray_check(argc, argv);
    if (!strcmp(c, "mesh"))
        return cmd_mesh(argc, argv);
    if (!strcmp(c, "times"))
        return cmd_times(argc, argv);
    if (!strcmp(c, "progress"))
        return cmd_progress(argc, argv);
    if (!strcmp(c, "nozzles"))
        return cmd_nozzles(argc, argv);
    if (!strcmp(c, "decompose"))
        return cmd_decompose(argc, argv);
    if (!strcmp(c, "level"))
        return cmd_level(argc, argv);
    if (!strcmp(c, "yplus"))
        return cmd_yplus(argc, argv);
    if (!strcmp(c, "join-logs"))
        return cmd_join_logs(argc, argv);
    if (!strcmp(c, "join-table"))
        return cmd_join_table(argc, argv);
    if (!strcmp(c, "resume-time"))
        return cmd_resume_time(argc, argv);
    if (!strcmp(c, "restart-tables"))
        return cmd_restart_tables(argc, argv);
    if (!strcmp(c, "resume-start") || !strcmp(c, "resume-join"))
        return cmd_resume(argc, argv, !strcmp(c, "resume-join"));
    return cmd_ladder(argc, argv, !strcmp(c, "total-error"));
}
