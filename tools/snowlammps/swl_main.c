/* swl_main.c - snowlammps: the rough-wall impacts of the kernel checked against
 * LAMMPS; options, help, exit status. The work is in swl_compare.c. */
#include "swl_lammps.h"
#include "swo_out.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *usage =
"NAME\n"
"    snowlammps - the rough-wall impacts of the kernel checked against LAMMPS\n"
"\n"
"SYNOPSIS\n"
"    snowlammps --out DIR [--force] [--lmp LMP] [--deck FILE] [--d D] [--grid K] [--angles LIST]\n"
"               [--speeds-hertz LIST] [--speeds-jkr LIST] [--cases LIST] [--cor E]\n"
"               [--lmp-steps N] [--halve] [--no-single] [--tol-v T] [--tol-w T]\n"
"               [--tol-e T] [--tol-vz-jkr T]\n"
"    snowlammps --help\n"
"\n"
"DESCRIPTION\n"
"    Runs the same impacts of one ice sphere on the kernel's default rough wall\n"
"    (wall lattice: a square lattice of hemispherical ABS asperities, radius and\n"
"    spacing as in `snowregime --help`) in the kernel's 3-D multi-contact\n"
"    integrator (regime/kernel/swr_rough.c, linked in: libswrkernel) and in LAMMPS\n"
"    (Debian's `lmp`, pair_style granular, one process per batch of impacts), and\n"
"    compares the rebound velocity (v_x, v_y, v_z), the spin (w_x, w_y, w_z), the\n"
"    number of contacts made and stick/bounce (x along the incoming tangential\n"
"    motion, z the wall normal). In LAMMPS the asperities are frozen spheres of\n"
"    radius r centred on z = 0, the base plane is fix wall/gran, the sphere is\n"
"    integrated by nve/sphere (the input deck tools/snowlammps/impact.lmp).\n"
"    Both codes use the kernel's default material constants. Normally run through\n"
"    validation/lammps-rough.sh, which adds --quick and an output folder that\n"
"    appears whole or not at all.\n"
"\n"
"    Cases (--cases, comma list):\n"
"      hertz        Hertz without adhesion, constant COR E on both branches (the\n"
"                   kernel: cor E, dashpot both; LAMMPS: damping tsuji, its input\n"
"                   calibrated until the flat-wall COR is E), Mindlin friction (mu),\n"
"                   no rolling resistance\n"
"      jkr-elastic  JKR (gamma) without damping, Mindlin friction, rolling resistance\n"
"                   (LAMMPS: rolling sds matched at a = a0); LAMMPS's contacts break\n"
"                   at its own pull-off overlap, so each loses less energy at\n"
"                   separation: accounted for per contact (dU)\n"
"      jkr          JKR with the COR dashpot of hertz\n"
"    Before the impacts: the COR calibration on the flat plane and one asperity,\n"
"    and (with a jkr case, unless --no-single) the separation overlap and the\n"
"    sticking velocity of a head-on impact on one asperity in both codes against\n"
"    the closed forms.\n"
"\n"
"OPTIONS\n"
"    --out DIR            output folder (made when missing; its parent must exist):\n"
"                         see OUTPUT for the folders it takes\n"
"    --force              write into a DIR that is not empty and not a SnowWall\n"
"                         output folder (its impacts.csv and summary.md are\n"
"                         replaced, nothing else is touched, no marker is added)\n"
"    --lmp LMP            the LAMMPS binary, a path or a name on PATH (default lmp)\n"
"    --deck FILE          LAMMPS input deck of one impact (default\n"
"                         ../tools/snowlammps/impact.lmp beside this program's folder,\n"
"                         else the source tree's)\n"
"    --d D                particle diameter [m] (default 10e-6; 2e-6 .. 1e-4)\n"
"    --grid K             K x K impact points over the lattice's unit cell,\n"
"                         x, y = 0, s/K, ..., (K-1)s/K (default 5: 25 points; 1..20)\n"
"    --angles LIST        impact angles from the normal [deg] (default 0,30,60; each\n"
"                         in [0, 80]): v_n = V cos, v_t = V sin (along +x)\n"
"    --speeds-hertz LIST  impact speeds V of the hertz case [m/s] (default 0.5,2);\n"
"                         the smallest is the speed of the COR calibration\n"
"    --speeds-jkr LIST    impact speeds V of the jkr cases [m/s] (default 0.3,1);\n"
"                         each speed in (0, 20]; every list at most 16 numbers,\n"
"                         each once, no empty item; a list out of order is taken\n"
"                         in ascending order, with a note on stderr\n"
"    --cases LIST         hertz, jkr-elastic, jkr (default hertz,jkr), each once,\n"
"                         run in the order given\n"
"    --cor E              the constant COR of the damped cases (default 0.7; 0.3 .. 0.95)\n"
"    --lmp-steps N        LAMMPS steps per flat-wall Hertz contact time (default 100;\n"
"                         20 .. 2000); the kernel keeps its own `accuracy` (60)\n"
"    --halve              also run every impact at half the step in both codes\n"
"                         (LAMMPS dt/2, the kernel accuracy x 2): the step error\n"
"    --no-single          skip the single-contact JKR checks (separation overlap,\n"
"                         sticking velocities: about 80 short LAMMPS runs)\n"
"    --tol-v T            |dv_x|, |dv_y|, |dv_z| (hertz) tolerance in units of V\n"
"                         (default 0.03)\n"
"    --tol-w T            R |dw_x|, R |dw_y|, R |dw_z| tolerance in units of V (default 0.05)\n"
"    --tol-e T            jkr-elastic: energy tolerance in units of E_in (default 0.05)\n"
"    --tol-vz-jkr T       jkr: |dv_z| tolerance in units of V (default 0.1)\n"
"                         (every tolerance in (0, 10])\n"
"    -h, --help           this text\n"
"\n"
"TOLERANCES (justified in doc/kernel.md, \"Cross-check against LAMMPS\")\n"
"    On bounces in both codes: |dv_x|, |dv_y| <= tol_v V, R |dw_x|, R |dw_y|, R |dw_z|\n"
"    <= tol_w V, the same number of contacts. hertz: also |dv_z| <= tol_v V and the same outcome. jkr-elastic:\n"
"    |E_L - E_s - n dU| <= tol_e E_in instead of dv_z; a kernel stick against a\n"
"    LAMMPS bounce is allowed when LAMMPS's v_z^2/2 - n dU <= tol_e E_in. jkr:\n"
"    |dv_z| <= tol_vz_jkr V; the outcome may differ when the code that bounces leaves\n"
"    with v_z <= tol_vz_jkr V. LAMMPS's sphere counts as stuck when it has not left\n"
"    after 100 flat-wall contact times.\n"
"\n"
"OUTPUT\n"
"    DIR is a SnowWall output folder (it holds .snowwall-output: tool, time): made\n"
"    when missing, or an empty folder, or one that holds the marker; a folder\n"
"    holding anything else is refused before any work (exit 2) unless --force; a\n"
"    symbolic link or a non-folder is refused. Each file appears whole or not at\n"
"    all (a temporary in DIR, every write error checked, renamed at the end); a\n"
"    folder, device, FIFO, socket or link at a file's name is refused and left.\n"
"    Files of other names in DIR are never touched. LAMMPS works in DIR/.work-XXXXXX,\n"
"    a folder of the run's own, removed at the end.\n"
"    DIR/summary.md   the calibration table and one row per case, speed and angle:\n"
"                     outcomes, contacts, the largest deviations, the step-halving\n"
"                     changes, the energy check, the count within the tolerances;\n"
"                     the run times; 'impacts outside the tolerances: N of M'\n"
"    DIR/impacts.csv  every impact in both codes (and at half the step with --halve):\n"
"                     ours_* the kernel, lmp_* LAMMPS, ours2_*, lmp2_* at half the\n"
"                     step; velocities [m/s], spins [rad/s]; the last nine columns\n"
"                     are the kernel's v_y, w_x, w_z and both codes' halved ones\n"
"                     (LAMMPS's are lmp_vy, lmp_wx, lmp_wz)\n"
"    standard output  summary.md, then one 'outside:' line per impact outside the\n"
"                     tolerances\n"
"\n"
"ENVIRONMENT\n"
"    OMPI_MCA_pml     set to ob1 for lmp unless already set (one process: skips the\n"
"                     UCX probing, halves lmp's start-up)\n"
"\n"
"EXIT STATUS\n"
"    0  done, every impact within the tolerances\n"
"    1  a run failed (lmp missing or failing, no or a NaN result, an output not written)\n"
"    2  usage error (the option and the value are named), a refused --out\n"
"    3  done, some impact outside the tolerances (listed on standard output)\n"
"\n"
"EXAMPLES\n"
"    snowlammps --out results/lr --halve\n"
"    snowlammps --out /tmp/lr --grid 2 --speeds-jkr 1 --cases hertz,jkr-elastic --no-single\n"
"    validation/lammps-rough.sh --out /tmp/lr --quick --check\n";

