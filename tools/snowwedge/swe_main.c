/* swe_main.c - snowwedge: the statistics of the wind-tunnel wedge's results
 * (tutorials/wedge/post): the spray's distribution and size classes, the
 * composition of the classes, the rear face's regions and their effective
 * sample sizes, and the force coefficients' mean, rms and spectral peak. */
#include "swe_signal.h"
#include "swe_spray.h"
#include "swe_stats.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *usage =
"NAME\n"
"    snowwedge - the statistics of the wind-tunnel wedge (tutorials/wedge)\n"
"\n"
"SYNOPSIS\n"
"    snowwedge distribution SPRAY\n"
"    snowwedge weights (SPRAY | --masses CSV) --classes D1,D2,...\n"
"    snowwedge classes --weights FILE --table FILE --desc TEXT [SPRAY]\n"
"    snowwedge regions --weights FILE --table FILE --desc TEXT\n"
"    snowwedge map --weights FILE MAP.csv...\n"
"    snowwedge outline MAP.csv\n"
"    snowwedge rear-stats --label TEXT --from TA --to TB --outline MAP.csv\n"
"                         --kind sticks|impacts [RECORDS.post...]\n"
"    snowwedge forces --window T0,T1 COEFFICIENT.dat\n"
"    snowwedge probes --window T0,T1 PROBES_U\n"
"    snowwedge errortime [--target P] POINTS\n"
"    snowwedge --help\n"
"\n"
"    SPRAY is --mvd UM [--sigma-g S] [--range MIN,MAX] [--freeze F]: droplet\n"
"    mass log-normal with median volume diameter UM (0.1 .. 1000 um), geometric\n"
"    standard deviation S (1 < S <= 10, default 1.8), droplets MIN .. MAX um\n"
"    (default 2,150), ice diameter F x the droplet's (0.5 .. 2, default 1.03).\n"
"\n"
"DESCRIPTION\n"
"    distribution  the spray's mass density of the ice diameter as OpenFOAM's\n"
"             general distribution (constant/sprayDistribution): 121 diameters\n"
"             log-spaced over the frozen range, in m, density x 1e-6.\n"
"    weights  per class (ice diameters D1 < D2 < ... um) one line \"D w e0 e1\":\n"
"             its mass share w of the spray truncated to its range, and its edges\n"
"             (the geometric means of the neighbours, the range's ends outside).\n"
"             With --masses, lines \"d_um,mass\" (d_um one of the classes; #\n"
"             lines and blank lines skipped) normalized; e0, e1 then nan.\n"
"    classes  the markdown table of the classes of a composed spray (classes.md:\n"
"             edges, w, rear capture in ppm of the sprayed mass, its error\n"
"             1/sqrt(n_eff), share of the rear deposit) and the mass median\n"
"             diameters of the spray and of the rear deposit: the class holding\n"
"             it and, with SPRAY, interpolated (the log-normal within each class,\n"
"             the class's capture constant across it; bisection).\n"
"    regions  the markdown table of the composed rear-face regions (regions.md):\n"
"             deposit sum_k w_k M_k,r, its relative standard error\n"
"             (se^2 = sum (w_k M_k,r)^2 / n_eff_k,r), its mean per area over the\n"
"             face's, and whether it stands out by more than 2 standard errors;\n"
"             when every class has its halves, the halves of the window (x2)\n"
"             and their z = difference / its standard error (disagree: |z| > 2).\n"
"             --weights is the output of weights; --table one line per class:\n"
"             \"D injected deposit\" then mass and n_eff of left side, right side,\n"
"             centre, edges, whole face for the window, then (optional) the same\n"
"             ten for the first and the second half.\n"
"    map      the composed rear-face map: CSV y,z,deposit_kg_m2 summed over the\n"
"             maps (the class's diameter from the path .../d<D>um/FILE) with\n"
"             their weights, in the first map's order of faces.\n"
"    outline  \"y0 y1 z0 z1\" of a rear-face map: the face centres extended by\n"
"             half a face (6 significant digits).\n"
"    rear-stats  one markdown row \"| TEXT | left | right | centre | edges |\n"
"             whole face |\": per region the records with TA < Time <= TB\n"
"             (OpenFOAM .post files with the header # Time (position0 position1\n"
"             position2) origProc origId nParticle d rho), their independent\n"
"             origins, mass (nParticle rho pi d^3 / 6), effective sample size\n"
"             n_eff = (sum_a W_a)^2 / sum_a W_a^2 and error 1/sqrt(n_eff).\n"
"    forces   over T0 < t <= T1 of forceCoeffs' table: mean Cd, rms and\n"
"             dominant frequency of Cs and Cl (the largest peak of the transform\n"
"             on the uneven samples, 2/W .. 300 Hz in steps of 1/(4W)) and their\n"
"             Strouhal numbers f H / U (H 0.12 m, U 19.444 m/s); one line.\n"
"    probes   over T0 < t <= T1 of a probes table of U: mean and rms of Ux at\n"
"             every probe; one line.\n"
"    errortime  POINTS has one tab-separated line \"design run wall_s error\" per\n"
"             sampling design (error: relative, in %); prints a markdown row per\n"
"             line with the time that design needs for the target error P %\n"
"             (default 10) at its rate: wall_s (error / P)^2 (the error of n\n"
"             independent samples falls as 1/sqrt(n), the time grows as n).\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 an input file unreadable; 2 usage or bad input (one line\n"
"    naming the input and the value).\n";

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("snowwedge: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

static double number(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v))
        die(2, "%s: '%s' is not a number", opt, s);
    return v;
}

