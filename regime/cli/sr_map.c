/* sr_map.c - snowregime map and snowregime sensitivity. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

/* the wall model reads at most this many values per list (wallmodel/core) */
#define SWW_TABLE_MAX 4096

/* Grid and map options shared by map and sensitivity. */
typedef struct {
    swt_grid g;
    int set_vmin, set_vmax;
    int degree, refine, plot;
    swt_vcrit_opts o;       /* outcome, tangential motion, tolerance */
    const char *out;
    int force;              /* --force: run even when estimated above SR_LONG_RUN_S, and
                               write into a non-empty folder that is not an output folder */
    swt_progress_mode progress; /* --progress: the progress line also off a terminal */
    swt_progress *pg;       /* the run's progress report (set by the command) */
} sr_mapopt;

static void mapopt_default(sr_mapopt *m)
{
    memset(m, 0, sizeof *m);
    m->g = (swt_grid){ 46, 50, 10e-6, 100e-6, 0.0, 0.0, 1 };
    m->degree = 3;
    m->refine = 1;
    m->plot = 1;
    swt_vcrit_opts_default(&m->o);
}

/* 1 taken, 0 not mine, -1 error */
static int mapopt_parse(sr_args *a, sr_mapopt *m)
{
    const char *v;
    long n;
    if (sr_flag(a, "--no-plot")) { m->plot = 0; return 1; }
    if (sr_flag(a, "--force")) { m->force = 1; return 1; }   /* long run and foreign --out folder */
    if (sr_flag(a, "--progress")) { m->progress = SWT_PROGRESS_ON; return 1; }
    if (sr_opt(a, "--out", &v)) {
        if (!v || !*v) { snprintf(a->err, sizeof a->err, "--out: missing folder name"); return -1; }
        m->out = v;
        return 1;
    }
#define INT_OPT(NAME, LO, HI, DST) \
    if (sr_opt(a, NAME, &v)) { \
        if (!v || swt_parse_int(NAME, v, LO, HI, &n, a->err, sizeof a->err)) return -1; \
        DST = (int)n; return 1; }
#define DBL_OPT(NAME, LO, HI, DST, EXTRA) \
    if (sr_opt(a, NAME, &v)) { \
        if (!v || swt_parse_double(NAME, v, LO, HI, &DST, a->err, sizeof a->err)) return -1; \
        EXTRA; return 1; }
    INT_OPT("--nd", 2, 10000, m->g.nd)
    INT_OPT("--nv", 2, 10000, m->g.nv)
    INT_OPT("--vlog", 0, 1, m->g.vlog)
    INT_OPT("--degree", 1, SWT_FIT_MAXDEG, m->degree)
    INT_OPT("--refine", 0, 1, m->refine)
    DBL_OPT("--dmin", SWR_D_MIN, SWR_D_MAX, m->g.dmin, (void)0)
    DBL_OPT("--dmax", SWR_D_MIN, SWR_D_MAX, m->g.dmax, (void)0)
    DBL_OPT("--vmin", SWR_V_MIN, SWR_V_MAX, m->g.vmin, m->set_vmin = 1)
    DBL_OPT("--vmax", SWR_V_MIN, SWR_V_MAX, m->g.vmax, m->set_vmax = 1)
    DBL_OPT("--tol", 1e-12, 0.5, m->o.rtol, (void)0)
    DBL_OPT("--max-slide", 1e-300, 1e3, m->o.max_slide, (void)0)
#undef INT_OPT
#undef DBL_OPT
    return 0;
}

/* Impacts of one map of mo on model m with options o (an estimate): the grid
 * (points per cell on a rough wall) and the interface bisections (the p =
 * 0.1 and 0.9 contours beside it on a rough wall), each evaluation about 60 %
 * of the points (swt_sticks stops once decided). */
static double map_work(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o)
{
    const int rough = swr_model_rough(m);
    const double P = rough ? o->points : 1.0, E = rough ? 0.6 * P : 1.0;
    const double cell = log(mo->g.dmax / mo->g.dmin) / (mo->g.nd - 1);
    const double bis = fmax(1.0, ceil(log2(cell / o->rtol)));
    const double levels = (mo->refine ? 1.0 : 0.0) + (rough ? 2.0 : 0.0);
    return (double)mo->g.nd * mo->g.nv * P + levels * mo->g.nv * bis * E;
}

/* The grid of the pilot before the speed range is known: the given speeds,
 * else 0.01-10 m/s (where sticking thresholds lie) */
static swt_grid pilot_grid(const sr_mapopt *mo)
{
    swt_grid g = mo->g;
    if (!mo->set_vmin) g.vmin = mo->set_vmax ? fmin(1e-2, 0.1 * g.vmax) : 1e-2;
    if (!mo->set_vmax) g.vmax = fmax(10.0, 10.0 * g.vmin);
    return g;
}

/* Grid size guard: a million cells is already about 45 MB of map.csv and
 * seconds to minutes of kernel time; beyond it a typo (--nd 10000 --nv 10000:
 * 4 GB, many minutes) is refused before anything runs. */
#define SR_MAX_CELLS 1000000L

static int mapopt_check(sr_mapopt *m, char *err, size_t errlen)
{
    if (!m->out) { snprintf(err, errlen, "--out: missing (output folder)"); return -1; }
    if ((long)m->g.nd * m->g.nv > SR_MAX_CELLS) {
        snprintf(err, errlen, "--nd x --nv: %d x %d = %ld cells, more than %ld (about %.0f MB of "
                 "map.csv); use a coarser grid", m->g.nd, m->g.nv, (long)m->g.nd * m->g.nv,
                 SR_MAX_CELLS, 45e-6 * (double)m->g.nd * m->g.nv);
        return -1;
    }
    if (!(m->g.dmax > m->g.dmin)) {
        snprintf(err, errlen, "--dmax: '%g' must be > --dmin (%g)", m->g.dmax, m->g.dmin);
        return -1;
    }
    if (m->set_vmin && m->set_vmax && !(m->g.vmax > m->g.vmin)) {
        snprintf(err, errlen, "--vmax: '%g' must be > --vmin (%g)", m->g.vmax, m->g.vmin);
        return -1;
    }
    return 0;
}

/* One computed map with its interface and fit. */
/* Rough wall: the p = 0.1 and 0.9 contours beside the map's p = 0.5 interface. */
typedef struct {
    swt_interface lo, hi;   /* p = 0.1, p = 0.9 */
} sr_contours;

typedef struct {
    swt_map *mp;
    swt_interface it;
    sr_contours *contours;  /* rough wall only, else NULL */
    swt_fit fit;
    int fit_ok;
    char fit_err[300];
    double seconds_total;
} sr_mapres;

