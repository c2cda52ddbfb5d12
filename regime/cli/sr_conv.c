/* sr_conv.c - snowregime convergence: error of v_crit against wall time per collision. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

int sr_cmd_convergence(int argc, char **argv)
{
    const char *cmd = "convergence";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 1;
    double *d = NULL, *acc = NULL;
    int nd = 0, nacc = 0, plot = 1, rc = 0, force = 0;
    double ref_factor = 8.0, tol = 1e-7, min_time = 0.01;
    const char *out = NULL, *v;
    for (; a.i < argc; a.i++) {
        int r = sr_settings_opt(&a, &s);
        if (r < 0) { rc = sr_usage_error(cmd, a.err); goto done; }
        if (r > 0) continue;
        if (sr_flag(&a, "--help") || sr_flag(&a, "-h")) { sr_help(cmd); goto done; }
        if (sr_flag(&a, "--no-plot")) { plot = 0; continue; }
        if (sr_flag(&a, "--force")) { force = 1; continue; }
        int bad = 0;
        if (sr_opt(&a, "--out", &v)) { if (!v || !*v) { snprintf(a.err, sizeof a.err, "--out: missing folder name"); bad = 1; } else out = v; }
        else if (sr_opt(&a, "--d", &v)) bad = !v || sr_list(&a, "--d", v, SWR_D_MIN, SWR_D_MAX, &d, &nd);
        /* each value once, taken in ascending order (the rows and the plot follow it) */
        else if (sr_opt(&a, "--accuracy", &v)) bad = !v || sr_list(&a, "--accuracy", v, 1.0, 1e6, &acc, &nacc);
        else if (sr_opt(&a, "--ref-factor", &v)) bad = !v || swt_parse_double("--ref-factor", v, 2.0, 1e3, &ref_factor, a.err, sizeof a.err);
        else if (sr_opt(&a, "--tol", &v)) bad = !v || swt_parse_double("--tol", v, 1e-12, 0.1, &tol, a.err, sizeof a.err);
        else if (sr_opt(&a, "--min-time", &v)) bad = !v || swt_parse_double("--min-time", v, 0.0, 3600.0, &min_time, a.err, sizeof a.err);
        else {
            snprintf(a.err, sizeof a.err, "unknown option '%s' (see snowregime convergence --help)", argv[a.i]);
            bad = 1;
        }
        if (bad) { rc = sr_usage_error(cmd, a.err); goto done; }
    }
    if (!out) { rc = sr_usage_error(cmd, "--out: missing (output folder)"); goto done; }
    if (!d) {
        static const double dd[] = { 10e-6, 30e-6, 100e-6 };
        nd = 3;
        d = malloc(sizeof dd);
        if (d) memcpy(d, dd, sizeof dd);
    }
    if (!acc) {
        static const double aa[] = { 10, 15, 20, 30, 45, 60, 90, 120, 180, 240 };
        nacc = 10;
        acc = malloc(sizeof aa);
        if (acc) memcpy(acc, aa, sizeof aa);
    }
    if (!d || !acc) { rc = sr_fail(cmd, "out of memory"); goto done; }

    char err[400];
    swr_params base;
    if (sr_settings_apply(&s, &base, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto done; }
    /* the output folder, checked (and made) before any work */
    swo_set *os = sr_out_open(cmd, out, force, &rc);
    if (!os) goto done;
    double amax = 0.0;
    for (int k = 0; k < nacc; k++) amax = fmax(amax, acc[k]);
    const int ncol = nacc + 1;   /* last: the reference */
    swr_model **models = calloc((size_t)ncol, sizeof *models);
    double *vc = calloc((size_t)nd * ncol, sizeof *vc), *us = calloc((size_t)nd * ncol, sizeof *us);
    double *spc = calloc((size_t)nd * ncol, sizeof *spc), *dts = calloc((size_t)nd * ncol, sizeof *dts);
    double *cpu = calloc((size_t)nd * ncol, sizeof *cpu);
    if (!models || !vc || !us || !spc || !dts || !cpu) { rc = sr_fail(cmd, "out of memory"); goto freeall; }
    for (int k = 0; k < ncol; k++) {
        swr_params p = base;
        char txt[64];
        snprintf(txt, sizeof txt, "%.10g", k < nacc ? acc[k] : ref_factor * amax);
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
    o.rtol = tol;
    double t_all = swt_now();
    for (int i = 0; i < nd && rc == 0; i++) {
        for (int k = ncol - 1; k >= 0; k--) {
            swt_vcrit_result r;
            swt_vcrit(models[k], d[i], &o, &r);
            if (r.status != SWT_VCRIT_FOUND) {
                snprintf(err, sizeof err, "--d: '%g': no v_crit in [%g, %g] m/s at accuracy %s: %s", d[i],
                         o.vmin, o.vmax, k < nacc ? "setting" : "reference",
                         r.status == SWT_VCRIT_ERROR ? r.msg : r.status == SWT_VCRIT_NO_STICK ? "bounces everywhere" : "sticks everywhere");
                rc = r.status == SWT_VCRIT_ERROR ? sr_usage_error(cmd, err) : sr_fail(cmd, err);
                break;
            }
            size_t q = (size_t)i * ncol + k;
            vc[q] = r.vcrit;
            spc[q] = (double)r.steps / (double)r.collisions;
            dts[q] = 0.5 * (r.dt_min + r.dt_max);
            if (k == nacc) continue;   /* the reference is not timed */
            /* median of 5 timed blocks (each >= min_time) against the load of
             * other processes */
            double blk[5], cblk[5];
            for (int b = 0; b < 5; b++) {
                long coll = 0;
                int reps = 0;
                double t0 = swt_now(), t1, c0 = swt_thread_cpu();
                do {
                    swt_vcrit_result rr;
                    swt_vcrit(models[k], d[i], &o, &rr);
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
            us[q] = blk[2];
            cpu[q] = cblk[2];
        }
    }
    double sec = swt_now() - t_all;
    FILE *fc = NULL, *fm = NULL;
    if (rc == 0 && (!(fc = swo_open(os, "convergence.csv", err, sizeof err)) ||
                    !(fm = swo_open(os, "convergence.md", err, sizeof err))))
        rc = sr_out_fail(cmd, os, err);
    if (rc == 0) {
        fprintf(fc, "# snowregime convergence: v_crit (bisection tol %g) against the reference accuracy %g\n",
                tol, ref_factor * amax);
        fprintf(fc, "# accuracy = steps per Hertz contact time; us_per_collision: mean over the searches\n");
        fprintf(fc, "d_m,accuracy,vcrit_m_s,vcrit_ref_m_s,rel_error,us_per_collision,steps_per_collision,dt_s,cpu_us_per_collision\n");
        fprintf(fm, "Relative error of v_crit against a reference with accuracy %g (bisection tolerance %g),\n"
                    "and the mean wall time per collision of the search (1 thread).\n\n", ref_factor * amax, tol);
        fprintf(fm, "| d [m] | accuracy | v_crit [m/s] | rel. error | us / collision (wall) | us / collision (CPU) | steps / collision | dt [s] |\n");
        fprintf(fm, "|---|---|---|---|---|---|---|---|\n");
        printf("%-10s %9s %14s %11s %12s %11s %10s %10s\n", "d_m", "accuracy", "vcrit_m_s", "rel_error",
               "us/coll", "cpu_us/coll", "steps/coll", "dt_s");
        for (int i = 0; i < nd; i++) {
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
        fprintf(fm, "\nCommand: snowregime convergence --out %s (%.2f s)\n", out, sec);
        printf("wall time %.2f s\n", sec);
    }
    if (rc == 0 && plot) {
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
            for (int i = 0; i < nd; i++)
                fprintf(f, "%s'%s' index %d using 6:($5 > 1e-9 ? $5 : 1e-9) with linespoints lw 2 pt 7 lc %d title 'd = %g um, wall time', "
                           "'' index %d using 6:($5 > 1e-9 ? $5 : 1e-9):(sprintf('%%g', $2)) with labels offset 0.8,0.6 font ',7' notitle, "
                           "'' index %d using 9:($5 > 1e-9 ? $5 : 1e-9) with linespoints lw 1 dt 2 pt 6 lc %d title 'd = %g um, CPU time'",
                        i ? ", \\\n     " : "", swt_gp_name(tc), i, i + 1, d[i] * 1e6, i, i, i + 1, d[i] * 1e6);
            fprintf(f, "\n");
            if (swt_gnuplot_finish(&g, err, sizeof err) != 0) rc = sr_fail(cmd, err);
        }
    }
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", out);
freeall:
    swo_free(os);
    for (int k = 0; models && k < ncol; k++) swr_model_free(models[k]);
    free(models); free(vc); free(us); free(spc); free(dts); free(cpu);
done:
    free(d); free(acc);
    return rc;
}
