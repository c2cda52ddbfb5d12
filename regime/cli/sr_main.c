/* sr_main.c - snowregime: stick/bounce regime maps of snow particles on a wall.
 * Subcommand dispatch, shared option handling and the manual pages. */
#include <stdlib.h>
#include <string.h>

#include "sr.h"

static const char *help_main =
"NAME\n"
"    snowregime - stick/bounce regime of dry-snow particles hitting a wall\n"
"\n"
"SYNOPSIS\n"
"    snowregime COMMAND [OPTIONS]\n"
"    snowregime COMMAND --help\n"
"    snowregime --help | --version\n"
"\n"
"DESCRIPTION\n"
"    Runs the SnowWall DEM collision kernel (one ice sphere hitting a flat wall,\n"
"    JKR adhesion with hysteresis, Thornton plastic COR, friction and rolling\n"
"    resistance) and turns many impacts into a regime map, its fitted interface\n"
"    d_crit(v_n) and the regime.coeffs file the wall model reads.\n"
"\n"
"COMMANDS\n"
"    collide       one impact: outcome, rebound COR, contact time, trajectory\n"
"    vcrit         critical normal sticking velocity per diameter (bisection)\n"
"    map           regime map over diameter x normal speed, fit, regime.coeffs, PNG\n"
"    sensitivity   each material parameter at the ends of its range: map changes\n"
"    convergence   error of v_crit against wall time per collision (accuracy knob)\n"
"\n"
"SETTINGS (every command)\n"
"    --config FILE        read settings, one \"key value\" or \"key = value\" per line, # comments\n"
"    --set KEY=VALUE      override one setting (repeatable; applied after --config)\n"
"    Keys (SI units, defaults = dry snow (ice) on ABS):\n"
"      rho 920  E 9.8e9  nu 0.31  sigma_y 1e6  E_wall 2e9  nu_wall 0.35  rho_wall 1100\n"
"      gamma 0.2  adhesion jkr|none  z0 3e-10\n"
"      cor elastic|<e in (0,1]>|thornton|thornton-asymptote|thornton-ning (default thornton)\n"
"        thornton*: a dashpot set to Thornton's plastic COR; thornton-ning: no dashpot,\n"
"        the adhesive elastic-plastic contact law of Thornton & Ning (yield at 2.5 sigma_y)\n"
"      dashpot loading|both (when the COR dashpot acts; default loading; refused\n"
"        with cor elastic or thornton-ning, which have no dashpot)\n"
"      cor_pair wall|particle  mu 0.05  xi_crit 1e-9  accuracy 60 (steps per Hertz contact time)\n"
"      wall flat|lattice (default flat). A lattice is a rough wall of hemispherical\n"
"        asperities of the wall material (doc/kernel.md): lattice square|hex,\n"
"        asperity_r 1e-6 (radius), asperity_spacing 2e-6 (nearest neighbours;\n"
"        2 r: touching; below 2 r, overlapping, refused), asperity_jitter 0 (random\n"
"        lateral offset / spacing, <= 0.5),\n"
"        asperity_dz 0 (random sinking depth [m], below asperity_r), wall_seed 1\n"
"        (integer), rough_hold 30 (contact times in contact after which a held\n"
"        sphere counts as stuck).\n"
"        On a lattice the outcome is a stick probability over impact points\n"
"        (--points N, --seed S of vcrit and map); cor thornton-ning is refused.\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 computation or output failure; 2 bad option, setting or input.\n"
"    On any failure no output file is left behind.\n"
"\n"
"EXAMPLES\n"
"    snowregime collide --d 50e-6 --vn 0.5\n"
"    snowregime vcrit --d 10e-6,50e-6,100e-6\n"
"    snowregime map --out results/map --set gamma=0.5\n";