static FILE *open_in(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        die(1, "cannot read %s", path);
    return f;
}

/* ---- options ------------------------------------------------------------- */
typedef struct {
    swe_spray spray;
    int has_spray;
    const char *mvd_s, *sg_s, *range_s, *freeze_s; /* as given, for the header */
    const char *masses, *classes, *weights, *table, *desc, *label, *outline, *kind, *window;
    const char *from, *to, *target;
    const char **files;
    int nfiles;
} options;

static void parse(int argc, char **argv, options *o)
{
    swe_spray_default(&o->spray);
    o->sg_s = "1.8";
    o->range_s = "2,150";
    o->freeze_s = "1.03";
    o->files = calloc((size_t)argc + 1, sizeof *o->files);
    if (!o->files)
        die(1, "out of memory");
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            exit(0);
        }
        if (a[0] == '-' && a[1] == '-') {
            if (i + 1 >= argc || !argv[i + 1][0])
                die(2, "%s needs a value (see --help)", a);
            const char *v = argv[++i];
            if (!strcmp(a, "--mvd")) {
                o->spray.mvd = number(a, v);
                o->mvd_s = v;
                o->has_spray = 1;
            } else if (!strcmp(a, "--sigma-g")) {
                o->spray.sigma_g = number(a, v);
                o->sg_s = v;
            } else if (!strcmp(a, "--freeze")) {
                o->spray.freeze = number(a, v);
                o->freeze_s = v;
            } else if (!strcmp(a, "--range")) {
                char *c = strchr(v, ',');
                if (!c || strchr(c + 1, ','))
                    die(2, "--range: '%s' is not MIN,MAX", v);
                char buf[64];
                snprintf(buf, sizeof buf, "%.*s", (int)(c - v), v);
                o->spray.dmin = number(a, buf);
                o->spray.dmax = number(a, c + 1);
                o->range_s = v;
            } else if (!strcmp(a, "--masses"))
                o->masses = v;
            else if (!strcmp(a, "--classes"))
                o->classes = v;
            else if (!strcmp(a, "--weights"))
                o->weights = v;
            else if (!strcmp(a, "--table"))
                o->table = v;
            else if (!strcmp(a, "--desc"))
                o->desc = v;
            else if (!strcmp(a, "--label"))
                o->label = v;
            else if (!strcmp(a, "--from"))
                o->from = v;
            else if (!strcmp(a, "--to"))
                o->to = v;
            else if (!strcmp(a, "--outline"))
                o->outline = v;
            else if (!strcmp(a, "--kind"))
                o->kind = v;
            else if (!strcmp(a, "--window"))
                o->window = v;
            else if (!strcmp(a, "--target"))
                o->target = v;
            else
                die(2, "%s: unknown option '%s' (see --help)", argv[1], a);
        } else
            o->files[o->nfiles++] = a;
    }
    if (o->has_spray) {
        char err[256];
        if (swe_spray_check(&o->spray, err, sizeof err))
            die(2, "%s", err);
    }
}

static void need(const char *what, const char *v, const char *cmd)
{
    if (!v)
        die(2, "%s: %s is required (see --help)", cmd, what);
}

/* ---- distribution ---------------------------------------------------------- */
static int cmd_distribution(const options *o)
{
    if (!o->has_spray)
        die(2, "distribution: --mvd is required (see --help)");
    const swe_spray *s = &o->spray;
    const double lo = s->dmin * s->freeze * 1e-6, hi = s->dmax * s->freeze * 1e-6;
    char a[64], b[64];
    const char *c = strchr(o->range_s, ',');
    snprintf(a, sizeof a, "%.*s", (int)(c - o->range_s), o->range_s);
    snprintf(b, sizeof b, "%s", c + 1);
    printf("// generated by Allrun from constant/sprayProperties (spray): log-normal mass density,\n");
    printf("// MVD %s um x %s (frozen), sigma_g %s, droplets %s .. %s um\n", o->mvd_s, o->freeze_s,
           o->sg_s, a, b);
    printf("type general;\ngeneralDistribution\n{\n    distribution\n    (\n");
    const int n = 120;
    for (int i = 0; i <= n; i++) {
        const double d = lo * exp((double)i / n * log(hi / lo));
        printf("        (%.8e %.8e)\n", d, swe_spray_density(s, d));
    }
    printf("    );\n}\n");
    return 0;
}

