/* sr_mapout.c - the files of one map of snowregime map (map.csv,
 * interface.csv, fit.txt, regime.coeffs, contours.csv, the plot) and the
 * check of every name before the work. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

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

/* Writes one map's files into the set. */
int sr_map_write_files(swo_set *os, const char *sfx, const sr_mapres *r, const swr_params *p,
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
        /* the kernel's e_n(d, v_n) of this map's bouncing points (rebound tables) */
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
        if (sr_map_plot_rough(os, sfx, r, title, err, errlen) != 0) return -1;
    } else if (plot) {
        /* data must be on disk before gnuplot reads the temporaries */
        fflush(NULL);
        char title[300];
        snprintf(title, sizeof title, "snowregime map: %s, gamma %g J/m2, sigma_y %g Pa", what,
                 p->gamma, p->sigma_y);
        if (sr_map_plot(os, sfx, r, title, err, errlen) != 0) return -1;
    }
    return 0;
}

/* Every file name of the maps (one per --vt / --angle value, suffix -vtV or
 * -angleA) checked before the work: one that is a folder, device, FIFO, socket
 * or link in the output folder is refused before hours of maps, not after. */
int sr_map_check_names(swo_set *os, const double *axis, int naxis, int axis_angle, char *err,
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