static const char *help_collide =
"NAME\n"
"    snowregime collide - simulate one impact of an ice sphere on the wall\n"
"\n"
"SYNOPSIS\n"
"    snowregime collide --d D --vn V [--vt V] [--omega W] [--x X --y Y] [--trace-csv FILE]\n"
"                       [--trace-vtk FILE] [--stride N] [--config FILE] [--set KEY=VALUE]...\n"
"\n"
"DESCRIPTION\n"
"    Integrates one impact from first contact until the outcome is decided and\n"
"    prints it: bounce, stick (normal contact kept and sliding and rolling\n"
"    arrested) or contact-kept-sliding (normal contact kept, still moving\n"
"    tangentially), with the rebound CORs, the contact time, the largest\n"
"    overlap, the time step, the number of steps and its bound, the energy\n"
"    balance error of the integration and any warning (e.g. Tabor parameter\n"
"    outside the JKR range).\n"
"\n"
"OPTIONS\n"
"    --d D             particle diameter [m] (required, 1e-7 .. 0.1)\n"
"    --vn V            normal approach speed [m/s] (required, > 0 and <= 1000;\n"
"                      without adhesion >= 1e-60: below it a Hertz contact's\n"
"                      scaled radii would overflow)\n"
"    --vt V            tangential speed [m/s] (default 0)\n"
"    --omega W         initial spin [rad/s] (default 0)\n"
"    --x X, --y Y      rough wall (wall lattice): the impact point [m], where the\n"
"                      sphere centre is when its lowest point crosses the plane of\n"
"                      the asperity tops (default 0, 0: on top of an asperity)\n"
"    --trace-csv FILE  trajectory as CSV: t, centre x and z, overlap, speeds, force, contact radius, spin\n"
"    --trace-vtk FILE  trajectory as legacy VTK polydata (a polyline of the particle\n"
"                      centre with the same quantities as point data), for ParaView\n"
"    --stride N        trace every N-th step (default 1)\n"
"    --config FILE, --set KEY=VALUE   settings (see snowregime --help)\n"
"\n"
"OUTPUT\n"
"    \"key: value\" lines on stdout (SI units): outcome, contact_kept, stick, e_n, e_t,\n"
"    t_contact, delta_max, e_target, t_rest and s_rest (kept contacts: time and\n"
"    distance along the wall until sliding and rolling stop; inf: never), dt, steps,\n"
"    max_steps, status, energy_err, tabor, warning; on a rough wall also x, y and\n"
"    contacts (asperity and base-plane contacts made).\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 output failure; 2 bad option, setting or input.\n"
"\n"
"EXAMPLES\n"
"    snowregime collide --d 20e-6 --vn 0.3\n"
"    snowregime collide --d 50e-6 --vn 1 --vt 0.5 --trace-vtk impact.vtk --trace-csv impact.csv\n";

static const char *help_vcrit =
"NAME\n"
"    snowregime vcrit - critical normal sticking velocity per diameter\n"
"\n"
"SYNOPSIS\n"
"    snowregime vcrit --d D1,D2,... [--vt V | --angle DEG] [--omega W] [--full-stick]\n"
"                     [--max-slide S] [--points N] [--seed S] [--level P]\n"
"                     [--tol T] [--vmin V] [--vmax V] [--scan-ratio R] [--threads N]\n"
"                     [--config FILE] [--set KEY=VALUE]...\n"
"\n"
"DESCRIPTION\n"
"    For each diameter, scans the normal speed over [vmin, vmax] at log-spaced\n"
"    points (ratio R) for the first stick -> bounce change, then bisects in\n"
"    ln(v_n) until the bracket [v_lo, v_hi] has v_hi/v_lo <= 1 + T; v_crit is its\n"
"    geometric mean (relative error <= T/2 on top of the kernel's accuracy).\n"
"    The outcome is \"normal contact kept\" unless --full-stick. A non-monotone\n"
"    outcome (sticks again above v_crit) is detected in the scan and reported.\n"
"    On a rough wall (--set wall=lattice) \"sticks\" means: the fraction of N\n"
"    impact points (uniform over the lattice's cell, the same points at every\n"
"    speed) that stick is >= P; v_crit is where that fraction falls below P.\n"
"\n"
"OPTIONS\n"
"    --d LIST          diameters [m], comma separated (required)\n"
"    --vt V            tangential speed of every impact [m/s] (default 0)\n"
"    --angle DEG       instead: impact angle from the wall normal, vt = vn tan(DEG)\n"
"    --omega W         initial spin [rad/s] (default 0)\n"
"    --full-stick      outcome = contact kept AND sliding and rolling arrested\n"
"    --max-slide S     outcome = full stick AND at rest within S metres of the\n"
"                      impact point (the kernel's predicted travel s_rest)\n"
"    --points N        rough wall: impact points per speed (default 64)\n"
"    --seed S          rough wall: seed of the impact points (default 1)\n"
"    --level P         rough wall: stick fraction of v_crit, in (0, 1] (default 0.5);\n"
"                      --points, --seed and --level are refused on a flat wall\n"
"    --tol T           relative bracket width (default 1e-3)\n"
"    --vmin V, --vmax V  search range [m/s] (default 1e-3, 50)\n"
"    --scan-ratio R    ratio of neighbouring scan speeds (default 2)\n"
"    --threads N       threads over the diameters (default 2)\n"
"    --config FILE, --set KEY=VALUE   settings (see snowregime --help)\n"
"\n"
"OUTPUT\n"
"    Lines starting with # are comments (settings, per-diameter details:\n"
"    bracket, collisions, steps, time step, non-monotone and range warnings).\n"
"    Every other line is  <d in m><TAB><v_crit in m/s> , one per diameter, in\n"
"    the order given. When no change is found in [vmin, vmax] the value is nan\n"
"    and a comment says whether it bounces or sticks everywhere.\n"
"\n"
"EXIT STATUS\n"
"    0 every v_crit found; 1 some diameter has no v_crit in the range;\n"
"    2 bad option, setting or input.\n"
"\n"
"EXAMPLES\n"
"    snowregime vcrit --d 10e-6,50e-6,100e-6\n"
"    snowregime vcrit --d 30e-6 --set cor=elastic --tol 1e-5\n";