static int usage_error(const char *fmt, const char *a, const char *b)
{
    fprintf(stderr, "snowlammps: ");
    fprintf(stderr, fmt, a, b);
    fprintf(stderr, " (see snowlammps --help)\n");
    return 2;
}

/* a finite number in [lo, hi] (lo excluded when lo_open) */
static int num(const char *opt, const char *s, double lo, double hi, int lo_open, double *out)
{
    char *end;
    errno = 0;
    const double v = s && *s ? strtod(s, &end) : NAN;
    if (!s || !*s || *end || errno == ERANGE || !isfinite(v) || v > hi || (lo_open ? v <= lo : v < lo)) {
        char msg[200];
        snprintf(msg, sizeof msg, "'%%s' is not a number in %s%g, %g]", lo_open ? "(" : "[", lo, hi);
        fprintf(stderr, "snowlammps: %s ", opt);
        fprintf(stderr, msg, s ? s : "");
        fprintf(stderr, " (see snowlammps --help)\n");
        return -1;
    }
    *out = v;
    return 0;
}

/* a comma list of numbers: the rule of every tool (swo_out.h) */
static int list(const char *opt, const char *s, double lo, double hi, int lo_open, double *v, int *n)
{
    double *x = NULL;
    char note[600], err[600];
    if (swo_list_numbers(opt, s, lo, hi, lo_open, SWL_MAXLIST, &x, n, note, sizeof note, err,
                         sizeof err) != SWO_OK) {
        fprintf(stderr, "snowlammps: %s (see snowlammps --help)\n", err);
        return -1;
    }
    if (note[0])
        fprintf(stderr, "snowlammps: note: %s\n", note);
    memcpy(v, x, (size_t)*n * sizeof *v);
    free(x);
    return 0;
}