/* ---- weights --------------------------------------------------------------- */
static int parse_classes(const char *list, double **d)
{
    int n = 1;
    for (const char *p = list; *p; p++)
        n += (*p == ',');
    *d = malloc((size_t)n * sizeof **d);
    if (!*d)
        die(1, "out of memory");
    char *copy = strdup(list), *save = NULL;
    int k = 0;
    for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save))
        (*d)[k++] = number("--classes", t);
    free(copy);
    if (k != n)
        die(2, "--classes: '%s' is not a comma-separated list of diameters", list);
    return n;
}

static int cmd_weights(const options *o)
{
    need("--classes", o->classes, "weights");
    if (!o->has_spray == !o->masses)
        die(2, "weights: give the spray, --mvd UM, or --masses CSV (not both)");
    double *d;
    const int n = parse_classes(o->classes, &d);
    double *w = calloc((size_t)n, sizeof *w), *e0 = calloc((size_t)n, sizeof *e0),
           *e1 = calloc((size_t)n, sizeof *e1);
    if (!w || !e0 || !e1)
        die(1, "out of memory");
    if (o->has_spray) {
        char err[256];
        if (swe_spray_classes(&o->spray, d, (size_t)n, w, e0, e1, err, sizeof err))
            die(2, "weights: %s", err);
        for (int i = 0; i < n; i++)
            printf("%.10g %.10g %.6g %.6g\n", d[i], w[i], e0[i], e1[i]);
    } else {
        FILE *f = open_in(o->masses);
        char line[4096];
        double tot = 0;
        for (int ln = 1; fgets(line, sizeof line, f); ln++) {
            char *p = line;
            while (*p == ' ' || *p == '\t')
                p++;
            if (*p == '#' || *p == '\n' || !*p)
                continue;
            line[strcspn(line, "\r\n")] = 0;
            char *c = strchr(line, ',');
            char *end;
            double dd = c ? strtod(line, &end) : NAN;
            int k = -1;
            for (int i = 0; c && i < n; i++)
                if (d[i] == dd)
                    k = i;
            /* the mass: a plain non-negative decimal (digits, a point, an exponent) */
            double m = NAN;
            const char *ms = c ? c + 1 : "";
            if (c && !strchr(ms, ',') && (isdigit((unsigned char)ms[0]) || ms[0] == '.') &&
                strspn(ms, "0123456789.eE+-") == strlen(ms)) {
                m = strtod(ms, &end);
                if (end == ms || *end)
                    m = NAN;
            }
            if (k < 0 || isnan(m)) {
                fprintf(stderr, "snowwedge: --masses line %d: \"%s\" is not d_um,mass with d_um one of ",
                        ln, line);
                for (int i = 0; i < n; i++)
                    fprintf(stderr, "%.10g ", d[i]);
                fputc('\n', stderr);
                exit(2);
            }
            w[k] += m;
            tot += m;
        }
        fclose(f);
        if (!(tot > 0))
            die(2, "--masses: the masses sum to 0");
        for (int i = 0; i < n; i++)
            printf("%.10g %.10g nan nan\n", d[i], w[i] / tot);
    }
    free(d);
    free(w);
    free(e0);
    free(e1);
    return 0;
}

/* ---- the composition's inputs -------------------------------------------------- */
typedef struct {
    char d[32];
    double w, e0, e1, inj, dep;
    swe_class win, h1, h2;
    int halves;
} comp_class;

static int read_weights(const char *path, char (*d)[32], double *w, double *e0, double *e1, int max)
{
    FILE *f = open_in(path);
    int n = 0;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (n >= max)
            die(2, "%s: more than %d classes", path, max);
        char e0s[64], e1s[64];
        if (sscanf(line, "%31s %lf %63s %63s", d[n], &w[n], e0s, e1s) != 4)
            die(2, "%s: line %d is not \"D w e0 e1\"", path, n + 1);
        e0[n] = strtod(e0s, NULL);
        e1[n] = strtod(e1s, NULL);
        n++;
    }
    fclose(f);
    return n;
}

static int read_table(const options *o, const char *cmd, comp_class **out)
{
    need("--weights", o->weights, cmd);
    need("--table", o->table, cmd);
    enum { MAXC = 256 };
    static char wd[MAXC][32];
    static double ww[MAXC], we0[MAXC], we1[MAXC];
    const int nw = read_weights(o->weights, wd, ww, we0, we1, MAXC);
    comp_class *c = calloc(MAXC, sizeof *c);
    if (!c)
        die(1, "out of memory");
    FILE *f = open_in(o->table);
    char line[8192];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        double v[40];
        int k = 0;
        char *save = NULL;
        char *t = strtok_r(line, " \t\r\n", &save);
        if (!t)
            continue;
        if (n >= MAXC)
            die(2, "%s: more than %d classes", o->table, MAXC);
        snprintf(c[n].d, sizeof c[n].d, "%s", t);
        for (t = strtok_r(NULL, " \t\r\n", &save); t && k < 40; t = strtok_r(NULL, " \t\r\n", &save))
            v[k++] = number(o->table, t);
        if (k != 12 && k != 32)
            die(2, "%s: class %s has %d numbers, not 12 or 32", o->table, c[n].d, k);
        int j = -1;
        for (int i = 0; i < nw; i++)
            if (!strcmp(wd[i], c[n].d))
                j = i;
        if (j < 0)
            die(2, "%s: class %s is not in %s", o->table, c[n].d, o->weights);
        c[n].w = ww[j];
        c[n].e0 = we0[j];
        c[n].e1 = we1[j];
        c[n].inj = v[0];
        c[n].dep = v[1];
        swe_class *blk[3] = {&c[n].win, &c[n].h1, &c[n].h2};
        for (int b = 0; b < (k == 32 ? 3 : 1); b++) {
            blk[b]->w = ww[j];
            for (int r = 0; r < SWE_NREGION; r++) {
                blk[b]->mass[r] = v[2 + 10 * b + 2 * r];
                blk[b]->neff[r] = v[3 + 10 * b + 2 * r];
            }
        }
        c[n].halves = (k == 32);
        n++;
    }
    fclose(f);
    if (!n)
        die(2, "%s: no class", o->table);
    *out = c;
    return n;
}