static const char *help_map =
"NAME\n"
"    snowregime map - stick/bounce regime map, fitted interface, regime.coeffs\n"
"\n"
"SYNOPSIS\n"
"    snowregime map --out DIR [--nd N] [--nv N] [--dmin D] [--dmax D] [--vmin V]\n"
"                   [--vmax V] [--vlog 0|1] [--degree K] [--full-stick] [--max-slide S]\n"
"                   [--vt LIST | --angle LIST] [--omega W] [--refine 0|1] [--tol T]\n"
"                   [--points N] [--seed S] [--threads N] [--no-plot]\n"
"                   [--config FILE] [--set KEY=VALUE]...\n"
"\n"
"DESCRIPTION\n"
"    Simulates every point of a diameter x normal-speed grid (rows split over\n"
"    threads). Diameters are linearly spaced, speeds log-spaced (or linear with\n"
"    --vlog 0). Without --vmin/--vmax the speed range is [v_crit(dmax)/1.5,\n"
"    1.5 v_crit(dmin)], so the interface lies inside it. In each speed column the\n"
"    first stick -> bounce change along d is refined by bisection in ln d to\n"
"    relative width T (--refine 0: midpoint of the two grid cells). The points\n"
"    are fitted by least squares (GSL) as ln d_crit = sum_i c_i (ln v_n)^i; when\n"
"    the fit of degree K is not non-increasing over its span, lower degrees are\n"
"    tried (reported).\n"
"    With --vt LIST or --angle LIST (impact angle from the normal in degrees,\n"
"    vt = vn tan(angle)) one map per value is made and the outcome is full stick;\n"
"    a map of the series whose interface cannot be fitted (too few points) is\n"
"    written without fit and without its coeffs file, with a warning.\n"
"    With --vt LIST starting at 0 (0,V1,V2,... increasing) the combined\n"
"    regime.coeffs is written too: the v_t = 0 fit plus the table of d_crit(v_n,\n"
"    v_t) (the largest diameter that sticks, by bisection in ln d over 0.1 um -\n"
"    10 cm) on those v_t and on log-spaced v_n from a decade below the map's range\n"
"    to 3x above it, for the wall model's tangential gate `model regime`. Use\n"
"    --max-slide S with it: on a flat wall an adhered particle always stops, so\n"
"    S (stick = at rest within S) is what makes v_t matter.\n"
"    On a rough wall (--set wall=lattice) every grid point is the stick fraction\n"
"    p over N impact points (uniform over the lattice's cell, seeded by S, the\n"
"    same points everywhere), with its binomial error sqrt(p (1 - p) / N); the\n"
"    interface is the p = 0.5 contour (bisected at the same points), fitted as\n"
"    above, and the p = 0.1 and 0.9 contours are written beside it. regime.coeffs\n"
"    then carries the stick-probability table (probabilityD/Vn/Stick, at most\n"
"    4096 cells), read by the wall model, and the PNG shows p. A rough map takes\n"
"    one --vt V at most (no --vt LIST or --angle).\n"
"\n"
"OPTIONS\n"
"    --out DIR         output folder (created; required)\n"
"    --nd N, --nv N    grid size (default 46 x 50; at most 1e6 cells)\n"
"    --dmin, --dmax    diameter range [m] (default 10e-6, 100e-6)\n"
"    --vmin, --vmax    normal speed range [m/s] (default automatic)\n"
"    --vlog 0|1        log-spaced speeds (default 1)\n"
"    --degree K        polynomial degree of the fit, 1..8 (default 3)\n"
"    --full-stick      outcome = full stick (default: normal contact kept)\n"
"    --max-slide S     outcome = full stick AND at rest within S m of the impact\n"
"                      point (the kernel's predicted travel s_rest); with the\n"
"                      kernel's friction and rolling resistance an adhered\n"
"                      particle always stops eventually, so this is what makes the\n"
"                      tangential speed / angle a real axis\n"
"    --vt LIST         tangential speeds [m/s], strictly increasing: one map each\n"
"                      (full stick); starting at 0 the table holds the list's\n"
"                      length x the speed nodes of --nv (about 2 nv) within 4096\n"
"                      values: a longer list is refused before any map\n"
"    --angle LIST      impact angles from the normal [deg], strictly increasing: one\n"
"                      map each (full stick)\n"
"    --omega W         initial spin [rad/s] (default 0)\n"
"    --refine 0|1      refine interface points by bisection (default 1)\n"
"    --tol T           relative tolerance of the refinement (default 1e-3)\n"
"    --points N        rough wall: impact points per grid point (default 64;\n"
"                      refused on a flat wall, as --seed is)\n"
"    --seed S          rough wall: seed of the impact points (default 1)\n"
"    --threads N       threads (default 2)\n"
"    --no-plot         do not run gnuplot (no PNG)\n"
"    --config FILE, --set KEY=VALUE   settings (see snowregime --help)\n"
"\n"
"OUTPUT\n"
"    In DIR (SUFFIX is empty, or -vt<V> / -angle<A> per third-axis value):\n"
"    mapSUFFIX.csv         d_m,vn_m_s,stick,contact_kept,e_n,e_t,status per grid point\n"
"    interfaceSUFFIX.csv   vn_m_s,dcrit_m,dfit_m,rel_residual per interface point\n"
"    fitSUFFIX.txt         degree, coefficients, residuals, slopes, counts, timing\n"
"    regimeSUFFIX.coeffs   the interface for the wall model (doc/regime-coeffs.md)\n"
"    regime.coeffs         with --vt 0,...: the v_t = 0 interface and the d_crit(v_n,\n"
"                          v_t) table (obliqueVt, obliqueVn, obliqueDCrit, obliqueSlide)\n"
"    mapSUFFIX.png         the map with the interface points and the fit (gnuplot)\n"
"    Rough wall: map.csv adds p_stick,p_err,points; contours.csv (level,vn_m_s,dcrit_m)\n"
"    holds the p = 0.1, 0.5 and 0.9 contours; map.png shows p with the contours.\n"
"    A summary is printed on stdout. All files appear together or not at all.\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 computation failure (e.g. no interface inside the grid, gnuplot\n"
"    failed); 2 bad option, setting or input.\n"
"\n"
"EXAMPLES\n"
"    snowregime map --out results/map\n"
"    snowregime map --out results/map-g05 --set gamma=0.5 --degree 4\n"
"    snowregime map --out results/angles --angle 0,30,60 --max-slide 100e-6 --nd 20 --nv 30\n"
"    snowregime map --out results/oblique --vt 0,0.25,0.5,1,2,4,8 --max-slide 100e-6\n"
"    snowregime map --out results/rough --set wall=lattice --points 64\n";

