/* sr_conv.c - snowregime convergence: error of v_crit against wall time per collision. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

/* One run of snowregime convergence: its options and, per diameter i and
 * accuracy column k (the last the reference), its results [i * ncol + k]. */
typedef struct {
    double *d, *acc;
    int nd, nacc, plot, force;
    double ref_factor, tol, min_time;
    const char *out;
    int ncol;
    double amax;
    double *vc, *us, *spc, *dts, *cpu;
} conv_run;

/* The options of snowregime convergence into s and c: 0 to go on, or 1 when
 * the command is done (--help, or an error printed) with its exit status in *rc. */
static int conv_options(sr_args *a, sr_settings *s, conv_run *c, int *rc)
{
    const char *cmd = a->cmd;
    char **argv = a->argv;
    const char *v;
    for (; a->i < a->argc; a->i++) {
        int r = sr_settings_opt(a, s);
        if (r < 0) { *rc = sr_usage_error(cmd, a->err); return 1; }
        if (r > 0) continue;
        if (sr_flag(a, "--help") || sr_flag(a, "-h")) { sr_help(cmd); return 1; }
        if (sr_flag(a, "--no-plot")) { c->plot = 0; continue; }
        if (sr_flag(a, "--force")) { c->force = 1; continue; }
        int bad = 0;
        if (sr_opt(a, "--out", &v)) { if (!v || !*v) { snprintf(a->err, sizeof a->err, "--out: missing folder name"); bad = 1; } else c->out = v; }
        else if (sr_opt(a, "--d", &v)) bad = !v || sr_list(a, "--d", v, SWR_D_MIN, SWR_D_MAX, &c->d, &c->nd);
        /* each value once, taken in ascending order (the rows and the plot follow it) */
        else if (sr_opt(a, "--accuracy", &v)) bad = !v || sr_list(a, "--accuracy", v, 1.0, 1e6, &c->acc, &c->nacc);
        else if (sr_opt(a, "--ref-factor", &v)) bad = !v || swt_parse_double("--ref-factor", v, 2.0, 1e3, &c->ref_factor, a->err, sizeof a->err);
        else if (sr_opt(a, "--tol", &v)) bad = !v || swt_parse_double("--tol", v, 1e-12, 0.1, &c->tol, a->err, sizeof a->err);
        else if (sr_opt(a, "--min-time", &v)) bad = !v || swt_parse_double("--min-time", v, 0.0, 3600.0, &c->min_time, a->err, sizeof a->err);
        else {
            snprintf(a->err, sizeof a->err, "unknown option '%s' (see snowregime convergence --help)", argv[a->i]);
            bad = 1;
        }
        if (bad) { *rc = sr_usage_error(cmd, a->err); return 1; }
    }
    return 0;
}

/* The wall and thread CPU time per collision [us] of the v_crit search of d
 * on model m: the median of 5 timed blocks (each >= min_time) against the
 * load of other processes. */
static void time_search(const swr_model *m, double d, const swt_vcrit_opts *o, double min_time,
                        double *us, double *cpu)
{
    double blk[5], cblk[5];
    for (int b = 0; b < 5; b++) {
        long coll = 0;
        int reps = 0;
        double t0 = swt_now(), t1, c0 = swt_thread_cpu();
        do {
            swt_vcrit_result rr;
            swt_vcrit(m, d, o, &rr);
            coll += rr.collisions;
            reps++;
            t1 = swt_now();
        } while (t1 - t0 < min_time && reps < 100000);
        blk[b] = 1e6 * (t1 - t0) / (double)coll;
        cblk[b] = 1e6 * (swt_thread_cpu() - c0) / (double)coll;
    }
    for (int x = 1; x < 5; x++)   /* insertion sort of 5 */
        for (int y = x; y > 0 && blk[y] < blk[y - 1]; y--) {
            double tmp = blk[y]; blk[y] = blk[y - 1]; blk[y - 1] = tmp;
        }
    for (int x = 1; x < 5; x++)
        for (int y = x; y > 0 && cblk[y] < cblk[y - 1]; y--) {
            double tmp = cblk[y]; cblk[y] = cblk[y - 1]; cblk[y - 1] = tmp;
        }
    *us = blk[2];
    *cpu = cblk[2];
}

/* v_crit, steps and time step of every diameter at every accuracy (models[k],
 * the reference last, from it down), and the time of the searches but the
 * reference's. Returns the exit status (a missing v_crit printed). */