/* ---- classes ------------------------------------------------------------------- */
static int cmd_classes(const options *o)
{
    need("--desc", o->desc, "classes");
    comp_class *c;
    const int n = read_table(o, "classes", &c);
    printf("# The rear face for a spray: %s\n\n", o->desc);
    printf("Composed from the per-diameter clouds of Allrun -sizes (post/wedge-compose).\n");
    printf("Capture: rear-face deposit of the window per mass sprayed in it, as if the whole\n");
    printf("spray had that diameter; share: the class's part of the composed rear deposit.\n\n");
    printf("| d [um] | class [um] | mass share w | rear capture [ppm] | +- | share of the rear deposit |\n");
    printf("|---:|---|---:|---:|---:|---:|\n");
    double tot = 0;
    for (int i = 0; i < n; i++)
        tot += c[i].w * c[i].win.mass[SWE_FACE];
    for (int i = 0; i < n; i++) {
        const double m = c[i].win.mass[SWE_FACE], ne = c[i].win.neff[SWE_FACE];
        const double cap = (c[i].inj > 0) ? 1e6 * c[i].dep / c[i].inj : 0;
        char cls[64] = "-", err[32] = "-";
        if (o->has_spray)
            snprintf(cls, sizeof cls, "%.3g - %.3g", c[i].e0, c[i].e1);
        if (m > 0)
            snprintf(err, sizeof err, "%.0f %%", ne > 0 ? 100 / sqrt(ne) : 0);
        printf("| %s | %s | %.4g | %.4g | %s | %.3g %% |\n", c[i].d, cls, c[i].w, cap, err,
               tot > 0 ? 100 * c[i].w * m / tot : 0);
    }
    /* the class that holds the median: the first whose cumulative share reaches 0.5 */
    const char *ms = "", *mr = "-";
    double cs = 0, cr = 0;
    for (int i = 0; i < n; i++) {
        if (cs < 0.5 && cs + c[i].w >= 0.5)
            ms = c[i].d;
        cs += c[i].w;
        const double f = tot > 0 ? c[i].w * c[i].win.mass[SWE_FACE] / tot : 0;
        if (cr < 0.5 && cr + f >= 0.5)
            mr = c[i].d;
        cr += f;
    }
    printf("\nMass median diameter (class of): the spray %s um, the rear-face deposit %s um.\n", ms,
           mr);
    if (o->has_spray && tot > 0) {
        double *e0 = malloc((size_t)n * sizeof *e0), *e1 = malloc((size_t)n * sizeof *e1),
               *w = malloc((size_t)n * sizeof *w), *cap = malloc((size_t)n * sizeof *cap);
        if (!e0 || !e1 || !w || !cap)
            die(1, "out of memory");
        for (int i = 0; i < n; i++) {
            e0[i] = c[i].e0;
            e1[i] = c[i].e1;
            w[i] = c[i].w;
            cap[i] = c[i].win.mass[SWE_FACE];
        }
        double xs, xd;
        char err[256];
        if (swe_spray_median(&o->spray, &xs, err, sizeof err) ||
            swe_deposit_median(&o->spray, e0, e1, w, cap, (size_t)n, &xd, err, sizeof err))
            die(2, "classes: %s", err);
        printf("Mass median diameter (interpolated: the log-normal within each class, its capture "
               "constant there): the spray %.3g um, the rear-face deposit %.3g um.\n",
               xs, xd);
        free(e0);
        free(e1);
        free(w);
        free(cap);
    }
    free(c);
    return 0;
}