static const char *help_sensitivity =
"NAME\n"
"    snowregime sensitivity - regime map change with each material parameter\n"
"\n"
"SYNOPSIS\n"
"    snowregime sensitivity --out DIR [--nd N] [--nv N] [--dmin D] [--dmax D]\n"
"                   [--vmin V] [--vmax V] [--vlog 0|1] [--refine 0|1] [--tol T]\n"
"                   [--threads N] [--no-plot] [--config FILE] [--set KEY=VALUE]...\n"
"\n"
"DESCRIPTION\n"
"    Computes the baseline map (settings as given) and, on the same grid, a map\n"
"    with each material parameter at each end of its range (snow-physics.md\n"
"    section 2), the others at baseline: E 8.9e9 / 11.2e9 Pa, nu 0.29 / 0.36,\n"
"    gamma 0.1 / 1.0 J/m2, sigma_y 0.5e6 / 1.5e6 Pa. Reports the number of\n"
"    sticking grid points, its ratio to the baseline, and the shift of the\n"
"    interface: the mean relative change of d_crit over the speed columns where\n"
"    both maps have an interface point.\n"
"\n"
"OPTIONS\n"
"    Grid options as for snowregime map (--nd --nv --dmin --dmax --vmin --vmax\n"
"    --vlog --refine --tol --max-slide; the automatic speed range comes from the\n"
"    baseline); on a rough wall (--set wall=lattice) --points N and --seed S,\n"
"    and the sticking cells are those with p_stick >= 0.5 (snowregime map);\n"
"    --threads N (default 2); --no-plot; settings.\n"
"    --out DIR         output folder (created; required)\n"
"\n"
"OUTPUT\n"
"    sensitivity.csv             param,value,n_stick,ratio,d_shift_rel,columns,n_interface\n"
"    sensitivity.md              the same as a markdown table\n"
"    sensitivity-interfaces.csv  param,value,vn_m_s,dcrit_m for every map\n"
"    sensitivity.png             the interfaces overlaid\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 computation or output failure; 2 bad option, setting or input.\n"
"\n"
"EXAMPLES\n"
"    snowregime sensitivity --out results/sensitivity\n"
"    snowregime sensitivity --out results/sens-small --nd 20 --nv 20\n";

