/* swc_main.c - snowdeposit: turbulent deposition in a fully developed channel
 * with the C core's near-wall dispersion model, and the calibration of its
 * sublayer closure (doc/deposition.md). */
#include "swc_channel.h"
#include "swo_out.h"
#include "swp_nearwall.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *usage =
"NAME\n"
"    snowdeposit - turbulent particle deposition in a channel with SnowWall's\n"
"    near-wall dispersion model; calibration of its sublayer closure\n"
"\n"
"SYNOPSIS\n"
"    snowdeposit channel   [--tau-plus LIST] [--closure LAW] [common options]\n"
"    snowdeposit calibrate --out FILE [--law LAW] [--tau-plus LIST] [common options]\n"
"    snowdeposit check FILE\n"
"    snowdeposit --help\n"
"\n"
"DESCRIPTION\n"
"    Both commands follow N particles in the wall-normal direction of a fully\n"
"    developed channel, in wall units (u_tau = nu = 1): the half channel\n"
"    0 < y+ < Re_tau with a mirror at the centreplane. The fluid velocity a\n"
"    particle sees is the continuous random walk of the C core (wallmodel/core/\n"
"    swd.h: anisotropic wall-layer statistics below layerYPlus, isotropic\n"
"    sqrt(2k/3) of the channel's k above blendYPlus); the particle follows it\n"
"    with Stokes drag of relaxation time tau+. A particle that reaches the wall\n"
"    deposits and is replaced by one at a random height, so the mean\n"
"    concentration C stays fixed, and after the warm-up the deposition velocity\n"
"    V+ = J / (C u_tau) is the deposits D times Re_tau over N and the window.\n"
"    Its standard error comes from 20 batch means (never below the Poisson\n"
"    error of D).\n"
"\n"
"    channel prints one line per tau+: V+, its standard error, the deposits by\n"
"    the particles' own motion (D_track) and the expected deposits of the\n"
"    sublayer closure (E_closure, its probabilities summed), the law's V+ (Wood 1981, the\n"
"    correlation of the measurements: 4.5e-4 tau+^2 up to its plateau 0.13,\n"
"    Brownian term omitted) and their ratio, the sublayer concentration over the\n"
"    mean, the particle steps and the mean step dt+. With --closure the model's\n"
"    sublayer closure is calibrated first (as calibrate does) and then used.\n"
"\n"
"    check reads FILE as the near-wall model reads a closure (the\n"
"    depositionClosure sub-dictionary that calibrate writes, with the default\n"
"    settings of the walk) and says whether it can be used: exit 0 with one\n"
"    line (the sublayer and Vs+ at tau+ 1), or exit 2 with one line naming the\n"
"    file, the line and the key. The benchmark scripts call it before any work.\n"
"\n"
"    calibrate computes the sublayer closure: the CRW alone misses most of the\n"
"    measured deposition below tau+ of about 5; the closure adds the rest as a\n"
"    deposition rate of the particles inside the sublayer y+ < S,\n"
"    lambda+ = Vs+(tau+) / S, with Vs+ = max(0, V+_law - V+_crw) / c_s (c_s the\n"
"    CRW's sublayer concentration over the mean), corrected once by a run with\n"
"    the closure. It writes FILE (an OpenFOAM dictionary\n"
"    depositionClosure { ... }, doc/deposition.md) and prints the table.\n"
"\n"
"OPTIONS\n"
"    --tau-plus LIST     comma-separated tau+ values, each in (0, 1e4], at most 64,\n"
"                        each once, no empty item; a list out of order is taken in\n"
"                        ascending order, with a note on stderr (default channel\n"
"                        0.1,0.3,1,3,10,30,100; calibrate\n"
"                        0.03,0.1,0.2,0.3,0.5,1,2,3,5,7,10,20,30,100,300)\n"
"    --closure LAW       channel: calibrate the closure for LAW and use it\n"
"    --law LAW           calibrate: wood (default) or mccoy-hanratty\n"
"                        (3.5e-4 tau+^2 up to its plateau 0.17, as FDS uses it)\n"
"    --out FILE          calibrate: the coefficients file to write (see OUTPUT)\n"
"    --sublayer S        the closure's sublayer y+ < S, in (0, layerYPlus] (default 10)\n"
"    --re-tau R          channel half-height in wall units, (10, 1e5] (default 314,\n"
"                        Liu & Agarwal's pipe at Re = 10 000)\n"
"    --particles N       particles, 1 .. 1e8 (default 2000)\n"
"    --t-warm T          warm-up t+, [0, 1e9] (default 2000)\n"
"    --t-run T           measurement window t+, (0, 1e9] (default 20000)\n"
"    --dt-max D          largest step dt+, (0, 100] (default 2)\n"
"    --c-tl C            step <= C T_L, (0, 1] (default 0.1)\n"
"    --c-y C             step <= C y / speed, (0, 1] (default 0.2)\n"
"    --scheme S          exact (default) or host: the particle's position moved\n"
"                        with its velocity at the start of a step, as OpenFOAM's\n"
"                        tracking moves a parcel\n"
"    --gravity G         gravity towards the wall, G = g nu / u_tau^3 in [0, 1]\n"
"                        (default 0): the particles settle at G tau+ (V+ of settling\n"
"                        alone); the centreplane's mirror then makes the half\n"
"                        channel one of height 2 Re_tau with gravity towards both\n"
"                        walls, the wall layer as under a floor\n"
"    --c-below Y         channel: the band y+ < Y (< Re_tau) whose concentration over\n"
"                        the mean is printed as c_sub (default 10)\n"
"    --radius            deposit when the particle's surface touches the wall\n"
"                        (r+ = d+/2 of an ice sphere in air at -15 C, from tau+)\n"
"                        instead of its centre\n"
"    --set KEY=VALUE     a setting of the near-wall model: layerYPlus, blendYPlus,\n"
"                        CT, Cmu (wallmodel/core/swd.h)\n"
"    --seed S            random seed, an integer >= 0 (default 1)\n"
"    --force             run even when the work estimate is over the limit below\n"
"                        (--out is a single file: there is no folder to force)\n"
"    -h, --help          this text\n"
"\n"
"WORK LIMIT\n"
"    Before any work the command estimates the particle steps from below:\n"
"    N (t-warm + t-run) / dt-max per tau+ value and run (calibrate makes two\n"
"    runs per value, channel --closure three). Over 1e10 steps (at about\n"
"    0.25 us a step on a 2-core reference machine, over 40 min) it refuses,\n"
"    exit 2, unless --force is given; over 4e8 steps (about 100 s) it prints\n"
"    the estimate to stderr before it starts.\n"
"\n"
"OUTPUT\n"
"    calibrate --out FILE: FILE appears whole or not at all: it is written to a\n"
"    temporary in its folder (.tmp-NAME.XXXXXX), flushed and closed with every\n"
"    error checked (a full disk is exit 1, the temporary removed) and renamed\n"
"    over FILE at the end. Checked before any work: FILE's folder must exist\n"
"    and be writable, and FILE is replaced only when it is absent or a regular\n"
"    file: a folder, device (/dev/full, /dev/null), FIFO, socket or symbolic link\n"
"    there is refused (exit 2) and left as it is.\n"
"\n"
"EXIT STATUS\n"
"    0 success, 2 usage or input error (one line naming the option and the value),\n"
"    1 other failure. Interrupted (SIGINT, SIGTERM, SIGHUP), calibrate leaves no\n"
"    file: the temporary is removed and the signal ends the run.\n"
"\n"
"EXAMPLES\n"
"    snowdeposit channel --tau-plus 1,10 --particles 4000\n"
"    snowdeposit calibrate --out deposition.coeffs\n";