/* ---- regions ------------------------------------------------------------------- */
static int cmd_regions(const options *o)
{
    need("--desc", o->desc, "regions");
    comp_class *c;
    const int n = read_table(o, "regions", &c);
    swe_class *win = malloc((size_t)n * sizeof *win), *h1 = malloc((size_t)n * sizeof *h1),
              *h2 = malloc((size_t)n * sizeof *h2);
    if (!win || !h1 || !h2)
        die(1, "out of memory");
    int halves = 1;
    for (int i = 0; i < n; i++) {
        win[i] = c[i].win;
        h1[i] = c[i].h1;
        h2[i] = c[i].h2;
        halves &= c[i].halves;
    }
    double S[SWE_NREGION], V[SWE_NREGION];
    swe_compose(win, (size_t)n, 1, S, V);
    printf("# Rear-face regions for a spray: %s\n\n", o->desc);
    printf("Composed deposit [kg / 30 min] per region with its relative standard error,\n");
    printf("propagated from the classes (se^2 = sum (w_k M_k,r)^2 / n_eff_k,r). A region\n");
    printf("*stands out* when its deposit differs from what the face's mean would put on its\n");
    printf("share of the area by more than 2 standard errors (areas from the region definitions:\n");
    printf("edge band 0.1 of each side: 36 %%; left and right 20 %% each; centre 12 %%).\n\n");
    printf("| region | deposit [kg] | +- | deposit per area over the face's | stands out |\n");
    printf("|---|---:|---:|---:|---|\n");
    for (int r = 0; r < SWE_NREGION; r++) {
        char rel[32] = "-";
        if (S[r] > 0)
            snprintf(rel, sizeof rel, "%.1f %%", 100 * sqrt(V[r]) / S[r]);
        const double ratio = S[SWE_FACE] > 0 ? (S[r] / swe_region_area(r)) / S[SWE_FACE] : 0;
        const int so = swe_stands_out(S[r], V[r], S[SWE_FACE], r);
        const char *out = so > 0 ? "**higher**" : so < 0 ? "**lower**" : "no";
        if (r < SWE_FACE && S[r] == 0 && S[SWE_FACE] > 0)
            out = "**lower** (no snow)";
        if (r == SWE_FACE)
            out = "-";
        printf("| %s | %.4g | %s | %.3g | %s |\n", swe_region_name(r), S[r], rel, ratio, out);
    }
    if (halves) {
        double A[SWE_NREGION], VA[SWE_NREGION], B[SWE_NREGION], VB[SWE_NREGION];
        swe_compose(h1, (size_t)n, 2, A, VA);
        swe_compose(h2, (size_t)n, 2, B, VB);
        printf("\n## The halves of the sampling window (each x2)\n\n");
        printf("| region | first half [kg] | +- | second half [kg] | +- | difference / its "
               "standard error |\n");
        printf("|---|---:|---:|---:|---:|---:|\n");
        int bad = 0, held = 0;
        for (int r = 0; r < SWE_NREGION; r++) {
            const double z = swe_ztest(A[r], VA[r], B[r], VB[r], NULL);
            if (A[r] + B[r] > 0) {
                held++;
                if (z > 2 || z < -2)
                    bad++;
            }
            char ea[32] = "-", eb[32] = "-";
            if (A[r] > 0)
                snprintf(ea, sizeof ea, "%.1f %%", 100 * sqrt(VA[r]) / A[r]);
            if (B[r] > 0)
                snprintf(eb, sizeof eb, "%.1f %%", 100 * sqrt(VB[r]) / B[r]);
            printf("| %s | %.4g | %s | %.4g | %s | %+.1f |\n", swe_region_name(r), A[r], ea, B[r],
                   eb, z);
        }
        printf("\nHalves: %s (%d of %d regions with snow differ by more than 2 standard errors).\n",
               bad ? "**disagree**" : "agree within 2 standard errors", bad, held);
    }
    free(win);
    free(h1);
    free(h2);
    free(c);
    return 0;
}

/* ---- maps ---------------------------------------------------------------------- */
typedef struct {
    char key[96];
    double v;
} face;