static void mapres_free(sr_mapres *r)
{
    swt_map_free(r->mp);
    swt_interface_free(&r->it);
    if (r->contours) {
        swt_interface_free(&r->contours->lo);
        swt_interface_free(&r->contours->hi);
        free(r->contours);
    }
    memset(r, 0, sizeof *r);
}

static int rough_contours(const swr_model *m, const sr_mapres *r, const swt_vcrit_opts *o,
                          int threads, sr_contours *c, char *err, size_t errlen);

static int compute_map(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o,
                       int threads, sr_mapres *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    double t0 = swt_now();
    r->mp = swt_map_alloc(&mo->g, err, errlen);
    if (!r->mp) return -1;
    r->mp->progress = mo->pg;
    if (swt_map_run(r->mp, m, o, threads, err, errlen) != 0) return -1;
    if (swt_interface_extract(r->mp, m, o, mo->refine, threads, &r->it, err, errlen) != 0) return -1;
    r->fit_ok = swt_fit_interface(&r->it, mo->degree, &r->fit, r->fit_err, sizeof r->fit_err) == 0;
    if (r->mp->points > 0) {
        r->contours = calloc(1, sizeof *r->contours);
        if (!r->contours) { snprintf(err, errlen, "out of memory"); return -1; }
        if (rough_contours(m, r, o, threads, r->contours, err, errlen) != 0) return -1;
    }
    r->seconds_total = swt_now() - t0;
    return 0;
}

static void write_map_csv(FILE *f, const sr_mapres *r, const swr_params *p, const char *what)
{
    const swt_map *mp = r->mp;
    fprintf(f, "# snowregime map: %s; %d x %d grid, d %g..%g m (linear), vn %g..%g m/s (%s)\n",
            what, mp->g.nd, mp->g.nv, mp->g.dmin, mp->g.dmax, mp->g.vmin, mp->g.vmax,
            mp->g.vlog ? "log" : "linear");
    fprintf(f, "# stick: 1 sticks (outcome of the map), contact_kept: normal contact kept, "
               "status: 0 ok, 1 step bound\n");
    swr_params_print(p, "# setting ", f);
    if (mp->points > 0) {
        fprintf(f, "# rough wall: p_stick = fraction of the %d impact points that stick, p_err its "
                   "binomial standard error sqrt(p (1 - p) / points); stick = p_stick >= 0.5; e_n the "
                   "mean over the bounces; status 1: some impact still held at the time bound "
                   "(rough_hold), counted as stick\n", mp->points);
        fprintf(f, "d_m,vn_m_s,stick,contact_kept,e_n,e_t,status,p_stick,p_err,points\n");
    } else {
        fprintf(f, "d_m,vn_m_s,stick,contact_kept,e_n,e_t,status\n");
    }
    for (int i = 0; i < mp->g.nd; i++)
        for (int j = 0; j < mp->g.nv; j++) {
            size_t k = (size_t)i * mp->g.nv + j;
            fprintf(f, "%.9g,%.9g,%d,%d,%.6g,%.6g,%d", mp->d[i], mp->v[j], mp->stick[k],
                    mp->kept[k], mp->e_n[k], mp->e_t[k], mp->status[k]);
            if (mp->points > 0) {
                const double pk = mp->p[k];
                fprintf(f, ",%.6g,%.4g,%d", pk, sqrt(pk * (1.0 - pk) / mp->points), mp->points);
            }
            fprintf(f, "\n");
        }
}

static void write_interface_csv(FILE *f, const sr_mapres *r)
{
    fprintf(f, "# interface points: first stick -> bounce change along d in each speed column\n");
    fprintf(f, "# dfit: the fitted polynomial (ln basis), rel_residual = dfit/dcrit - 1\n");
    fprintf(f, "vn_m_s,dcrit_m,dfit_m,rel_residual\n");
    for (int k = 0; k < r->it.n; k++) {
        double df = r->fit_ok ? exp(swt_fit_eval(&r->fit, r->it.vn[k])) : 0.0;
        fprintf(f, "%.9g,%.9g,%.9g,%.6g\n", r->it.vn[k], r->it.dcrit[k], df,
                r->fit_ok ? df / r->it.dcrit[k] - 1.0 : 0.0);
    }
}

static void write_fit_txt(FILE *f, const sr_mapres *r, int threads)
{
    const swt_fit *F = &r->fit;
    fprintf(f, "fit of the interface: ln(d_crit / 1 m) = sum_i c_i (ln(v_n / 1 m/s))^i\n");
    if (!r->fit_ok) fprintf(f, "no fit: %s\n", r->fit_err);
    fprintf(f, "degree: %d (asked %d)\n", F->degree, F->degree_asked);
    if (F->note[0]) fprintf(f, "note: %s\n", F->note);
    fprintf(f, "coeffs:");
    for (int i = 0; i <= F->degree; i++) fprintf(f, " %.10g", F->c[i]);
    fprintf(f, "\npoints: %d\nvn_range: %.6g %.6g m/s\n", F->npts, F->vnmin, F->vnmax);
    fprintf(f, "rms_rel_residual: %.4g\nmax_rel_residual: %.4g\n", F->rms, F->maxres);
    fprintf(f, "slope_low: %.5g\nslope_high: %.5g\n", F->slope_lo, F->slope_hi);
    fprintf(f, "columns_all_stick: %d\ncolumns_all_bounce: %d\ncolumns_nonmonotone: %d\n",
            r->it.cols_all_stick, r->it.cols_all_bounce, r->it.cols_nonmono);
    fprintf(f, "grid_points: %ld\nsticking_points: %ld\nstep_bound_points: %ld\n",
            r->mp->collisions, r->mp->nstick, r->mp->step_bound);
    fprintf(f, "grid_seconds: %.6f\nrefine_collisions: %ld\ntotal_seconds: %.6f\nthreads: %d\n",
            r->mp->seconds, r->it.collisions, r->seconds_total, threads);
}

static void gp_fit_function(FILE *gp, const char *name, const swt_fit *F)
{
    fprintf(gp, "%s(x) = (x < %.10g || x > %.10g) ? 1/0 : 1e6*exp(", name, F->vnmin, F->vnmax);
    for (int i = 0; i <= F->degree; i++) fprintf(gp, "%s(%.17g)*log(x)**%d", i ? " + " : "", F->c[i], i);
    fprintf(gp, ")\n");
}