static int conv_measure(const char *cmd, swr_model *const *models, conv_run *c,
                        const swt_vcrit_opts *o)
{
    int rc = 0;
    char err[400];
    const int nacc = c->nacc, ncol = c->ncol;
    for (int i = 0; i < c->nd && rc == 0; i++) {
        for (int k = ncol - 1; k >= 0; k--) {
            swt_vcrit_result r;
            swt_vcrit(models[k], c->d[i], o, &r);
            if (r.status != SWT_VCRIT_FOUND) {
                snprintf(err, sizeof err, "--d: '%g': no v_crit in [%g, %g] m/s at accuracy %s: %s", c->d[i],
                         o->vmin, o->vmax, k < nacc ? "setting" : "reference",
                         r.status == SWT_VCRIT_ERROR ? r.msg : r.status == SWT_VCRIT_NO_STICK ? "bounces everywhere" : "sticks everywhere");
                rc = r.status == SWT_VCRIT_ERROR ? sr_usage_error(cmd, err) : sr_fail(cmd, err);
                break;
            }
            size_t q = (size_t)i * ncol + k;
            c->vc[q] = r.vcrit;
            c->spc[q] = (double)r.steps / (double)r.collisions;
            c->dts[q] = 0.5 * (r.dt_min + r.dt_max);
            if (k == nacc) continue;   /* the reference is not timed */
            time_search(models[k], c->d[i], o, c->min_time, &c->us[q], &c->cpu[q]);
        }
    }
    return rc;
}

/* The results as convergence.csv (fc), convergence.md (fm) and a table on
 * stdout; sec: the wall time of the searches. */
static void conv_tables(const conv_run *c, FILE *fc, FILE *fm, double sec)
{
    const int nacc = c->nacc, ncol = c->ncol;
    const double *d = c->d, *acc = c->acc, *vc = c->vc, *us = c->us, *spc = c->spc;
    const double *dts = c->dts, *cpu = c->cpu;
    fprintf(fc, "# snowregime convergence: v_crit (bisection tol %g) against the reference accuracy %g\n",
            c->tol, c->ref_factor * c->amax);
    fprintf(fc, "# accuracy = steps per Hertz contact time; us_per_collision: mean over the searches\n");
    fprintf(fc, "d_m,accuracy,vcrit_m_s,vcrit_ref_m_s,rel_error,us_per_collision,steps_per_collision,dt_s,cpu_us_per_collision\n");
    fprintf(fm, "Relative error of v_crit against a reference with accuracy %g (bisection tolerance %g),\n"
                "and the mean wall time per collision of the search (1 thread).\n\n", c->ref_factor * c->amax, c->tol);
    fprintf(fm, "| d [m] | accuracy | v_crit [m/s] | rel. error | us / collision (wall) | us / collision (CPU) | steps / collision | dt [s] |\n");
    fprintf(fm, "|---|---|---|---|---|---|---|---|\n");
    printf("%-10s %9s %14s %11s %12s %11s %10s %10s\n", "d_m", "accuracy", "vcrit_m_s", "rel_error",
           "us/coll", "cpu_us/coll", "steps/coll", "dt_s");
    for (int i = 0; i < c->nd; i++) {
        double ref = vc[(size_t)i * ncol + nacc];
        for (int k = 0; k < nacc; k++) {
            size_t q = (size_t)i * ncol + k;
            double e = fabs(vc[q] / ref - 1.0);
            fprintf(fc, "%.6g,%g,%.10g,%.10g,%.4g,%.4g,%.1f,%.4g,%.4g\n", d[i], acc[k], vc[q], ref, e,
                    us[q], spc[q], dts[q], cpu[q]);
            fprintf(fm, "| %.3g | %g | %.7g | %.2e | %.3g | %.3g | %.0f | %.3g |\n", d[i], acc[k], vc[q], e,
                    us[q], cpu[q], spc[q], dts[q]);
            printf("%-10.4g %9g %14.8g %11.3e %12.3f %11.3f %10.0f %10.3g\n", d[i], acc[k], vc[q], e, us[q],
                   cpu[q], spc[q], dts[q]);
        }
        fprintf(fc, "\n\n");
    }
    fprintf(fm, "\nCommand: snowregime convergence --out %s (%.2f s)\n", c->out, sec);
    printf("wall time %.2f s\n", sec);
}

/* convergence.png (gnuplot, from convergence.csv): the error against the time
 * per collision. Returns the exit status. */