#define MAXTAU 64

typedef struct {
    swc_params p;
    double tau[MAXTAU];
    size_t ntau;
    const char *out;
    const char *law;
    int law_given;   /* --law was on the command line */
    const char *closure;
    double sublayer;
    int radius;
    int force;   /* --force: run beyond the work limit */
} opts;

static int usage_error(const char *fmt, const char *a, const char *b)
{
    fprintf(stderr, "snowdeposit: ");
    fprintf(stderr, fmt, a, b);
    fprintf(stderr, " (see snowdeposit --help)\n");
    return 2;
}

static int number(const char *opt, const char *s, double *v)
{
    char *end;
    errno = 0;
    const double x = strtod(s, &end);
    if (end == s || *end || errno == ERANGE || !isfinite(x) || strpbrk(s, "xXnN"))
        return usage_error("%s: '%s' is not a finite decimal number", opt, s);
    *v = x;
    return 0;
}

/* --tau-plus: the comma-list rule of every tool (swo_out.h): no empty item,
 * each value once, taken in ascending order with a note */
static int parse_list(const char *opt, const char *s, double *v, size_t *n)
{
    double *x = NULL;
    int k = 0;
    char note[600], err[600];
    if (swo_list_numbers(opt, s, 0.0, 1e4, 1, MAXTAU, &x, &k, note, sizeof note, err,
                         sizeof err) != SWO_OK) {
        fprintf(stderr, "snowdeposit: %s (see snowdeposit --help)\n", err);
        return 2;
    }
    if (note[0])
        fprintf(stderr, "snowdeposit: note: %s\n", note);
    memcpy(v, x, (size_t)k * sizeof *v);
    *n = (size_t)k;
    free(x);
    return 0;
}