static const char *help_convergence =
"NAME\n"
"    snowregime convergence - error of v_crit against wall time per collision\n"
"\n"
"SYNOPSIS\n"
"    snowregime convergence --out DIR [--d LIST] [--accuracy LIST] [--ref-factor F]\n"
"                   [--tol T] [--min-time S] [--no-plot] [--config FILE] [--set KEY=VALUE]...\n"
"\n"
"DESCRIPTION\n"
"    For each diameter, v_crit is computed at every accuracy setting (key\n"
"    `accuracy`, steps per Hertz contact time) and at a reference accuracy F times\n"
"    the largest setting, each with bisection tolerance T (well below the errors\n"
"    measured). Reports the relative error of v_crit against the reference and\n"
"    the wall time per collision of the search (median of 5 blocks, each\n"
"    repeating the search for at least S seconds; 1 thread), with the steps per\n"
"    collision and the time step.\n"
"\n"
"OPTIONS\n"
"    --out DIR         output folder (created; required)\n"
"    --d LIST          diameters [m] (default 10e-6,30e-6,100e-6)\n"
"    --accuracy LIST   accuracy settings, >= 10 (default 10,15,20,30,45,60,90,120,180,240)\n"
"    --ref-factor F    reference accuracy = F x the largest setting (default 8)\n"
"    --tol T           bisection tolerance (default 1e-7)\n"
"    --min-time S      minimum wall time of each of the 5 timed blocks [s] (default 0.01)\n"
"    --no-plot         do not run gnuplot\n"
"\n"
"OUTPUT\n"
"    convergence.csv  d_m,accuracy,vcrit_m_s,vcrit_ref_m_s,rel_error,us_per_collision,\n"
"                     steps_per_collision,dt_s,cpu_us_per_collision (thread CPU time:\n"
"                     less sensitive to other processes than the wall time)\n"
"    convergence.md   the same as a markdown table\n"
"    convergence.png  relative error against time per collision, log-log\n"
"\n"
"EXIT STATUS\n"
"    0 success; 1 computation or output failure; 2 bad option, setting or input.\n"
"\n"
"EXAMPLES\n"
"    snowregime convergence --out results/convergence\n";

