/* sr_sensitivity.c - snowregime sensitivity: the map of the baseline and of
 * each parameter at the ends of its range, their sticking points and
 * interface shifts (output contract: see --help). */
#include <stdlib.h>
#include <string.h>

#include "sr.h"

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

/* The options of snowregime sensitivity into s and mo: 0 to go on, or 1 when
 * the command is done (--help, or an error printed) with its exit status in *rc. */
static int sens_options(sr_args *a, sr_settings *s, sr_mapopt *mo, int *rc)
{
    const char *cmd = a->cmd;
    for (; a->i < a->argc; a->i++) {
        int r = sr_settings_opt(a, s);
        if (r == 0) r = sr_mapopt_parse(a, mo);
        if (r == 0) r = sr_rough_opt(a, &mo->o);
        if (r < 0) { *rc = sr_usage_error(cmd, a->err); return 1; }
        if (r > 0) continue;
        if (sr_flag(a, "--help") || sr_flag(a, "-h")) { sr_help(cmd); *rc = 0; return 1; }
        snprintf(a->err, sizeof a->err, "unknown option '%s' (see snowregime sensitivity --help)", a->argv[a->i]);
        *rc = sr_usage_error(cmd, a->err);
        return 1;
    }
    return 0;
}

/* Before any map: the file names checked, the estimate of the nvar maps
 * (refused beyond SR_LONG_RUN_S without --force), the automatic speed range
 * from the baseline m0 and the grid. 0, or the exit status with the message
 * printed (after the progress report, freed then). */
static int sens_before_work(const char *cmd, const swr_model *m0, sr_mapopt *mo, int threads,
                            swo_set *os, int nvar)
{
    char err[400];
    static const char *const names[] = { "sensitivity.csv", "sensitivity.md",
                                         "sensitivity-interfaces.csv", "sensitivity.png" };
    for (size_t q = 0; q < sizeof names / sizeof names[0]; q++)
        if (swo_check(os, names[q], err, sizeof err) != SWO_OK)
            return sr_out_fail(cmd, os, err);
    {
        const swt_grid gp = sr_pilot_grid(mo);
        const double work = sr_auto_vrange_work(m0, mo->set_vmin, mo->set_vmax, &mo->o)
                          + nvar * sr_map_work(m0, mo, &mo->o);
        if (swt_grid_check(&gp, err, sizeof err) == 0
            && sr_estimate(cmd, m0, &gp, &mo->o, work, threads, mo->force, mo->progress, &mo->pg,
                           err, sizeof err) != 0)
            return sr_usage_error(cmd, err);
    }
    if ((!mo->set_vmin || !mo->set_vmax) &&
        sr_auto_vrange(m0, &mo->g, mo->set_vmin, mo->set_vmax, &mo->o, mo->pg, err, sizeof err) != 0) {
        swt_progress_free(mo->pg);
        mo->pg = NULL;
        return sr_fail(cmd, err);
    }
    if (swt_grid_check(&mo->g, err, sizeof err) != 0) {
        swt_progress_free(mo->pg);
        mo->pg = NULL;
        return sr_usage_error(cmd, err);
    }
    return 0;
}

/* The nvar maps: the baseline (model m0, parameters base) and each parameter
 * of sens_ranges at each end of its range, into res, their keys and values.
 * Returns the exit status. */
static int sens_maps(const char *cmd, swr_model *m0, const swr_params *base,
                     const sr_mapopt *mo, int threads, int nvar, sr_mapres *res, char keys[][16],
                     double *vals)
{
    int rc = 0;
    char err[400];
    for (int k = 0; k < nvar && rc == 0; k++) {
        swr_params p = *base;
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
        if (sr_map_compute(m, mo, &mo->o, threads, &res[k], err, sizeof err) != 0) rc = sr_usage_error(cmd, err);
        if (m != m0) swr_model_free(m);
    }
    return rc;
}

/* The mean relative change of map r's d_crit against the baseline b over the
 * speed columns where both have an interface point (*ncol of them; 0 if none). */
static double interface_shift(const sr_mapres *b, const sr_mapres *r, int *ncol)
{
    double sum = 0.0;
    *ncol = 0;
    for (int q = 0; q < r->it.n; q++)
        for (int u = 0; u < b->it.n; u++)
            if (b->it.vn[u] == r->it.vn[q]) {
                sum += r->it.dcrit[q] / b->it.dcrit[u] - 1.0;
                (*ncol)++;
            }
    return *ncol ? sum / *ncol : 0.0;
}