static double law_value(const char *law, double t)
{
    if (!strcmp(law, "mccoy-hanratty")) {
        const double v = 3.5e-4 * t * t;
        return v < 0.17 ? v : 0.17;
    }
    return swp_wood_vplus(t, 0.0);
}

static int check_law(const char *opt, const char *law)
{
    if (strcmp(law, "wood") && strcmp(law, "mccoy-hanratty"))
        return usage_error("%s: '%s' is not a law (wood, mccoy-hanratty)", opt, law);
    return 0;
}

/* r+ of an ice sphere (920 kg/m3) in air at -15 C with this tau+ at u_tau = 1 m/s:
 * d+ = d u_tau / nu, d from tau+; r+ = d+/2 (in wall units it depends on tau+ and
 * the density ratio only) */
static double radius_plus(double tau_plus)
{
    const double mu = 1.641e-5, nu = 1.2e-5, rho_p = 920.0;
    const double d = swp_d_of_tau_plus(tau_plus, rho_p, mu, nu, 1.0);
    return 0.5 * d * 1.0 / nu;
}

/* FILE through the common writer (the set `o` opened and FILE checked before the work) */
static int write_coeffs(const opts *o, swo_set *set, const swd_model *m, const double *vs,
                        const double *law, const double *vcrw, const double *vcrw_se,
                        const double *cs)
{
    char err[600];
    FILE *f = swo_open(set, o->out, err, sizeof err);
    if (f) {
        fprintf(f, "// SnowWall near-wall dispersion: sublayer deposition closure\n"
                   "// written by: snowdeposit calibrate (doc/deposition.md)\n"
                   "// channel Re_tau %g, %zu particles, window t+ %g, seed %lu\n\n",
                o->p.re_tau, o->p.n, o->p.t_run, o->p.seed);
        fprintf(f, "depositionClosure\n{\n    version 1;\n    law %s;\n    reTau %g;\n", o->law,
                o->p.re_tau);
        fprintf(f, "    sublayerYPlus %g;\n", o->sublayer);
        for (size_t k = 0; swd_key(k); k++)
            fprintf(f, "    %s %.10g;    // the CRW setting calibrated with\n", swd_key(k),
                    swd_get(m, swd_key(k)));
        const struct {
            const char *name;
            const double *v;
        } cols[] = { { "tauPlus", o->tau },      { "vPlusSublayer", vs },
                     { "vPlusLaw", law },        { "vPlusCrw", vcrw },
                     { "vPlusCrwError", vcrw_se }, { "cSublayer", cs } };
        for (size_t c = 0; c < sizeof cols / sizeof cols[0]; c++) {
            fprintf(f, "    %s (", cols[c].name);
            for (size_t i = 0; i < o->ntau; i++)
                fprintf(f, " %.9g", cols[c].v[i]);
            fprintf(f, " );\n");
        }
        fprintf(f, "}\n");
    }
    if (!f || swo_commit(set, err, sizeof err) != SWO_OK) {
        fprintf(stderr, "snowdeposit: --out: %s\n", err);
        return swo_code(set);
    }
    return 0;
}