/* The axes of a map plot: v_n (log when the grid is) against d in um. */
static void gp_map_axes(FILE *f, const swt_map *mp)
{
    fprintf(f, "set datafile separator ','\nset key outside below horizontal\nset format x '%%g'\nset mxtics 10\n");
    if (mp->g.vlog) fprintf(f, "set logscale x\n");
    fprintf(f, "set xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n",
            mp->g.vmin / (mp->g.vlog ? 1.05 : 1.0), mp->g.vmax * 1.05,
            mp->g.dmin * 1e6 - 2, mp->g.dmax * 1e6 + 2);
    fprintf(f, "set xlabel 'normal impact speed v_n [m/s]'\nset ylabel 'particle diameter d [um]'\n");
}

static int write_map_plot(swo_set *os, const char *sfx, const sr_mapres *r, const char *title,
                          char *err, size_t errlen)
{
    char name[128], gpname[128], csv[128], itf[128];
    snprintf(name, sizeof name, "map%s.png", sfx);
    snprintf(gpname, sizeof gpname, "map%s.gp", sfx);
    snprintf(csv, sizeof csv, "map%s.csv", sfx);
    snprintf(itf, sizeof itf, "interface%s.csv", sfx);
    const char *png = swo_add(os, name, err, errlen);
    const char *tcsv = swo_add(os, csv, err, errlen);
    const char *titf = swo_add(os, itf, err, errlen);
    if (!png || !tcsv || !titf) return -1;
    swt_gnuplot g;
    if (swt_gnuplot_open(&g, png, 800, 700, err, errlen) != 0) return -1;
    FILE *f = g.f;
    gp_map_axes(f, r->mp);
    fprintf(f, "set title \"%s\" noenhanced\nset samples 400\n", title);
    if (r->fit_ok) gp_fit_function(f, "dfit", &r->fit);
    fprintf(f, "plot '%s' skip 1 using 2:($3==1 ? $1*1e6 : 1/0) with points pt 5 ps 0.55 lc rgb '#3070d0' title 'stick', \\\n"
               "     '%s' skip 1 using 2:($3==0 ? $1*1e6 : 1/0) with points pt 5 ps 0.55 lc rgb '#e08070' title 'bounce', \\\n"
               "     '%s' skip 1 using 1:($2*1e6) with points pt 7 ps 0.8 lc rgb 'black' title 'interface points'",
            swt_gp_name(tcsv), swt_gp_name(tcsv), swt_gp_name(titf));
    if (r->fit_ok) fprintf(f, ", \\\n     dfit(x) with lines lw 2 lc rgb '#000000' title 'fit d_{crit}(v_n), degree %d'", r->fit.degree);
    fprintf(f, "\n");
    (void)gpname;
    return swt_gnuplot_finish(&g, err, errlen);
}

static int rough_contours(const swr_model *m, const sr_mapres *r, const swt_vcrit_opts *o,
                          int threads, sr_contours *c, char *err, size_t errlen)
{
    /* the interface extraction reads the grid at each options' level */
    memset(c, 0, sizeof *c);
    swt_vcrit_opts o1 = *o, o9 = *o;
    o1.level = 0.1;
    o9.level = 0.9;
    if (swt_interface_extract(r->mp, m, &o1, 1, threads, &c->lo, err, errlen) != 0) return -1;
    return swt_interface_extract(r->mp, m, &o9, 1, threads, &c->hi, err, errlen);
}

static void write_contours_csv(FILE *f, const sr_mapres *r, const sr_contours *c)
{
    fprintf(f, "# contours of the stick probability p(d, v_n) on the rough wall: in each speed "
               "column the first p >= level -> p < level change along d, bisected in ln d\n");
    fprintf(f, "level,vn_m_s,dcrit_m\n");
    const swt_interface *its[3] = { &c->lo, &r->it, &c->hi };
    const double lv[3] = { 0.1, 0.5, 0.9 };
    for (int k = 0; k < 3; k++)
        for (int q = 0; q < its[k]->n; q++)
            fprintf(f, "%g,%.9g,%.9g\n", lv[k], its[k]->vn[q], its[k]->dcrit[q]);
}

static int write_rough_plot(swo_set *os, const char *sfx, const sr_mapres *r, const char *title,
                            char *err, size_t errlen)
{
    char npng[64], ncsv[64], ncon[64];
    snprintf(npng, sizeof npng, "map%s.png", sfx);
    snprintf(ncsv, sizeof ncsv, "map%s.csv", sfx);
    snprintf(ncon, sizeof ncon, "contours%s.csv", sfx);
    const char *png = swo_add(os, npng, err, errlen);
    const char *tcsv = swo_add(os, ncsv, err, errlen);
    const char *tcon = swo_add(os, ncon, err, errlen);
    if (!png || !tcsv || !tcon) return -1;
    swt_gnuplot g;
    if (swt_gnuplot_open(&g, png, 820, 700, err, errlen) != 0) return -1;
    FILE *f = g.f;
    gp_map_axes(f, r->mp);
    fprintf(f, "set cblabel 'stick probability'\nset cbrange [0:1]\n"
               "set palette defined (0 '#e08070', 0.5 '#f4f0e8', 1 '#3070d0')\n");
    fprintf(f, "set title \"%s\" noenhanced\n", title);  /* title: no quotes or backslashes but its \\n */
    fprintf(f, "plot '%s' skip 1 using 2:($1*1e6):8 with points pt 5 ps 1.3 palette notitle, \\\n"
               "     '%s' skip 2 using ($1==0.1 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#804000' title 'p = 0.1', \\\n"
               "     '%s' skip 2 using ($1==0.5 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb 'black' title 'p = 0.5', \\\n"
               "     '%s' skip 2 using ($1==0.9 ? $2 : 1/0):($3*1e6) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#004080' title 'p = 0.9'\n",
            swt_gp_name(tcsv), swt_gp_name(tcon), swt_gp_name(tcon), swt_gp_name(tcon));
    return swt_gnuplot_finish(&g, err, errlen);
}