void sr_help(const char *cmd)
{
    const char *t = help_main;
    if (cmd && strcmp(cmd, "collide") == 0) t = help_collide;
    else if (cmd && strcmp(cmd, "vcrit") == 0) t = help_vcrit;
    else if (cmd && strcmp(cmd, "map") == 0) t = help_map;
    else if (cmd && strcmp(cmd, "sensitivity") == 0) t = help_sensitivity;
    else if (cmd && strcmp(cmd, "convergence") == 0) t = help_convergence;
    fputs(t, stdout);
}

int sr_opt(sr_args *a, const char *name, const char **val)
{
    const char *w = a->argv[a->i];
    size_t n = strlen(name);
    if (strncmp(w, name, n) != 0) return 0;
    if (w[n] == '=') { *val = w + n + 1; return 1; }
    if (w[n] != '\0') return 0;
    if (a->i + 1 >= a->argc) {
        *val = NULL;
        snprintf(a->err, sizeof a->err, "%s: missing value", name);
        return 1;
    }
    *val = a->argv[++a->i];
    return 1;
}

int sr_flag(sr_args *a, const char *name)
{
    return strcmp(a->argv[a->i], name) == 0;
}

int sr_settings_opt(sr_args *a, sr_settings *s)
{
    const char *v;
    if (sr_opt(a, "--config", &v)) {
        if (!v) return -1;
        s->config = v;
        return 1;
    }
    if (sr_opt(a, "--set", &v)) {
        if (!v) return -1;
        if (s->nsets == (int)(sizeof s->sets / sizeof s->sets[0])) {
            snprintf(a->err, sizeof a->err, "--set: too many (max 256)");
            return -1;
        }
        s->sets[s->nsets++] = v;
        return 1;
    }
    if (sr_opt(a, "--threads", &v)) {
        long n;
        if (!v || swt_parse_int("--threads", v, 1, 64, &n, a->err, sizeof a->err) != 0) return -1;
        s->threads = (int)n;
        return 1;
    }
    return 0;
}

int sr_settings_apply(const sr_settings *s, swr_params *p, char *err, size_t errlen)
{
    char e[300];
    swr_params_default(p);
    if (s->config && swr_params_load(p, s->config, e, sizeof e) != 0) {
        snprintf(err, errlen, "--config: %s", e);
        return -1;
    }
    for (int k = 0; k < s->nsets; k++)
        if (swr_params_set_kv(p, s->sets[k], e, sizeof e) != 0) {
            snprintf(err, errlen, "--set: %s", e);
            return -1;
        }
    if (swr_params_validate(p, e, sizeof e) != 0) {
        snprintf(err, errlen, "settings: %s", e);
        return -1;
    }
    return 0;
}

int sr_rough_opt(sr_args *a, swt_vcrit_opts *o)
{
    const char *v;
    long n;
    if (sr_opt(a, "--points", &v)) {
        if (!a->rough_only) a->rough_only = "--points";
        if (!v || swt_parse_int("--points", v, 1, 100000, &n, a->err, sizeof a->err) != 0) return -1;
        o->points = (int)n;
        return 1;
    }
    if (sr_opt(a, "--seed", &v)) {
        if (!a->rough_only) a->rough_only = "--seed";
        if (!v || swt_parse_int("--seed", v, 0, 4294967295L, &n, a->err, sizeof a->err) != 0) return -1;
        o->seed = (unsigned long)n;
        return 1;
    }
    if (sr_opt(a, "--level", &v)) {
        if (!a->rough_only) a->rough_only = "--level";
        if (!v || swt_parse_double("--level", v, 1e-6, 1.0, &o->level, a->err, sizeof a->err) != 0)
            return -1;
        return 1;
    }
    return 0;
}

int sr_rough_only_check(const sr_args *a, const swr_model *m, char *err, size_t errlen)
{
    if (!a->rough_only || swr_model_rough(m))
        return 0;
    snprintf(err, errlen, "%s: only for a rough wall (--set wall=lattice); this wall is flat, "
             "where every impact point gives the same outcome", a->rough_only);
    return -1;
}