static int parse(int argc, char **argv, opts *o, swd_model *m)
{
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            exit(0);
        }
        if (!strcmp(a, "--radius")) {
            o->radius = 1;
            continue;
        }
        if (!strcmp(a, "--force")) {
            o->force = 1;
            continue;
        }
        if (!v)
            return usage_error("%s needs a value%s", a, "");
        i++;
        if (!strcmp(a, "--tau-plus")) {
            if (parse_list(a, v, o->tau, &o->ntau))
                return 2;
        } else if (!strcmp(a, "--out")) {
            o->out = v;
        } else if (!strcmp(a, "--law")) {
            if (check_law(a, v))
                return 2;
            o->law = v;
            o->law_given = 1;
        } else if (!strcmp(a, "--closure")) {
            if (check_law(a, v))
                return 2;
            o->closure = v;
        } else if (!strcmp(a, "--scheme")) {
            if (!strcmp(v, "exact"))
                o->p.scheme = SWC_EXACT;
            else if (!strcmp(v, "host"))
                o->p.scheme = SWC_HOST;
            else
                return usage_error("%s: '%s' is not a scheme (exact, host)", a, v);
        } else if (!strcmp(a, "--set")) {
            const char *eq = strchr(v, '=');
            char key[64];
            if (!eq || eq == v || (size_t)(eq - v) >= sizeof key)
                return usage_error("%s: '%s' is not KEY=VALUE", a, v);
            memcpy(key, v, (size_t)(eq - v));
            key[eq - v] = '\0';
            char opt[80];
            snprintf(opt, sizeof opt, "--set %s", key);   /* the message names the key */
            if (number(opt, eq + 1, &x))
                return 2;
            if (swd_set(m, key, x) != SWD_OK) {
                fprintf(stderr, "snowdeposit: --set %s: %s\n", v, swd_errmsg(m));
                return 2;
            }
        } else if (!strcmp(a, "--particles") || !strcmp(a, "--seed")) {
            if (number(a, v, &x))
                return 2;
            const double hi = !strcmp(a, "--seed") ? 4294967295.0 : 1e8;
            const double lo = !strcmp(a, "--seed") ? 0.0 : 1.0;
            if (x != floor(x) || x < lo || x > hi) {
                fprintf(stderr, "snowdeposit: %s: %s is not an integer in [%.0f, %.10g] (see "
                        "snowdeposit --help)\n", a, v, lo, hi);
                return 2;
            }
            if (!strcmp(a, "--seed"))
                o->p.seed = (unsigned long)x;
            else
                o->p.n = (size_t)x;
        } else {
            /* option, destination, accepted range (lo open?) */
            const struct {
                const char *opt;
                double *dst, lo, hi;
                int lo_open;
            } num[] = {
                { "--re-tau", &o->p.re_tau, 10, 1e5, 1 },  { "--t-warm", &o->p.t_warm, 0, 1e9, 0 },
                { "--t-run", &o->p.t_run, 0, 1e9, 1 },     { "--dt-max", &o->p.dt_max, 0, 100, 1 },
                { "--c-tl", &o->p.c_tl, 0, 1, 1 },         { "--c-y", &o->p.c_y, 0, 1, 1 },
                { "--sublayer", &o->sublayer, 0, 200, 1 },
                { "--gravity", &o->p.g_plus, 0, 1, 0 },    { "--c-below", &o->p.y_sub, 0, 1e5, 1 },
            };
            size_t k = 0;
            while (k < sizeof num / sizeof num[0] && strcmp(a, num[k].opt))
                k++;
            if (k == sizeof num / sizeof num[0])
                return usage_error("unknown option '%s'%s", a, "");
            if (number(a, v, &x))
                return 2;
            if (!((num[k].lo_open ? x > num[k].lo : x >= num[k].lo) && x <= num[k].hi)) {   /* x finite */
                fprintf(stderr, "snowdeposit: %s: %s is outside %s%g, %g] (see snowdeposit --help)\n",
                        a, v, num[k].lo_open ? "(" : "[", num[k].lo, num[k].hi);
                return 2;
            }
            *num[k].dst = x;
        }
    }
    if (swd_commit(m) != SWD_OK) {
        fprintf(stderr, "snowdeposit: --set: %s\n", swd_errmsg(m));
        return 2;
    }
    char err[256];
    if (!(o->p.y_sub < o->p.re_tau)) {   /* finite: bounded above */
        fprintf(stderr, "snowdeposit: --c-below: %g is not below Re_tau %g (see snowdeposit "
                        "--help)\n", o->p.y_sub, o->p.re_tau);
        return 2;
    }
    swc_params q = o->p;
    if (swc_params_check(&q, err, sizeof err)) {
        fprintf(stderr, "snowdeposit: %s (see snowdeposit --help)\n", err);
        return 2;
    }
    if (!(o->sublayer > 0.0 && o->sublayer <= swd_get(m, "layerYPlus")))   /* finite */
        return usage_error("--sublayer: %s is outside (0, layerYPlus]%s",
                           (snprintf(err, sizeof err, "%g", o->sublayer), err), "");
    return 0;
}

/* snowdeposit check FILE: a closure file, read as the model reads it: usable or not, before
 * any work; the exit status */