/* Writes one map's files into the set. */
static int write_map_files(swo_set *os, const char *sfx, const sr_mapres *r, const swr_params *p,
                           const char *what, int plot, int threads, char *err, size_t errlen)
{
    char name[128];
    FILE *f;
    snprintf(name, sizeof name, "map%s.csv", sfx);
    if (!(f = swo_open(os, name, err, errlen))) return -1;
    write_map_csv(f, r, p, what);
    snprintf(name, sizeof name, "interface%s.csv", sfx);
    if (!(f = swo_open(os, name, err, errlen))) return -1;
    write_interface_csv(f, r);
    snprintf(name, sizeof name, "fit%s.txt", sfx);
    if (!(f = swo_open(os, name, err, errlen))) return -1;
    write_fit_txt(f, r, threads);
    char label[200];
    snprintf(label, sizeof label, "%s, gamma %g", what, p->gamma);
    if (r->fit_ok) {
        snprintf(name, sizeof name, "regime%s.coeffs", sfx);
        if (!(f = swo_open(os, name, err, errlen))) return -1;
        /* the kernel's e_n(d, v_n) of this map's bouncing points (issue 23) */
        swt_rebound rb;
        if (swt_rebound_init(&rb, r->mp, NULL, 1, err, errlen) != 0) return -1;
        if (swt_rebound_layer(&rb, 0, r->mp, err, errlen) != 0) { swt_rebound_free(&rb); return -1; }
        swt_coeffs_write_all(f, &r->fit, p, r->mp->g.dmin, r->mp->g.dmax, label, NULL,
                             r->mp->points > 0 ? r->mp : NULL, &rb);
        swt_rebound_free(&rb);
    }
    if (r->contours) {
        snprintf(name, sizeof name, "contours%s.csv", sfx);
        if (!(f = swo_open(os, name, err, errlen))) return -1;
        write_contours_csv(f, r, r->contours);
    }
    if (plot && r->mp->points > 0) {
        fflush(NULL);
        char title[300];
        snprintf(title, sizeof title, "snowregime map: stick probability, %d impact points per cell, "
                 "gamma %g J/m2\\n%s", r->mp->points, p->gamma, what);
        if (write_rough_plot(os, sfx, r, title, err, errlen) != 0) return -1;
    } else if (plot) {
        /* data must be on disk before gnuplot reads the temporaries */
        fflush(NULL);
        char title[300];
        snprintf(title, sizeof title, "snowregime map: %s, gamma %g J/m2, sigma_y %g Pa", what,
                 p->gamma, p->sigma_y);
        if (write_map_plot(os, sfx, r, title, err, errlen) != 0) return -1;
    }
    return 0;
}

/* Speed nodes of the d_crit(v_n, v_t) table for a map grid: the map's log
 * spacing (ln 1.5 on a linear grid), extended a decade below and half a decade
 * above its range (the wall model clamps v_n to the table for the tangential
 * limit); *v_lo, *v_hi get the table's range. */
static int oblique_nodes(const swt_grid *g, double *v_lo, double *v_hi)
{
    *v_lo = g->vmin / 10.0;
    *v_hi = fmin(g->vmax * sqrt(10.0), SWR_V_MAX);
    const double step = g->vlog ? log(g->vmax / g->vmin) / (g->nv - 1) : log(1.5);
    return 1 + (int)ceil(log(*v_hi / *v_lo) / (step > 0.0 ? step : log(1.5)));
}

/* Every file name of the maps (one per --vt / --angle value, suffix -vtV or
 * -angleA) checked before the work: one that is a folder, device, FIFO, socket
 * or link in the output folder is refused before hours of maps, not after. */
static int check_map_names(swo_set *os, const double *axis, int naxis, int axis_angle, char *err,
                           size_t errlen)
{
    static const char *const stem[][2] = { { "map", ".csv" },  { "interface", ".csv" },
                                          { "fit", ".txt" },  { "regime", ".coeffs" },
                                          { "contours", ".csv" }, { "map", ".png" } };
    if (swo_check(os, "regime.coeffs", err, errlen) != SWO_OK)
        return -1;
    for (int k = 0; k < (axis ? naxis : 1); k++) {
        char sfx[64] = "", name[160];
        if (axis)
            snprintf(sfx, sizeof sfx, "-%s%g", axis_angle ? "angle" : "vt", axis[k]);
        for (size_t q = 0; q < sizeof stem / sizeof stem[0]; q++) {
            snprintf(name, sizeof name, "%s%s%s", stem[q][0], sfx, stem[q][1]);
            if (swo_check(os, name, err, errlen) != SWO_OK)
                return -1;
        }
    }
    return 0;
}