const char *sr_outcome_text(const swt_vcrit_opts *o, char *buf, size_t n)
{
    if (o->max_slide > 0.0)
        snprintf(buf, n, "full stick, at rest within %g m of the impact", o->max_slide);
    else
        snprintf(buf, n, "%s", o->full_stick ? "full stick" : "normal contact kept");
    return buf;
}

int sr_usage_error(const char *cmd, const char *msg)
{
    fprintf(stderr, "snowregime%s%s: %s\n", cmd ? " " : "", cmd ? cmd : "", msg);
    return SR_EXIT_USAGE;
}

int sr_out_error(const char *cmd, const char *dir, const char *msg)
{
    fprintf(stderr, "snowregime %s: --out: '%s': %s\n", cmd, dir, msg);
    return SR_EXIT_USAGE;
}

int sr_fail(const char *cmd, const char *msg)
{
    fprintf(stderr, "snowregime%s%s: %s\n", cmd ? " " : "", cmd ? cmd : "", msg);
    return SR_EXIT_FAIL;
}

/* v_crit of diameter d for the automatic speed range, or -1 with a message. */
static int auto_vcrit(const swr_model *m, double d, const swt_vcrit_opts *vo, double *vcrit,
                      char *err, size_t errlen)
{
    swt_vcrit_result r;
    swt_vcrit(m, d, vo, &r);
    if (r.status != SWT_VCRIT_FOUND) {
        snprintf(err, errlen, "automatic speed range: no v_crit for d = %g m in [%g, %g] m/s "
                 "(%s); give --vmin and --vmax", d, vo->vmin, vo->vmax,
                 r.status == SWT_VCRIT_ALL_STICK ? "sticks everywhere" :
                 r.status == SWT_VCRIT_NO_STICK ? "bounces everywhere" : r.msg);
        return -1;
    }
    *vcrit = r.vcrit;
    return 0;
}

int sr_auto_vrange(const swr_model *m, swt_grid *g, int set_min, int set_max,
                   const swt_vcrit_opts *o, char *err, size_t errlen)
{
    swt_vcrit_opts vo = *o;
    vo.vmin = 1e-4;
    vo.vmax = SWR_V_MAX;
    vo.rtol = 1e-2;
    double v;
    if (!set_min) {
        if (auto_vcrit(m, g->dmax, &vo, &v, err, errlen) != 0)
            return -1;
        g->vmin = v / 1.5;
    }
    if (!set_max) {
        if (auto_vcrit(m, g->dmin, &vo, &v, err, errlen) != 0)
            return -1;
        /* within the speeds the kernel accepts */
        g->vmax = 1.5 * v < SWR_V_MAX ? 1.5 * v : SWR_V_MAX;
    }
    if (!(g->vmax > g->vmin)) {
        snprintf(err, errlen, "speed range [%g, %g] m/s is empty: give --vmin and --vmax",
                 g->vmin, g->vmax);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("usage: snowregime COMMAND [OPTIONS]   (snowregime --help for the manual)\n", stderr);
        return SR_EXIT_USAGE;
    }
    const char *c = argv[1];
    if (strcmp(c, "--help") == 0 || strcmp(c, "-h") == 0 || strcmp(c, "help") == 0) {
        sr_help(argc > 2 ? argv[2] : NULL);
        return 0;
    }
    if (strcmp(c, "--version") == 0) {
        puts("snowregime (SnowWall) 0.1");
        return 0;
    }
    if (strcmp(c, "collide") == 0) return sr_cmd_collide(argc - 1, argv + 1);
    if (strcmp(c, "vcrit") == 0) return sr_cmd_vcrit(argc - 1, argv + 1);
    if (strcmp(c, "map") == 0) return sr_cmd_map(argc - 1, argv + 1);
    if (strcmp(c, "sensitivity") == 0) return sr_cmd_sensitivity(argc - 1, argv + 1);
    if (strcmp(c, "convergence") == 0) return sr_cmd_convergence(argc - 1, argv + 1);
    fprintf(stderr, "snowregime: unknown command '%s' (snowregime --help lists them)\n", c);
    return SR_EXIT_USAGE;
}