static int cmd_check(int argc, char **argv)
{
    if (argc == 3 && (!strcmp(argv[2], "-h") || !strcmp(argv[2], "--help"))) {
        fputs(usage, stdout);
        return 0;
    }
    if (argc != 3)
        return usage_error("check takes one FILE%s%s", "", "");
    swd_model *m = swd_alloc();
    if (!m) {
        fprintf(stderr, "snowdeposit: out of memory\n");
        return 1;
    }
    if (swd_load_closure(m, argv[2]) != SWD_OK || swd_commit(m) != SWD_OK) {
        fprintf(stderr, "snowdeposit: check: %s\n", swd_errmsg(m));
        swd_free(m);
        return 2;
    }
    printf("%s: a sublayer closure for the default walk, Vs+ %g at tau+ 1\n", argv[2],
           swd_closure_vs(m, 1.0));
    swd_free(m);
    return 0;
}

/* the options that do not go with the command (calibrate's --out, the other command's --law or
 * --closure): refused, not dropped; 0, or the exit status with the message printed */
static int command_mismatch(int cal, const opts *o)
{
    if (cal && !o->out)
        return usage_error("calibrate needs --out FILE%s%s", "", "");
    if (!cal && o->out)
        return usage_error("--out is an option of calibrate, not of channel%s%s", "", "");
    /* an option of the other command is refused, not dropped */
    if (!cal && o->law_given)
        return usage_error("--law is an option of calibrate, not of channel (channel --closure %s "
                           "calibrates for that law and uses it)%s", o->law, "");
    if (cal && o->closure)
        return usage_error("--closure is an option of channel, not of calibrate (calibrate --law %s "
                           "names the law to calibrate for)%s", o->closure, "");
    return 0;
}

/* the work, estimated from below before any of it: a run of centuries (1e8 particles over t+
 * 1e9) is refused, not started without a word; 0, or 2 with the message printed */
static int estimate_work(int cal, const opts *o)
{
    const double runs = cal ? 2.0 : (o->closure ? 3.0 : 1.0);
    const double steps = (double)o->p.n * (o->p.t_warm + o->p.t_run) / o->p.dt_max
                         * (double)o->ntau * runs;
    const double sec = steps * 0.25e-6;
    if (steps > 1e10 && !o->force) {
        fprintf(stderr,
                "snowdeposit: the run needs at least %.3g particle steps (--particles %zu x "
                "(--t-warm %g + --t-run %g) / --dt-max %g x %zu tau+ x %g runs), about %.3g h; "
                "the limit is 1e10 steps (about 40 min): use fewer particles or a shorter "
                "window, or --force\n",
                steps, o->p.n, o->p.t_warm, o->p.t_run, o->p.dt_max, o->ntau, runs, sec / 3600.0);
        return 2;
    }
    if (steps > 4e8)
        fprintf(stderr, "snowdeposit: estimate: at least %.3g particle steps, about %.0f s "
                        "at 0.25 us a step\n", steps, sec);
    return 0;
}

/* snowdeposit channel's table: a run of the channel per tau+ (with the closure in m, if any);
 * 0, or 2 with the message printed */