static int cmd_map(const options *o)
{
    need("--weights", o->weights, "map");
    if (!o->nfiles)
        die(2, "map: give the class maps (see --help)");
    enum { MAXC = 256 };
    static char wd[MAXC][32];
    static double ww[MAXC], we0[MAXC], we1[MAXC];
    const int nw = read_weights(o->weights, wd, ww, we0, we1, MAXC);
    size_t cap = 1024, nf = 0;
    face *F = malloc(cap * sizeof *F);
    if (!F)
        die(1, "out of memory");
    for (int fi = 0; fi < o->nfiles; fi++) {
        /* the class: .../d<D>um/<file> */
        const char *p = o->files[fi];
        char d[32] = "", dd[32], um[4];
        for (const char *s = strstr(p, "/d"); s; s = strstr(s + 1, "/d"))
            if (sscanf(s, "/d%31[0-9]%3[um/]", dd, um) == 2 && !strcmp(um, "um/"))
                memcpy(d, dd, sizeof d);
        double w = NAN;
        for (int i = 0; d[0] && i < nw; i++)
            if (!strcmp(wd[i], d))
                w = ww[i];
        if (isnan(w))
            die(2, "map: %s is no class of %s (a path .../d<D>um/MAP.csv)", p, o->weights);
        FILE *f = open_in(p);
        char line[512];
        size_t hint = 0;
        for (int ln = 0; fgets(line, sizeof line, f); ln++) {
            if (ln == 0)
                continue;
            line[strcspn(line, "\r\n")] = 0;
            char *c2 = strrchr(line, ',');
            if (!c2 || c2 == line || !strchr(line, ',') || strchr(line, ',') == c2)
                die(2, "map: %s line %d is not y,z,value", p, ln + 1);
            *c2 = 0;
            const double v = number(p, c2 + 1);
            size_t k = nf;
            for (size_t j = 0; j < nf; j++) {
                const size_t jj = (hint + j) % nf;
                if (!strcmp(F[jj].key, line)) {
                    k = jj;
                    break;
                }
            }
            if (k == nf) {
                if (nf == cap) {
                    cap *= 2;
                    face *g = realloc(F, cap * sizeof *F);
                    if (!g)
                        die(1, "out of memory");
                    F = g;
                }
                if (strlen(line) >= sizeof F[nf].key)
                    die(2, "map: %s line %d: y,z longer than %zu characters", p, ln + 1,
                        sizeof F[nf].key - 1);
                memcpy(F[nf].key, line, strlen(line) + 1);
                F[nf++].v = 0;
            }
            F[k].v += w * v;
            hint = k + 1;
        }
        fclose(f);
    }
    for (size_t i = 0; i < nf; i++)
        printf("%s,%.6g\n", F[i].key, F[i].v);
    free(F);
    return 0;
}

/* the outline of a rear-face map, to 6 significant digits (as the panels and
   the region tables of earlier runs read it) */
static void outline_of(const char *path, double o[4])
{
    FILE *f = open_in(path);
    char line[512];
    size_t cap = 1024, n = 0;
    double *y = malloc(cap * sizeof *y), *z = malloc(cap * sizeof *z);
    if (!y || !z)
        die(1, "out of memory");
    for (int ln = 0; fgets(line, sizeof line, f); ln++) {
        if (ln == 0)
            continue;
        if (n == cap) {
            cap *= 2;
            y = realloc(y, cap * sizeof *y);
            z = realloc(z, cap * sizeof *z);
            if (!y || !z)
                die(1, "out of memory");
        }
        if (sscanf(line, "%lf,%lf", &y[n], &z[n]) != 2)
            die(2, "%s line %d is not y,z,value", path, ln + 1);
        n++;
    }
    fclose(f);
    if (!n)
        die(2, "%s holds no face", path);
    double *a[2] = {y, z};
    for (int c = 0; c < 2; c++) {
        double lo = a[c][0], hi = a[c][0];
        for (size_t i = 0; i < n; i++) {
            lo = a[c][i] < lo ? a[c][i] : lo;
            hi = a[c][i] > hi ? a[c][i] : hi;
        }
        /* distinct values: sorted, counted */
        double *s = malloc(n * sizeof *s);
        if (!s)
            die(1, "out of memory");
        memcpy(s, a[c], n * sizeof *s);
        for (size_t i = 1; i < n; i++) /* insertion sort: maps are small and nearly sorted */
            for (size_t j = i; j > 0 && s[j - 1] > s[j]; j--) {
                const double t = s[j];
                s[j] = s[j - 1];
                s[j - 1] = t;
            }
        size_t nd = 1;
        for (size_t i = 1; i < n; i++)
            nd += (s[i] != s[i - 1]);
        free(s);
        const double h = (nd > 1) ? (hi - lo) / (double)(nd - 1) / 2 : 0.005;
        char buf[64];
        snprintf(buf, sizeof buf, "%.6g", lo - h);
        o[2 * c] = strtod(buf, NULL);
        snprintf(buf, sizeof buf, "%.6g", hi + h);
        o[2 * c + 1] = strtod(buf, NULL);
    }
    free(y);
    free(z);
}

static int cmd_outline(const options *o)
{
    if (o->nfiles != 1)
        die(2, "outline: give one map (see --help)");
    double b[4];
    outline_of(o->files[0], b);
    printf("%.6g %.6g %.6g %.6g\n", b[0], b[1], b[2], b[3]);
    return 0;
}

/* ---- rear-face records ------------------------------------------------------------ */
static void strip_parens(char *s)
{
    for (; *s; s++)
        if (*s == '(' || *s == ')')
            *s = ' ';
}