/* The results as sensitivity.csv (fc), sensitivity.md (fm), the interfaces
 * (fi) and a table on stdout; sec: the wall time of the maps. */
static void sens_tables(const sr_mapopt *mo, int threads, int nvar, const sr_mapres *res,
                        const char keys[][16], const double *vals, FILE *fc, FILE *fm, FILE *fi,
                        double sec)
{
    const sr_mapres *b = &res[0];
    fprintf(fc, "# snowregime sensitivity: %d x %d grid, d %g..%g m, vn %g..%g m/s (%s)\n",
            mo->g.nd, mo->g.nv, mo->g.dmin, mo->g.dmax, mo->g.vmin, mo->g.vmax, mo->g.vlog ? "log" : "linear");
    fprintf(fc, "# d_shift_rel: mean of d_crit/d_crit,baseline - 1 over the common speed columns\n");
    fprintf(fc, "param,value,n_stick,ratio,d_shift_rel,columns,n_interface\n");
    char ocb[160];
    fprintf(fm, "Grid %d x %d: d %g..%g m, v_n %.4g..%.4g m/s (%s); outcome: %s.\n\n",
            mo->g.nd, mo->g.nv, mo->g.dmin, mo->g.dmax, mo->g.vmin, mo->g.vmax, mo->g.vlog ? "log" : "linear",
            sr_outcome_text(&mo->o, ocb, sizeof ocb));
    fprintf(fm, "| parameter | value | sticking points | ratio to baseline | interface shift (mean d_crit change) | common columns |\n");
    fprintf(fm, "|---|---|---|---|---|---|\n");
    fprintf(fi, "param,value,vn_m_s,dcrit_m\n");
    printf("%-10s %-10s %8s %7s %10s %7s\n", "param", "value", "n_stick", "ratio", "d_shift", "cols");
    for (int k = 0; k < nvar; k++) {
        const sr_mapres *r = &res[k];
        int ncol;
        double shift = interface_shift(b, r, &ncol);
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
    fprintf(fm, "\nCommand: snowregime sensitivity --out %s (%.2f s, %d threads)\n", mo->out, sec, threads);
    printf("wall time %.3f s (%d maps, %d threads)\n", sec, nvar, threads);
}

int sr_cmd_sensitivity(int argc, char **argv)
{
    const char *cmd = "sensitivity";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 2;
    sr_mapopt mo;
    sr_mapopt_default(&mo);
    int rc = 0;
    if (sens_options(&a, &s, &mo, &rc) != 0) return rc;
    char err[400];
    if (sr_mapopt_check(&mo, err, sizeof err) != 0) return sr_usage_error(cmd, err);
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
    swo_set *os = sr_out_open(cmd, mo.out, mo.force, &rc);
    if (!os) {
        swr_model_free(m0);
        return rc;
    }
    rc = sens_before_work(cmd, m0, &mo, s.threads, os, nvar);
    if (rc != 0) {
        swo_free(os);
        swr_model_free(m0);
        return rc;
    }

    sr_mapres res[9];
    char keys[9][16];
    double vals[9];
    memset(res, 0, sizeof res);
    double t0 = swt_now();
    rc = sens_maps(cmd, m0, &base, &mo, s.threads, nvar, res, keys, vals);
    double sec = swt_now() - t0;
    FILE *fc = NULL, *fm = NULL, *fi = NULL;
    if (rc == 0 && (!(fc = swo_open(os, "sensitivity.csv", err, sizeof err)) ||
                    !(fm = swo_open(os, "sensitivity.md", err, sizeof err)) ||
                    !(fi = swo_open(os, "sensitivity-interfaces.csv", err, sizeof err))))
        rc = sr_out_fail(cmd, os, err);
    if (rc == 0) sens_tables(&mo, s.threads, nvar, res, keys, vals, fc, fm, fi, sec);
    if (rc == 0 && mo.plot) {
        fflush(NULL);
        const char *png = swo_add(os, "sensitivity.png", err, sizeof err);
        const char *ti = png ? swo_add(os, "sensitivity-interfaces.csv", err, sizeof err) : NULL;
        if (!png || !ti) rc = sr_out_fail(cmd, os, err);
        else if (sr_plot_sensitivity(png, ti, &mo.g, nvar, keys, vals, err, sizeof err) != 0)
            rc = sr_fail(cmd, err);
    }
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", mo.out);
    swo_free(os);
    for (int k = 0; k < nvar; k++) sr_mapres_free(&res[k]);
    swr_model_free(m0);
    swt_progress_free(mo.pg);
    return rc;
}