static int channel_table(const opts *o, const swd_model *m)
{
    const size_t n = o->ntau;
    char err[256];
    printf("# Re_tau %g, %zu particles, warm-up t+ %g, window t+ %g, scheme %s%s%s, gravity "
           "g+ %g, c_sub in y+ < %g\n",
           o->p.re_tau, o->p.n, o->p.t_warm, o->p.t_run, o->p.scheme == SWC_EXACT ? "exact" : "host",
           o->closure ? ", closure " : "", o->closure ? o->closure : "", o->p.g_plus, o->p.y_sub);
    printf("%10s %12s %10s %9s %10s %12s %8s %8s %10s %7s\n", "tau+", "V+", "se", "D_track",
           "E_closure", "V+_wood", "ratio", "c_sub", "steps", "dt+");
    for (size_t i = 0; i < n; i++) {
        swc_params q = o->p;
        swc_result r;
        q.tau_plus = o->tau[i];
        q.r_plus = o->radius ? radius_plus(o->tau[i]) : 0.0;
        q.seed = o->p.seed + 7919 * (i + 1);
        if (swc_run(m, &q, &r, err, sizeof err)) {
            fprintf(stderr, "snowdeposit: %s\n", err);
            return 2;
        }
        const double w = swp_wood_vplus(o->tau[i], 0.0);
        printf("%10.4g %12.4e %10.2e %9zu %10.2f %12.4e %8.3g %8.3f %10.3e %7.3f\n", o->tau[i],
               r.vplus, r.vplus_se, r.deposits, r.expected_closure, w, r.vplus / w, r.c_sub,
               r.steps, r.dt_mean);
        fflush(stdout);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs(usage, stderr);
        return 2;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, stdout);
        return 0;
    }
    if (!strcmp(argv[1], "check"))
        return cmd_check(argc, argv);
    const int cal = !strcmp(argv[1], "calibrate");
    swo_signals_on();   /* interrupted, calibrate leaves no temporary behind */
    if (!cal && strcmp(argv[1], "channel"))
        return usage_error("unknown command '%s'%s (channel, calibrate, check)", argv[1], "");

    opts o;
    memset(&o, 0, sizeof o);
    swc_params_default(&o.p);
    o.law = "wood";
    o.sublayer = 10.0;
    if (cal) {
        const double t[] = { 0.03, 0.1, 0.2, 0.3, 0.5, 1, 2, 3, 5, 7, 10, 20, 30, 100, 300 };
        o.ntau = sizeof t / sizeof t[0];
        memcpy(o.tau, t, sizeof t);
    } else {
        const double t[] = { 0.1, 0.3, 1, 3, 10, 30, 100 };
        o.ntau = sizeof t / sizeof t[0];
        memcpy(o.tau, t, sizeof t);
    }
    swd_model *m = swd_alloc();
    if (!m) {
        fprintf(stderr, "snowdeposit: out of memory\n");
        return 1;
    }
    int rc = parse(argc, argv, &o, m);
    if (!rc)
        rc = command_mismatch(cal, &o);
    if (rc) {
        swd_free(m);
        return rc;
    }
    /* calibrate's FILE: its folder takes files and FILE is absent or a regular
       file, checked before the work */
    swo_set *set = NULL;
    if (cal) {
        char err[600];
        const swo_spec spec = { "snowdeposit calibrate", "--out", NULL, 0, 0 };
        int c = swo_alloc(&spec, &set, err, sizeof err);
        if (c == SWO_OK)
            c = swo_check(set, o.out, err, sizeof err);
        if (c != SWO_OK) {
            fprintf(stderr, "snowdeposit: --out: %s\n", err);
            swo_free(set);
            swd_free(m);
            return c;
        }
    }
    if (estimate_work(cal, &o)) {
        swo_free(set);
        swd_free(m);
        return 2;
    }
    const size_t n = o.ntau;
    double law[MAXTAU], vs[MAXTAU], vcrw[MAXTAU], vcrw_se[MAXTAU], cs[MAXTAU], vt[MAXTAU],
        vt_se[MAXTAU];
    const char *lawname = cal ? o.law : (o.closure ? o.closure : "wood");
    for (size_t i = 0; i < n; i++)
        law[i] = law_value(lawname, o.tau[i]);
    char err[256];
    if (cal || o.closure) {
        if (o.radius)
            fprintf(stderr, "snowdeposit: note: the closure is calibrated for point particles "
                            "(--radius is used by channel's own runs only)\n");
        rc = swc_calibrate(m, &o.p, o.sublayer, o.tau, law, n, vs, vcrw, vcrw_se, cs, vt, vt_se,
                           err, sizeof err);
        if (rc) {
            fprintf(stderr, "snowdeposit: %s\n", err);
            swo_free(set);
            swd_free(m);
            return rc == -1 ? 2 : 1;
        }
    }
    if (cal) {
        printf("# law %s, sublayer y+ < %g, Re_tau %g, %zu particles, window t+ %g\n", o.law,
               o.sublayer, o.p.re_tau, o.p.n, o.p.t_run);
        printf("%10s %12s %12s %10s %10s %12s\n", "tau+", "V+_law", "V+_crw", "se", "c_s",
               "Vs+");
        for (size_t i = 0; i < n; i++)
            printf("%10.4g %12.4e %12.4e %10.2e %10.3f %12.4e\n", o.tau[i], law[i], vcrw[i],
                   vcrw_se[i], cs[i], vs[i]);
        rc = write_coeffs(&o, set, m, vs, law, vcrw, vcrw_se, cs);
        swo_free(set);
        swd_free(m);
        return rc;
    }
    if (o.closure && swd_set_closure(m, o.sublayer, o.tau, vs, n) == SWD_OK)
        swd_commit(m);
    rc = channel_table(&o, m);
    swd_free(m);
    return rc;
}