static int cmd_rear_stats(const options *o)
{
    need("--label", o->label, "rear-stats");
    need("--from", o->from, "rear-stats");
    need("--to", o->to, "rear-stats");
    need("--outline", o->outline, "rear-stats");
    need("--kind", o->kind, "rear-stats");
    const double ta = number("--from", o->from), tb = number("--to", o->to);
    double ol[4];
    outline_of(o->outline, ol);
    size_t cap = 4096, n = 0;
    swe_record *rec = malloc(cap * sizeof *rec);
    if (!rec)
        die(1, "out of memory");
    static char line[1 << 16];
    for (int fi = 0; fi < o->nfiles; fi++) {
        FILE *f = open_in(o->files[fi]);
        enum { T, Y, Z, P, I, N, D, R, NCOL };
        static const char *want[NCOL] = {"Time", "position1", "position2", "origProc",
                                         "origId", "nParticle", "d", "rho"};
        int col[NCOL], have = 0;
        for (int ln = 1; fgets(line, sizeof line, f); ln++) {
            strip_parens(line);
            char *tok[64];
            int nt = 0;
            char *save = NULL;
            for (char *t = strtok_r(line, " \t\r\n", &save); t && nt < 64;
                 t = strtok_r(NULL, " \t\r\n", &save))
                tok[nt++] = t;
            if (nt && tok[0][0] == '#') {
                if (!have) {
                    for (int k = 0; k < NCOL; k++) {
                        col[k] = -1;
                        for (int j = 1; j < nt; j++)
                            if (!strcmp(tok[j], want[k]))
                                col[k] = j - 1;
                        if (col[k] < 0)
                            die(2, "%s: the header has no column %s", o->files[fi], want[k]);
                    }
                    have = 1;
                }
                continue;
            }
            if (!nt)
                continue;
            if (!have)
                die(2, "%s line %d: a record before the header", o->files[fi], ln);
            double v[NCOL];
            for (int k = 0; k < NCOL; k++) {
                if (col[k] >= nt)
                    die(2, "%s line %d: %d columns, the header names more", o->files[fi], ln, nt);
                v[k] = number(o->files[fi], tok[col[k]]);
            }
            if (!(v[T] > ta + 1e-12 && v[T] <= tb + 1e-12))
                continue;
            if (n == cap) {
                cap *= 2;
                swe_record *g = realloc(rec, cap * sizeof *rec);
                if (!g)
                    die(1, "out of memory");
                rec = g;
            }
            rec[n++] = (swe_record){v[Y], v[Z], v[N] * v[R] * M_PI / 6 * v[D] * v[D] * v[D],
                                    (long)v[P], (long)v[I]};
        }
        fclose(f);
    }
    swe_region_stats st[SWE_NREGION];
    char err[256];
    if (swe_rear_stats(rec, n, ol, st, err, sizeof err))
        die(2, "rear-stats: %s", err);
    static const int order[SWE_NREGION] = {SWE_LEFT, SWE_RIGHT, SWE_CENTRE, SWE_EDGES, SWE_FACE};
    printf("| %s |", o->label);
    for (int i = 0; i < SWE_NREGION; i++) {
        const swe_region_stats *s = &st[order[i]];
        if (!s->n)
            printf(" 0 |");
        else
            printf(" %ld %s, %ld origins, %.3g kg, n_eff %.1f, +- %.0f %% |", s->n, o->kind,
                   s->origins, s->mass, s->neff, 100 / sqrt(s->neff));
    }
    printf("\n");
    free(rec);
    return 0;
}

/* ---- time series of the flow ------------------------------------------------------ */
static void window_of(const options *o, const char *cmd, double *a, double *b)
{
    need("--window", o->window, cmd);
    const char *c = strchr(o->window, ',');
    char buf[64];
    if (!c || (size_t)(c - o->window) >= sizeof buf)
        die(2, "--window: '%s' is not T0,T1", o->window);
    snprintf(buf, sizeof buf, "%.*s", (int)(c - o->window), o->window);
    *a = number("--window", buf);
    *b = number("--window", c + 1);
    if (!(*b > *a))
        die(2, "--window: '%s' is not T0,T1 with T0 < T1", o->window);
}

static int cmd_forces(const options *o)
{
    double a, b;
    window_of(o, "forces", &a, &b);
    if (o->nfiles != 1)
        die(2, "forces: give one coefficient.dat (see --help)");
    FILE *f = open_in(o->files[0]);
    size_t cap = 4096, n = 0;
    double *t = malloc(cap * sizeof *t), *cd = malloc(cap * sizeof *cd),
           *cs = malloc(cap * sizeof *cs), *cl = malloc(cap * sizeof *cl);
    static char line[1 << 14];
    while (t && cd && cs && cl && fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        double v[4];
        if (sscanf(line, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]) != 4)
            continue;
        if (!(v[0] > a + 1e-12 && v[0] <= b + 1e-12))
            continue;
        if (n == cap) {
            cap *= 2;
            t = realloc(t, cap * sizeof *t);
            cd = realloc(cd, cap * sizeof *cd);
            cs = realloc(cs, cap * sizeof *cs);
            cl = realloc(cl, cap * sizeof *cl);
            if (!t || !cd || !cs || !cl)
                break;
        }
        t[n] = v[0];
        cd[n] = v[1];
        cs[n] = v[2];
        cl[n] = v[3];
        n++;
    }
    fclose(f);
    if (!t || !cd || !cs || !cl)
        die(1, "out of memory");
    if (n >= 10) { /* fewer samples: no line, as the window holds no spectrum */
        double fs, fl;
        char err[256];
        if (swe_peak_frequency(t, cs, n, a, b, 300, &fs, err, sizeof err) ||
            swe_peak_frequency(t, cl, n, a, b, 300, &fl, err, sizeof err))
            die(2, "forces: %s", err);
        printf("Forces on the wedge (reference: rear face 0.0144 m2, 19.444 m/s): mean Cd %.3f; "
               "side force Cs rms %.3g, dominant frequency %.1f Hz (Strouhal number f H/U = %.3f, "
               "H = 0.12 m); lift Cl rms %.3g, dominant frequency %.1f Hz (St %.3f).\n",
               swe_mean(cd, n), swe_rms(cs, n), fs, fs * 0.12 / 19.444, swe_rms(cl, n), fl,
               fl * 0.12 / 19.444);
    }
    free(t);
    free(cd);
    free(cs);
    free(cl);
    return 0;
}