int sr_cmd_map(int argc, char **argv)
{
    const char *cmd = "map";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 2;
    sr_mapopt mo;
    mapopt_default(&mo);
    double *axis = NULL, omega = 0.0;
    int naxis = 0, axis_angle = 0, rc = 0;
    const char *v;
    for (; a.i < argc; a.i++) {
        int r = sr_settings_opt(&a, &s);
        if (r == 0) r = mapopt_parse(&a, &mo);
        if (r == 0 && strncmp(argv[a.i], "--level", 7) == 0) {
            snprintf(a.err, sizeof a.err, "--level: not for map (it draws the p = 0.1, 0.5 and 0.9 contours)");
            r = -1;
        }
        if (r == 0) r = sr_rough_opt(&a, &mo.o);
        if (r < 0) { rc = sr_usage_error(cmd, a.err); goto out; }
        if (r > 0) continue;
        if (sr_flag(&a, "--help") || sr_flag(&a, "-h")) { sr_help(cmd); goto out; }
        if (sr_flag(&a, "--full-stick")) { mo.o.full_stick = 1; continue; }
        int ang = 0, hit = sr_opt(&a, "--vt", &v);
        if (!hit) hit = ang = sr_opt(&a, "--angle", &v);
        if (hit) {
            if (axis) { rc = sr_usage_error(cmd, "--vt and --angle: give one of them, once"); goto out; }
            /* checked here, before any map is computed: each value once, taken in
             * ascending order (one map per value, the table's axis increasing) */
            if (!v || sr_list(&a, ang ? "--angle" : "--vt", v, 0.0, ang ? 89.9 : SWR_V_MAX, &axis,
                              &naxis)) {
                rc = sr_usage_error(cmd, a.err); goto out;
            }
            axis_angle = ang;
            continue;
        }
        if (sr_opt(&a, "--omega", &v)) {
            if (!v || swt_parse_double("--omega", v, -1e12, 1e12, &omega, a.err, sizeof a.err)) {
                rc = sr_usage_error(cmd, a.err); goto out;
            }
            continue;
        }
        snprintf(a.err, sizeof a.err, "unknown option '%s' (see snowregime map --help)", argv[a.i]);
        rc = sr_usage_error(cmd, a.err);
        goto out;
    }
    char err[400];
    if (mapopt_check(&mo, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto out; }
    mo.o.omega = omega;
    swr_params p;
    if (sr_settings_apply(&s, &p, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto out; }
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m) { rc = sr_usage_error(cmd, err); goto out; }
    if (sr_rough_only_check(&a, m, err, sizeof err) != 0) {
        swr_model_free(m);
        rc = sr_usage_error(cmd, err);
        goto out;
    }
    if (swr_model_rough(m) && axis) {
        if (axis_angle) {
            swr_model_free(m);
            rc = sr_usage_error(cmd, "--angle: not with a rough wall (wall lattice): its table's "
                                     "third axis is the tangential speed: give --vt V or --vt 0,V1,...");
            goto out;
        }
        if (naxis == 1) {
            mo.o.vt = axis[0];   /* one value: a single map at that v_t */
            free(axis);
            axis = NULL;
            naxis = 0;
        } else if (axis[0] == 0.0 && (long)mo.g.nd * mo.g.nv * naxis > SWW_TABLE_MAX) {
            /* the combined table of a rough wall over v_t: refused before any map */
            swr_model_free(m);
            snprintf(err, sizeof err, "--nd x --nv x --vt: %d x %d x %d cells exceed the %d values "
                     "of the stick-probability table in regime.coeffs (rough wall over v_t): give "
                     "a smaller grid or fewer --vt values", mo.g.nd, mo.g.nv, naxis, SWW_TABLE_MAX);
            rc = sr_usage_error(cmd, err);
            goto out;
        }
    }
    if (swr_model_rough(m) && (long)mo.g.nd * mo.g.nv > SWW_TABLE_MAX) {
        swr_model_free(m);
        snprintf(err, sizeof err, "--nd x --nv: %d x %d cells exceed the %d values of the stick-"
                 "probability table in regime.coeffs (rough wall)", mo.g.nd, mo.g.nv, SWW_TABLE_MAX);
        rc = sr_usage_error(cmd, err);
        goto out;
    }

    /* the output folder, checked (and made) before any work */
    swo_set *os = sr_out_open(cmd, mo.out, mo.force, &rc);
    if (!os) { swr_model_free(m); goto out; }
    if (axis) mo.o.full_stick = 1;
    int nmaps = axis ? naxis : 1;
    if (check_map_names(os, axis, naxis, axis_angle, err, sizeof err) != 0) {
        rc = sr_out_fail(cmd, os, err);
        swo_free(os);
        swr_model_free(m);
        goto out;
    }
    /* the speed range (automatic: from the first map's settings) is common to all maps */
    swt_vcrit_opts o0 = mo.o;
    if (axis) {
        if (axis_angle) o0.tan_angle = tan(axis[0] * M_PI / 180.0);
        else o0.vt = axis[0];
    }
    /* the estimate, before any work (issue 24: a typo in --points started a
     * run of hours without a word) */
    {
        const swt_grid gp = pilot_grid(&mo);
        const double work = sr_auto_vrange_work(m, mo.set_vmin, mo.set_vmax, &o0)
                          + nmaps * map_work(m, &mo, &o0);
        if (swt_grid_check(&gp, err, sizeof err) == 0
            && sr_estimate(cmd, m, &gp, &o0, work, s.threads, mo.force, mo.progress, &mo.pg, err,
                           sizeof err) != 0) {
            swo_free(os);
            swr_model_free(m);
            rc = sr_usage_error(cmd, err);
            goto out;
        }
    }
    if ((!mo.set_vmin || !mo.set_vmax) &&
        sr_auto_vrange(m, &mo.g, mo.set_vmin, mo.set_vmax, &o0, mo.pg, err, sizeof err) != 0) {
        swo_free(os);
        swr_model_free(m);
        rc = sr_fail(cmd, err);
        goto out;
    }
    if (swt_grid_check(&mo.g, err, sizeof err) != 0) {
        swo_free(os);
        swr_model_free(m);
        rc = sr_usage_error(cmd, err);
        goto out;
    }
    /* --vt LIST starting at 0: the v_t = 0 map's fit and speed nodes, for the
     * combined regime.coeffs with the d_crit(v_n, v_t) table */
    /* a list from 0: one combined regime.coeffs; on a flat wall with the
     * d_crit(v_n, v_t) table, on a rough wall with the stick probability
     * over (d, v_t, v_n) */
    const int combined = axis && !axis_angle && naxis >= 2 && axis[0] == 0.0;
    const int oblique = combined && !swr_model_rough(m);
    const int rough_vt = combined && swr_model_rough(m);
    float *pvt = NULL;        /* rough_vt: p of every map, [k][i][j] */
    double *pd0 = NULL, *pv0 = NULL;
    int points0 = 0;
    swt_fit fit0;
    swt_rebound rb0;                 /* the kernel's rebound over (v_t, d, v_n) */
    memset(&rb0, 0, sizeof rb0);
    int have_fit0 = 0;
    double *vn0 = NULL, d0min = 0.0, d0max = 0.0;
    int nvn0 = 0;
    if (oblique) {
        /* the table has oblique_nodes() speeds per v_t: a list too long for it is
         * refused here, before any map (it used to coarsen the speeds silently) */
        double v_lo, v_hi;
        const long nodes = oblique_nodes(&mo.g, &v_lo, &v_hi);
        if (nodes * naxis > SWW_TABLE_MAX) {
            swo_free(os);
            swr_model_free(m);
            snprintf(err, sizeof err, "--vt: %d values x %ld speed nodes (the map's --nv %d "
                     "spacing over [%g, %g] m/s) exceed the %d values of the d_crit(v_n, v_t) "
                     "table: give at most %ld values, or a smaller --nv", naxis, nodes, mo.g.nv,
                     v_lo, v_hi, SWW_TABLE_MAX, SWW_TABLE_MAX / nodes);
            rc = sr_usage_error(cmd, err);
            goto out;
        }
    }
    if (axis && !axis_angle && naxis >= 2 && axis[0] != 0.0) {
        printf("  note: --vt LIST does not start with 0: no combined regime.coeffs with the "
               "d_crit(v_n, v_t) table\n");
    }
    for (int k = 0; k < nmaps && rc == 0; k++) {
        swt_vcrit_opts o = mo.o;
        char sfx[64] = "", what[160];
        char ocb[160];
        const char *outc = sr_outcome_text(&o, ocb, sizeof ocb);
        if (axis && axis_angle) {
            o.tan_angle = tan(axis[k] * M_PI / 180.0);
            snprintf(sfx, sizeof sfx, "-angle%g", axis[k]);
            snprintf(what, sizeof what, "%s, impact angle %g deg", outc, axis[k]);
        } else if (axis) {
            o.vt = axis[k];
            snprintf(sfx, sizeof sfx, "-vt%g", axis[k]);
            snprintf(what, sizeof what, "%s, vt %g m/s", outc, axis[k]);
        } else if (swr_model_rough(m)) {
            snprintf(what, sizeof what, "%s, rough wall (%s lattice, asperity r %g m, spacing %g m%s)",
                     outc, p.lattice == SWR_LATTICE_HEX ? "hex" : "square", p.asperity_r,
                     p.asperity_spacing, p.asperity_jitter > 0.0 || p.asperity_dz > 0.0 ? ", random" : "");
        } else {
            snprintf(what, sizeof what, "%s", outc);
        }
        sr_mapres r;
        if (compute_map(m, &mo, &o, s.threads, &r, err, sizeof err) != 0) {
            rc = sr_usage_error(cmd, err);
        } else if (combined && ((k == 0 && swt_rebound_init(&rb0, r.mp, axis, naxis, err, sizeof err) != 0)
                               || swt_rebound_layer(&rb0, k, r.mp, err, sizeof err) != 0)) {
            rc = sr_fail(cmd, err);
        } else if (!r.fit_ok && !axis) {
            rc = sr_fail(cmd, r.fit_err);
        } else if (write_map_files(os, sfx, &r, &p, what, mo.plot, s.threads, err, sizeof err) != 0) {
            rc = sr_out_fail(cmd, os, err);
        } else {
            const swt_fit *F = &r.fit;
            printf("map%s: %s\n", sfx, what);
            if (!r.fit_ok) {
                printf("  warning: no fit and no regime%s.coeffs: %s\n", sfx, r.fit_err);
                fprintf(stderr, "snowregime map: warning: map%s: no fit: %s\n", sfx, r.fit_err);
            }
            printf("  grid %d x %d: d %.4g..%.4g m, vn %.4g..%.4g m/s (%s)\n", r.mp->g.nd, r.mp->g.nv,
                   r.mp->g.dmin, r.mp->g.dmax, r.mp->g.vmin, r.mp->g.vmax, r.mp->g.vlog ? "log" : "linear");
            if (r.mp->points > 0)
                printf("  cells with p_stick >= 0.5: %ld of %d; %ld impacts, %ld held at the time "
                       "bound (counted as stick)\n", r.mp->nstick, r.mp->g.nd * r.mp->g.nv,
                       r.mp->collisions, r.mp->step_bound);
            else
                printf("  sticking points %ld of %ld, step-bound points %ld\n", r.mp->nstick,
                       r.mp->collisions, r.mp->step_bound);
            printf("  interface points %d (columns all stick %d, all bounce %d, non-monotone %d)\n",
                   r.it.n, r.it.cols_all_stick, r.it.cols_all_bounce, r.it.cols_nonmono);
            if (r.contours)
                printf("  rough wall: %d impact points per cell (seed %lu); contour points p = 0.1: %d, "
                       "p = 0.5: %d, p = 0.9: %d\n", r.mp->points, mo.o.seed, r.contours->lo.n,
                       r.it.n, r.contours->hi.n);
            if (r.fit_ok) {
                printf("  fit degree %d%s%s: coeffs", F->degree, F->note[0] ? " - " : "", F->note);
                for (int i = 0; i <= F->degree; i++) printf(" %.6g", F->c[i]);
                printf("\n  residuals (relative, d_crit): rms %.3g, max %.3g; slopes %.3f (low), %.3f (high)\n",
                       F->rms, F->maxres, F->slope_lo, F->slope_hi);
            }
            printf("  wall time: grid %.4f s (%ld collisions, %d threads), total %.4f s\n",
                   r.mp->seconds, r.mp->collisions, s.threads, r.seconds_total);
            if (r.mp->msg[0]) printf("  kernel warning: %s\n", r.mp->msg);
            if (rough_vt) {
                const size_t nc = (size_t)r.mp->g.nd * r.mp->g.nv;
                if (k == 0) {
                    pvt = malloc((size_t)naxis * nc * sizeof *pvt);
                    pd0 = malloc((size_t)r.mp->g.nd * sizeof *pd0);
                    pv0 = malloc((size_t)r.mp->g.nv * sizeof *pv0);
                    if (pd0) memcpy(pd0, r.mp->d, (size_t)r.mp->g.nd * sizeof *pd0);
                    if (pv0) memcpy(pv0, r.mp->v, (size_t)r.mp->g.nv * sizeof *pv0);
                    points0 = r.mp->points;
                }
                if (pvt) memcpy(pvt + (size_t)k * nc, r.mp->p, nc * sizeof *pvt);
            }
            if (combined && k == 0 && r.fit_ok) {
                fit0 = r.fit;
                have_fit0 = 1;
                d0min = r.mp->g.dmin;
                d0max = r.mp->g.dmax;
            }
            if (oblique && k == 0 && r.fit_ok) {
                /* table speeds: the map's log spacing, extended a decade below
                 * and half a decade above its range (the wall model clamps v_n
                 * to the table for the tangential limit) */
                double v_lo, v_hi;
                nvn0 = oblique_nodes(&r.mp->g, &v_lo, &v_hi);   /* fits: checked before the maps */
                if (nvn0 >= 2) {
                    vn0 = malloc((size_t)nvn0 * sizeof *vn0);
                    for (int j = 0; vn0 && j < nvn0; j++)
                        vn0[j] = v_lo * pow(v_hi / v_lo, (double)j / (nvn0 - 1));
                }
            }
        }
        mapres_free(&r);
    }
    if (rc == 0 && rough_vt) {
        if (!have_fit0) {
            rc = sr_fail(cmd, "--vt LIST: the v_t = 0 map has no fit: no combined regime.coeffs "
                              "(widen --vmin/--vmax)");
        } else if (!pvt || !pd0 || !pv0) {
            rc = sr_fail(cmd, "out of memory");
        } else {
            char ocb[160], label[300];
            snprintf(label, sizeof label, "%s, rough wall, vt 0..%g m/s, gamma %g",
                     sr_outcome_text(&mo.o, ocb, sizeof ocb), axis[naxis - 1], p.gamma);
            const swt_prob pr = { pd0, pv0, axis, mo.g.nd, mo.g.nv, naxis, pvt, points0 };
            FILE *f = swo_open(os, "regime.coeffs", err, sizeof err);
            if (!f) {
                rc = sr_out_fail(cmd, os, err);
            } else {
                swt_coeffs_write_prob(f, &fit0, &p, d0min, d0max, label, &pr, &rb0);
                printf("regime.coeffs: stick probability %d x %d x %d (d x v_t 0..%g m/s x v_n), "
                       "%d impact points per cell, with the v_t = 0 interface\n", mo.g.nd, naxis,
                       mo.g.nv, axis[naxis - 1], points0);
            }
        }
    }
    free(pvt);
    free(pd0);
    free(pv0);
    if (rc == 0 && oblique) {
        if (!have_fit0 || !vn0) {
            rc = sr_fail(cmd, "--vt LIST: the v_t = 0 map has no fit: no combined regime.coeffs "
                              "(widen --vmin/--vmax)");
        } else {
            swt_oblique ob;
            swt_vcrit_opts o = mo.o;
            if (swt_oblique_compute(&ob, m, axis, naxis, vn0, nvn0, &o, SWR_D_MIN, SWR_D_MAX,
                                    s.threads, err, sizeof err) != 0) {
                rc = sr_fail(cmd, err);
            } else {
                char ocb[160], label[300];
                snprintf(label, sizeof label, "%s, vt 0..%g m/s, gamma %g",
                         sr_outcome_text(&o, ocb, sizeof ocb), axis[naxis - 1], p.gamma);
                FILE *f = swo_open(os, "regime.coeffs", err, sizeof err);
                if (!f) {
                    rc = sr_out_fail(cmd, os, err);
                } else {
                    swt_coeffs_write_all(f, &fit0, &p, d0min, d0max, label, &ob, NULL, &rb0);
                    /* the v_t = 0 row against the fit it sits beside */
                    double dev = 0.0;
                    for (int j = 0; j < nvn0; j++)
                        if (ob.status[j] == SWT_OB_FOUND && vn0[j] >= fit0.vnmin && vn0[j] <= fit0.vnmax)
                            dev = fmax(dev, fabs(exp(swt_fit_eval(&fit0, vn0[j])) / ob.dcrit[j] - 1.0));
                    printf("regime.coeffs: d_crit(v_n, v_t) table %d x %d (v_t 0..%g m/s, slide "
                           "length %g m), %ld collisions, %.3f s; v_t = 0 row vs the fit: max %.3g; "
                           "nodes sticking at every d %d, bouncing at every d %d, non-monotone %d\n",
                           naxis, nvn0, axis[naxis - 1], o.max_slide, ob.collisions, ob.seconds,
                           dev, ob.n_all_stick, ob.n_no_stick, ob.n_nonmono);
                    if (o.max_slide <= 0.0)
                        printf("  note: without --max-slide every kept contact comes to rest on a "
                               "flat wall: the table repeats the normal interface\n");
                }
                swt_oblique_free(&ob);
            }
        }
    }
    free(vn0);
    swt_rebound_free(&rb0);
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", mo.out);
    swo_free(os);
    swr_model_free(m);
out:
    swt_progress_free(mo.pg);
    free(axis);
    return rc;
}

/* ---- sensitivity ---- */

typedef struct {
    const char *key;
    double lo, hi;
} sr_range;

static const sr_range sens_ranges[] = {
    { "E", 8.9e9, 11.2e9 },
    { "nu", 0.29, 0.36 },
    { "gamma", 0.1, 1.0 },
    { "sigma_y", 0.5e6, 1.5e6 },
};

int sr_cmd_sensitivity(int argc, char **argv)
{
    const char *cmd = "sensitivity";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 2;
    sr_mapopt mo;
    mapopt_default(&mo);
    for (; a.i < argc; a.i++) {
        int r = sr_settings_opt(&a, &s);
        if (r == 0) r = mapopt_parse(&a, &mo);
        if (r == 0) r = sr_rough_opt(&a, &mo.o);
        if (r < 0) return sr_usage_error(cmd, a.err);
        if (r > 0) continue;
        if (sr_flag(&a, "--help") || sr_flag(&a, "-h")) { sr_help(cmd); return 0; }
        snprintf(a.err, sizeof a.err, "unknown option '%s' (see snowregime sensitivity --help)", argv[a.i]);
        return sr_usage_error(cmd, a.err);
    }
    char err[400];
    if (mapopt_check(&mo, err, sizeof err) != 0) return sr_usage_error(cmd, err);
    swr_params base;
    if (sr_settings_apply(&s, &base, err, sizeof err) != 0) return sr_usage_error(cmd, err);
    swr_model *m0 = swr_model_alloc(&base, err, sizeof err);
    if (!m0) return sr_usage_error(cmd, err);
    if (sr_rough_only_check(&a, m0, err, sizeof err) != 0) {
        swr_model_free(m0);
        return sr_usage_error(cmd, err);
    }
    const int nvar = 1 + 2 * (int)(sizeof sens_ranges / sizeof sens_ranges[0]);
    /* the output folder and its file names, checked (the folder made) before any work */
    int rc = 0;
    swo_set *os = sr_out_open(cmd, mo.out, mo.force, &rc);
    if (!os) {
        swr_model_free(m0);
        return rc;
    }
    static const char *const names[] = { "sensitivity.csv", "sensitivity.md",
                                         "sensitivity-interfaces.csv", "sensitivity.png" };
    for (size_t q = 0; q < sizeof names / sizeof names[0]; q++)
        if (swo_check(os, names[q], err, sizeof err) != SWO_OK) {
            rc = sr_out_fail(cmd, os, err);
            swo_free(os);
            swr_model_free(m0);
            return rc;
        }
    {
        const swt_grid gp = pilot_grid(&mo);
        const double work = sr_auto_vrange_work(m0, mo.set_vmin, mo.set_vmax, &mo.o)
                          + nvar * map_work(m0, &mo, &mo.o);
        if (swt_grid_check(&gp, err, sizeof err) == 0
            && sr_estimate(cmd, m0, &gp, &mo.o, work, s.threads, mo.force, mo.progress, &mo.pg,
                           err, sizeof err) != 0) {
            swo_free(os);
            swr_model_free(m0);
            return sr_usage_error(cmd, err);
        }
    }
    if ((!mo.set_vmin || !mo.set_vmax) &&
        sr_auto_vrange(m0, &mo.g, mo.set_vmin, mo.set_vmax, &mo.o, mo.pg, err, sizeof err) != 0) {
        swt_progress_free(mo.pg);
        swo_free(os);
        swr_model_free(m0);
        return sr_fail(cmd, err);
    }
    if (swt_grid_check(&mo.g, err, sizeof err) != 0) {
        swt_progress_free(mo.pg);
        swo_free(os);
        swr_model_free(m0);
        return sr_usage_error(cmd, err);
    }

    sr_mapres res[9];
    char keys[9][16];
    double vals[9];
    memset(res, 0, sizeof res);
    double t0 = swt_now();
    for (int k = 0; k < nvar && rc == 0; k++) {
        swr_params p = base;
        swr_model *m = m0;
        if (k == 0) {
            snprintf(keys[k], sizeof keys[k], "baseline");
            vals[k] = 0.0;
        } else {
            const sr_range *rg = &sens_ranges[(k - 1) / 2];
            double val = (k - 1) % 2 ? rg->hi : rg->lo;
            char txt[64];
            snprintf(txt, sizeof txt, "%.10g", val);
            snprintf(keys[k], sizeof keys[k], "%s", rg->key);
            vals[k] = val;
            if (swr_params_set(&p, rg->key, txt, err, sizeof err) != 0 ||
                swr_params_validate(&p, err, sizeof err) != 0 ||
                !(m = swr_model_alloc(&p, err, sizeof err))) {
                rc = sr_usage_error(cmd, err);
                break;
            }
        }
        if (compute_map(m, &mo, &mo.o, s.threads, &res[k], err, sizeof err) != 0) rc = sr_usage_error(cmd, err);
        if (m != m0) swr_model_free(m);
    }
    double sec = swt_now() - t0;
    FILE *fc = NULL, *fm = NULL, *fi = NULL;
    if (rc == 0 && (!(fc = swo_open(os, "sensitivity.csv", err, sizeof err)) ||
                    !(fm = swo_open(os, "sensitivity.md", err, sizeof err)) ||
                    !(fi = swo_open(os, "sensitivity-interfaces.csv", err, sizeof err))))
        rc = sr_out_fail(cmd, os, err);
    if (rc == 0) {
        const sr_mapres *b = &res[0];
        fprintf(fc, "# snowregime sensitivity: %d x %d grid, d %g..%g m, vn %g..%g m/s (%s)\n",
                mo.g.nd, mo.g.nv, mo.g.dmin, mo.g.dmax, mo.g.vmin, mo.g.vmax, mo.g.vlog ? "log" : "linear");
        fprintf(fc, "# d_shift_rel: mean of d_crit/d_crit,baseline - 1 over the common speed columns\n");
        fprintf(fc, "param,value,n_stick,ratio,d_shift_rel,columns,n_interface\n");
        char ocb[160];
        fprintf(fm, "Grid %d x %d: d %g..%g m, v_n %.4g..%.4g m/s (%s); outcome: %s.\n\n",
                mo.g.nd, mo.g.nv, mo.g.dmin, mo.g.dmax, mo.g.vmin, mo.g.vmax, mo.g.vlog ? "log" : "linear",
                sr_outcome_text(&mo.o, ocb, sizeof ocb));
        fprintf(fm, "| parameter | value | sticking points | ratio to baseline | interface shift (mean d_crit change) | common columns |\n");
        fprintf(fm, "|---|---|---|---|---|---|\n");
        fprintf(fi, "param,value,vn_m_s,dcrit_m\n");
        printf("%-10s %-10s %8s %7s %10s %7s\n", "param", "value", "n_stick", "ratio", "d_shift", "cols");
        for (int k = 0; k < nvar; k++) {
            const sr_mapres *r = &res[k];
            double sum = 0.0;
            int ncol = 0;
            for (int q = 0; q < r->it.n; q++)
                for (int u = 0; u < b->it.n; u++)
                    if (b->it.vn[u] == r->it.vn[q]) {
                        sum += r->it.dcrit[q] / b->it.dcrit[u] - 1.0;
                        ncol++;
                    }
            double shift = ncol ? sum / ncol : 0.0;
            double ratio = b->mp->nstick ? (double)r->mp->nstick / (double)b->mp->nstick : 0.0;
            char vtxt[32];
            if (k == 0) snprintf(vtxt, sizeof vtxt, "-");
            else snprintf(vtxt, sizeof vtxt, "%g", vals[k]);
            fprintf(fc, "%s,%s,%ld,%.6g,%.6g,%d,%d\n", keys[k], k ? vtxt : "", r->mp->nstick, ratio,
                    shift, ncol, r->it.n);
            if (ncol) fprintf(fm, "| %s | %s | %ld | %.3f | %+.2f %% | %d |\n", keys[k], vtxt, r->mp->nstick,
                              ratio, 100.0 * shift, ncol);
            else fprintf(fm, "| %s | %s | %ld | %.3f | n/a (no common interface column) | 0 |\n", keys[k],
                         vtxt, r->mp->nstick, ratio);
            printf("%-10s %-10s %8ld %7.3f %+9.2f%% %7d\n", keys[k], vtxt, r->mp->nstick, ratio,
                   100.0 * shift, ncol);
            for (int q = 0; q < r->it.n; q++)
                fprintf(fi, "%s,%s,%.9g,%.9g\n", keys[k], k ? vtxt : "", r->it.vn[q], r->it.dcrit[q]);
            fprintf(fi, "\n\n");   /* gnuplot data block separator */
        }
        fprintf(fm, "\nCommand: snowregime sensitivity --out %s (%.2f s, %d threads)\n", mo.out, sec, s.threads);
        printf("wall time %.3f s (%d maps, %d threads)\n", sec, nvar, s.threads);
    }
    if (rc == 0 && mo.plot) {
        fflush(NULL);
        const char *png = swo_add(os, "sensitivity.png", err, sizeof err);
        const char *ti = png ? swo_add(os, "sensitivity-interfaces.csv", err, sizeof err) : NULL;
        swt_gnuplot g;
        if (!png || !ti) rc = sr_out_fail(cmd, os, err);
        else if (swt_gnuplot_open(&g, png, 950, 650, err, sizeof err) != 0) rc = sr_fail(cmd, err);
        else {
            FILE *f = g.f;
            fprintf(f, "set datafile separator ','\nset key outside right top\nset format x '%%g'\nset mxtics 10\n");
            if (mo.g.vlog) fprintf(f, "set logscale x\n");
            fprintf(f, "set xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n", mo.g.vmin, mo.g.vmax,
                    mo.g.dmin * 1e6, mo.g.dmax * 1e6);
            fprintf(f, "set xlabel 'normal impact speed v_n [m/s]'\nset ylabel 'critical diameter d_{crit} [um]'\n");
            fprintf(f, "set title 'snowregime sensitivity: stick/bounce interface per parameter (below: stick)'\n");
            fprintf(f, "plot ");
            for (int k = 0; k < nvar; k++) {
                char lab[64];
                if (k == 0) snprintf(lab, sizeof lab, "baseline");
                else snprintf(lab, sizeof lab, "%s = %g", keys[k], vals[k]);
                fprintf(f, "%s'%s' index %d skip %d using 3:($4*1e6) with linespoints lw %d pt %d ps 0.6 title '%s'",
                        k ? ", \\\n     " : "", swt_gp_name(ti), k, k == 0 ? 1 : 0, k == 0 ? 3 : 1, k, lab);
            }
            fprintf(f, "\n");
            if (swt_gnuplot_finish(&g, err, sizeof err) != 0) rc = sr_fail(cmd, err);
        }
    }
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", mo.out);
    swo_free(os);
    for (int k = 0; k < nvar; k++) mapres_free(&res[k]);
    swr_model_free(m0);
    swt_progress_free(mo.pg);
    return rc;
}