/* the deck beside the program: <dir of the executable>/../tools/snowlammps/impact.lmp */
static void default_deck(char *buf, size_t n)
{
    char exe[PATH_MAX];
    const ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (k <= 0) {
        snprintf(buf, n, "tools/snowlammps/impact.lmp");
        return;
    }
    exe[k] = '\0';
    char *sl = strrchr(exe, '/');
    if (sl) *sl = '\0';
    snprintf(buf, n, "%s/../tools/snowlammps/impact.lmp", exe);
#ifdef SWL_SOURCE_DECK
    if (access(buf, R_OK) != 0) /* in the build tree: the source's */
        snprintf(buf, n, "%s", SWL_SOURCE_DECK);
#endif
}

int main(int argc, char **argv)
{
    static swl_opts o;
    static char deck[PATH_MAX + 64];
    o.lmp = "lmp";
    o.d = 10e-6;
    o.grid = 5;
    o.angles_s = "0,30,60";
    o.speeds_h_s = "0.5,2";
    o.speeds_j_s = "0.3,1";
    const char *cases_s = "hertz,jkr";
    o.cor = 0.7;
    o.lmp_steps = 100.0;
    o.tol_v = 0.03;
    o.tol_w = 0.05;
    o.tol_e = 0.05;
    o.tol_vz_jkr = 0.1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            fputs(usage, stdout);
            return fflush(stdout) == 0 && !ferror(stdout) ? 0 : 1;
        }
        if (strcmp(a, "--halve") == 0) { o.halve = 1; continue; }
        if (strcmp(a, "--no-single") == 0) { o.no_single = 1; continue; }
        if (strcmp(a, "--force") == 0) { o.force = 1; continue; }
        static const char *valued[] = { "--out", "--lmp", "--deck", "--d", "--grid", "--angles",
                                         "--speeds-hertz", "--speeds-jkr", "--cases", "--cor",
                                         "--lmp-steps", "--tol-v", "--tol-w", "--tol-e",
                                         "--tol-vz-jkr" };
        int known = 0;
        for (size_t k = 0; k < sizeof valued / sizeof *valued; k++) known |= strcmp(a, valued[k]) == 0;
        if (!known) return usage_error("unknown option '%s'%s", a, "");
        if (i + 1 >= argc || !argv[i + 1][0]) return usage_error("%s needs a value%s", a, "");
        const char *v = argv[++i];
        double x;
        if (strcmp(a, "--out") == 0) o.out = v;
        else if (strcmp(a, "--lmp") == 0) o.lmp = v;
        else if (strcmp(a, "--deck") == 0) snprintf(deck, sizeof deck, "%s", v);
        else if (strcmp(a, "--d") == 0) { if (num(a, v, 2e-6, 1e-4, 0, &o.d)) return 2; }
        else if (strcmp(a, "--grid") == 0) {
            char *end;
            errno = 0;
            const long g = strtol(v, &end, 10);
            if (*end || errno || g < 1 || g > 20 || v[0] < '0' || v[0] > '9')
                return usage_error("--grid '%s' is not a whole number in 1..20%s", v, "");
            o.grid = (int)g;
        } else if (strcmp(a, "--angles") == 0) o.angles_s = v;
        else if (strcmp(a, "--speeds-hertz") == 0) o.speeds_h_s = v;
        else if (strcmp(a, "--speeds-jkr") == 0) o.speeds_j_s = v;
        else if (strcmp(a, "--cases") == 0) cases_s = v;
        else if (strcmp(a, "--cor") == 0) { if (num(a, v, 0.3, 0.95, 0, &o.cor)) return 2; }
        else if (strcmp(a, "--lmp-steps") == 0) { if (num(a, v, 20, 2000, 0, &o.lmp_steps)) return 2; }
        else {
            if (num(a, v, 0, 10, 1, &x)) return 2;
            if (strcmp(a, "--tol-v") == 0) o.tol_v = x;
            else if (strcmp(a, "--tol-w") == 0) o.tol_w = x;
            else if (strcmp(a, "--tol-e") == 0) o.tol_e = x;
            else o.tol_vz_jkr = x;
        }
    }
    if (!o.out) return usage_error("--out DIR is required%s%s", "", "");
    if (list("--angles", o.angles_s, 0, 80, 0, o.angles, &o.nangles) ||
        list("--speeds-hertz", o.speeds_h_s, 0, 20, 1, o.speeds_h, &o.nspeeds_h) ||
        list("--speeds-jkr", o.speeds_j_s, 0, 20, 1, o.speeds_j, &o.nspeeds_j))
        return 2;
    {
        static const char *const names[] = { "hertz", "jkr-elastic", "jkr", NULL };
        char err[600];
        if (swo_list_words("--cases", cases_s, names, SWL_MAXLIST, o.cases, &o.ncases, err,
                           sizeof err) != SWO_OK) {
            fprintf(stderr, "snowlammps: %s (see snowlammps --help)\n", err);
            return 2;
        }
    }
    if (!deck[0]) default_deck(deck, sizeof deck);
    o.deck = deck;
    if (access(deck, R_OK) != 0) {
        fprintf(stderr, "snowlammps: --deck: cannot read '%s' (%s)\n", deck, strerror(errno));
        return 1;
    }
    /* the output folder (swo_out.h: made, or empty, or a SnowWall output folder;
     * a foreign one only with --force) and its file names, checked before any work */
    static char err[SWL_ERRLEN];
    {
        const swo_spec spec = { "snowlammps", "--out", o.out, o.force, 0 };
        int c = swo_alloc(&spec, &o.set, err, sizeof err);
        if (c == SWO_OK && (c = swo_check(o.set, "impacts.csv", err, sizeof err)) == SWO_OK)
            c = swo_check(o.set, "summary.md", err, sizeof err);
        if (c != SWO_OK) {
            fprintf(stderr, "snowlammps: %s\n", err);
            swo_free(o.set);
            return c;
        }
        if (swo_note(o.set))
            fprintf(stderr, "snowlammps: note: %s\n", swo_note(o.set));
    }
    swo_signals_on();
    setenv("OMPI_MCA_pml", "ob1", 0); /* single process: skip UCX probing (halves start-up) */
    const int rc = swl_compare_run(&o, stdout, err, sizeof err);
    swo_free(o.set);   /* after a failure: its temporaries and the folder it made removed */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "snowlammps: standard output: write error\n");
        return 1;
    }
    if (rc < 0) {
        fprintf(stderr, "snowlammps: %s\n", err);
        return 1;
    }
    return rc;
}