static int cmd_probes(const options *o)
{
    double a, b;
    window_of(o, "probes", &a, &b);
    if (o->nfiles != 1)
        die(2, "probes: give one probes file of U (see --help)");
    FILE *f = open_in(o->files[0]);
    enum { MAXP = 64 };
    char loc[MAXP][128];
    double s[MAXP] = {0}, q[MAXP] = {0};
    int np = 0;
    long n = 0;
    static char line[1 << 14];
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "# Probe ", 8)) {
            char *p = line + 8;
            while (*p >= '0' && *p <= '9')
                p++;
            if (*p == ' ')
                p++;
            p[strcspn(p, "\r\n")] = 0;
            if (strlen(p) >= sizeof loc[0])
                die(2, "%s: a probe location longer than %zu characters", o->files[0],
                    sizeof loc[0] - 1);
            if (np < MAXP)
                memcpy(loc[np++], p, strlen(p) + 1);
            continue;
        }
        if (line[0] == '#')
            continue;
        strip_parens(line);
        char *save = NULL, *tok = strtok_r(line, " \t\r\n", &save);
        if (!tok)
            continue;
        const double t = strtod(tok, NULL);
        if (!(t > a + 1e-12 && t <= b + 1e-12))
            continue;
        n++;
        for (int k = 0; k < np; k++) {
            tok = strtok_r(NULL, " \t\r\n", &save);
            const double u = tok ? strtod(tok, NULL) : 0;
            s[k] += u;
            q[k] += u * u;
            strtok_r(NULL, " \t\r\n", &save);
            strtok_r(NULL, " \t\r\n", &save);
        }
    }
    fclose(f);
    if (!n)
        return 0;
    printf("Axial air velocity Ux in the near wake (mean / rms of the fluctuation):");
    for (int k = 0; k < np; k++) {
        const double m = s[k] / (double)n;
        printf(" at %s %.2f / %.2f m/s;", loc[k], m, sqrt(q[k] / (double)n - m * m));
    }
    printf("\n");
    return 0;
}

/* ---- error against run time ------------------------------------------------------ */
static int cmd_errortime(const options *o)
{
    const double target = o->target ? number("--target", o->target) : 10;
    if (!(target > 0))
        die(2, "--target: '%s' is not a positive error in %%", o->target);
    if (o->nfiles != 1)
        die(2, "errortime: give one POINTS file (see --help)");
    FILE *f = open_in(o->files[0]);
    char line[4096];
    for (int ln = 1; fgets(line, sizeof line, f); ln++) {
        line[strcspn(line, "\r\n")] = 0;
        char *fld[4], *save = NULL;
        int k = 0;
        for (char *t = strtok_r(line, "\t", &save); t && k < 4; t = strtok_r(NULL, "\t", &save))
            fld[k++] = t;
        if (k != 4)
            die(2, "%s line %d is not \"design run wall_s error\" (tab-separated)", o->files[0], ln);
        const double t = number(o->files[0], fld[2]), e = number(o->files[0], fld[3]);
        printf("| %s | %s | %.0f | %.1f | %.3g |\n", fld[0], fld[1], t, e,
               swe_time_for_error(t, e, target));
    }
    fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        die(2, "give a command (see --help)");
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, stdout);
        return 0;
    }
    options o = {0};
    parse(argc, argv, &o);
    int rc;
    if (!strcmp(argv[1], "distribution"))
        rc = cmd_distribution(&o);
    else if (!strcmp(argv[1], "weights"))
        rc = cmd_weights(&o);
    else if (!strcmp(argv[1], "classes"))
        rc = cmd_classes(&o);
    else if (!strcmp(argv[1], "regions"))
        rc = cmd_regions(&o);
    else if (!strcmp(argv[1], "map"))
        rc = cmd_map(&o);
    else if (!strcmp(argv[1], "outline"))
        rc = cmd_outline(&o);
    else if (!strcmp(argv[1], "rear-stats"))
        rc = cmd_rear_stats(&o);
    else if (!strcmp(argv[1], "forces"))
        rc = cmd_forces(&o);
    else if (!strcmp(argv[1], "probes"))
        rc = cmd_probes(&o);
    else if (!strcmp(argv[1], "errortime"))
        rc = cmd_errortime(&o);
    else
        die(2, "unknown command '%s' (see --help)", argv[1]);
    free(o.files);
    return rc;
}