static int conv_plot(const char *cmd, swo_set *os, const conv_run *c)
{
    int rc = 0;
    char err[400];
    fflush(NULL);
    const char *png = swo_add(os, "convergence.png", err, sizeof err);
    const char *tc = png ? swo_add(os, "convergence.csv", err, sizeof err) : NULL;
    swt_gnuplot g;
    if (!png || !tc) rc = sr_out_fail(cmd, os, err);
    else if (swt_gnuplot_open(&g, png, 850, 600, err, sizeof err) != 0) rc = sr_fail(cmd, err);
    else {
        FILE *f = g.f;
        fprintf(f, "set datafile separator ','\nset logscale xy\nset key top right\nset format y '10^{%%L}'\nset format x '%%g'\n");
        fprintf(f, "set xlabel 'time per collision [us] (solid: wall, dashed: thread CPU)'\nset ylabel 'relative error of v_{crit}'\n");
        fprintf(f, "set title 'snowregime convergence: error against run time (labels: accuracy)'\n");
        fprintf(f, "plot ");
        for (int i = 0; i < c->nd; i++)
            fprintf(f, "%s'%s' index %d using 6:($5 > 1e-9 ? $5 : 1e-9) with linespoints lw 2 pt 7 lc %d title 'd = %g um, wall time', "
                       "'' index %d using 6:($5 > 1e-9 ? $5 : 1e-9):(sprintf('%%g', $2)) with labels offset 0.8,0.6 font ',7' notitle, "
                       "'' index %d using 9:($5 > 1e-9 ? $5 : 1e-9) with linespoints lw 1 dt 2 pt 6 lc %d title 'd = %g um, CPU time'",
                    i ? ", \\\n     " : "", swt_gp_name(tc), i, i + 1, c->d[i] * 1e6, i, i, i + 1, c->d[i] * 1e6);
        fprintf(f, "\n");
        if (swt_gnuplot_finish(&g, err, sizeof err) != 0) rc = sr_fail(cmd, err);
    }
    return rc;
}

int sr_cmd_convergence(int argc, char **argv)
{
    const char *cmd = "convergence";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 1;
    conv_run c = { 0 };
    c.plot = 1;
    c.ref_factor = 8.0;
    c.tol = 1e-7;
    c.min_time = 0.01;
    int rc = 0;
    if (conv_options(&a, &s, &c, &rc) != 0) goto done;
    if (!c.out) { rc = sr_usage_error(cmd, "--out: missing (output folder)"); goto done; }
    if (!c.d) {
        static const double dd[] = { 10e-6, 30e-6, 100e-6 };
        c.nd = 3;
        c.d = malloc(sizeof dd);
        if (c.d) memcpy(c.d, dd, sizeof dd);
    }
    if (!c.acc) {
        static const double aa[] = { 10, 15, 20, 30, 45, 60, 90, 120, 180, 240 };
        c.nacc = 10;
        c.acc = malloc(sizeof aa);
        if (c.acc) memcpy(c.acc, aa, sizeof aa);
    }
    if (!c.d || !c.acc) { rc = sr_fail(cmd, "out of memory"); goto done; }

    char err[400];
    swr_params base;
    if (sr_settings_apply(&s, &base, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto done; }
    /* the output folder, checked (and made) before any work */
    swo_set *os = sr_out_open(cmd, c.out, c.force, &rc);
    if (!os) goto done;
    const int nd = c.nd, nacc = c.nacc;
    c.amax = 0.0;
    for (int k = 0; k < nacc; k++) c.amax = fmax(c.amax, c.acc[k]);
    const int ncol = c.ncol = nacc + 1;   /* last: the reference */
    swr_model **models = calloc((size_t)ncol, sizeof *models);
    c.vc = calloc((size_t)nd * ncol, sizeof *c.vc);
    c.us = calloc((size_t)nd * ncol, sizeof *c.us);
    c.spc = calloc((size_t)nd * ncol, sizeof *c.spc);
    c.dts = calloc((size_t)nd * ncol, sizeof *c.dts);
    c.cpu = calloc((size_t)nd * ncol, sizeof *c.cpu);
    if (!models || !c.vc || !c.us || !c.spc || !c.dts || !c.cpu) { rc = sr_fail(cmd, "out of memory"); goto freeall; }
    for (int k = 0; k < ncol; k++) {
        swr_params p = base;
        char txt[64];
        snprintf(txt, sizeof txt, "%.10g", k < nacc ? c.acc[k] : c.ref_factor * c.amax);
        if (swr_params_set(&p, "accuracy", txt, err, sizeof err) != 0 ||
            swr_params_validate(&p, err, sizeof err) != 0 ||
            !(models[k] = swr_model_alloc(&p, err, sizeof err))) {
            char e2[500];
            snprintf(e2, sizeof e2, "%s%s", k == nacc ? "reference accuracy (--ref-factor x max): " : "--accuracy: ", err);
            rc = sr_usage_error(cmd, e2);
            goto freeall;
        }
    }
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    o.rtol = c.tol;
    double t_all = swt_now();
    rc = conv_measure(cmd, models, &c, &o);
    double sec = swt_now() - t_all;
    FILE *fc = NULL, *fm = NULL;
    if (rc == 0 && (!(fc = swo_open(os, "convergence.csv", err, sizeof err)) ||
                    !(fm = swo_open(os, "convergence.md", err, sizeof err))))
        rc = sr_out_fail(cmd, os, err);
    if (rc == 0) conv_tables(&c, fc, fm, sec);
    if (rc == 0 && c.plot) rc = conv_plot(cmd, os, &c);
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", c.out);
freeall:
    swo_free(os);
    for (int k = 0; models && k < ncol; k++) swr_model_free(models[k]);
    free(models); free(c.vc); free(c.us); free(c.spc); free(c.dts); free(c.cpu);
done:
    free(c.d); free(c.acc);
    return rc;
}
