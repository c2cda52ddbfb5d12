/* sr_map.c - snowregime map: the stick/bounce map over (d, v_n), its
 * interface, fit and regime.coeffs; with --vt/--angle one map per value and
 * the combined regime.coeffs (output contract: see --help). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

/* the wall model reads at most this many values per list (wallmodel/core) */
#define SWW_TABLE_MAX 4096

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

/* The summary of one map on stdout (and a missing fit as a warning on stderr). */
static void print_map(const sr_mapres *r, const char *sfx, const char *what, unsigned long seed,
                      int threads)
{
    const swt_fit *F = &r->fit;
    printf("map%s: %s\n", sfx, what);
    if (!r->fit_ok) {
        printf("  warning: no fit and no regime%s.coeffs: %s\n", sfx, r->fit_err);
        fprintf(stderr, "snowregime map: warning: map%s: no fit: %s\n", sfx, r->fit_err);
    }
    printf("  grid %d x %d: d %.4g..%.4g m, vn %.4g..%.4g m/s (%s)\n", r->mp->g.nd, r->mp->g.nv,
           r->mp->g.dmin, r->mp->g.dmax, r->mp->g.vmin, r->mp->g.vmax, r->mp->g.vlog ? "log" : "linear");
    if (r->mp->points > 0)
        printf("  cells with p_stick >= 0.5: %ld of %d; %ld impacts, %ld held at the time "
               "bound (counted as stick)\n", r->mp->nstick, r->mp->g.nd * r->mp->g.nv,
               r->mp->collisions, r->mp->step_bound);
    else
        printf("  sticking points %ld of %ld, step-bound points %ld\n", r->mp->nstick,
               r->mp->collisions, r->mp->step_bound);
    printf("  interface points %d (columns all stick %d, all bounce %d, non-monotone %d)\n",
           r->it.n, r->it.cols_all_stick, r->it.cols_all_bounce, r->it.cols_nonmono);
    if (r->contours)
        printf("  rough wall: %d impact points per cell (seed %lu); contour points p = 0.1: %d, "
               "p = 0.5: %d, p = 0.9: %d\n", r->mp->points, seed, r->contours->lo.n,
               r->it.n, r->contours->hi.n);
    if (r->fit_ok) {
        printf("  fit degree %d%s%s: coeffs", F->degree, F->note[0] ? " - " : "", F->note);
        for (int i = 0; i <= F->degree; i++) printf(" %.6g", F->c[i]);
        printf("\n  residuals (relative, d_crit): rms %.3g, max %.3g; slopes %.3f (low), %.3f (high)\n",
               F->rms, F->maxres, F->slope_lo, F->slope_hi);
    }
    printf("  wall time: grid %.4f s (%ld collisions, %d threads), total %.4f s\n",
           r->mp->seconds, r->mp->collisions, threads, r->seconds_total);
    if (r->mp->msg[0]) printf("  kernel warning: %s\n", r->mp->msg);
}

/* One run of snowregime map, shared by its steps: the model, the options,
 * the output set and the third axis (the --vt or --angle list; NULL: one map). */
typedef struct {
    const char *cmd;
    const swr_model *m;
    const swr_params *p;
    sr_mapopt *mo;
    int threads;
    swo_set *os;
    const double *axis;
    int naxis, axis_angle;
} map_job;

/* What the combined regime.coeffs of a --vt list from 0 takes from the maps:
 * the v_t = 0 map's fit and speed nodes, a rough wall's p of every map. */
typedef struct {
    int combined, oblique, rough_vt;
    float *pvt;        /* rough_vt: p of every map, [k][i][j] */
    double *pd0, *pv0;
    int points0;
    swt_fit fit0;
    swt_rebound rb0;   /* the kernel's rebound over (v_t, d, v_n) */
    int have_fit0;
    double *vn0, d0min, d0max;
    int nvn0;
} map_combined;

/* The options of snowregime map into s and mo, the --vt or --angle list
 * (*axis, *naxis, *axis_angle) and *omega: 0 to go on, or 1 when the command
 * is done (--help, or an error printed) with its exit status in *rc. */
static int map_options(sr_args *a, sr_settings *s, sr_mapopt *mo, double **axis, int *naxis,
                       int *axis_angle, double *omega, int *rc)
{
    const char *cmd = a->cmd;
    char **argv = a->argv;
    const char *v;
    for (; a->i < a->argc; a->i++) {
        int r = sr_settings_opt(a, s);
        if (r == 0) r = sr_mapopt_parse(a, mo);
        if (r == 0 && strncmp(argv[a->i], "--level", 7) == 0) {
            snprintf(a->err, sizeof a->err, "--level: not for map (it draws the p = 0.1, 0.5 and 0.9 contours)");
            r = -1;
        }
        if (r == 0) r = sr_rough_opt(a, &mo->o);
        if (r < 0) { *rc = sr_usage_error(cmd, a->err); return 1; }
        if (r > 0) continue;
        if (sr_flag(a, "--help") || sr_flag(a, "-h")) { sr_help(cmd); return 1; }
        if (sr_flag(a, "--full-stick")) { mo->o.full_stick = 1; continue; }
        int ang = 0, hit = sr_opt(a, "--vt", &v);
        if (!hit) hit = ang = sr_opt(a, "--angle", &v);
        if (hit) {
            if (*axis) { *rc = sr_usage_error(cmd, "--vt and --angle: give one of them, once"); return 1; }
            /* checked here, before any map is computed: each value once, taken in
             * ascending order (one map per value, the table's axis increasing) */
            if (!v || sr_list(a, ang ? "--angle" : "--vt", v, 0.0, ang ? 89.9 : SWR_V_MAX, axis,
                              naxis)) {
                *rc = sr_usage_error(cmd, a->err); return 1;
            }
            *axis_angle = ang;
            continue;
        }
        if (sr_opt(a, "--omega", &v)) {
            if (!v || swt_parse_double("--omega", v, -1e12, 1e12, omega, a->err, sizeof a->err)) {
                *rc = sr_usage_error(cmd, a->err); return 1;
            }
            continue;
        }
        snprintf(a->err, sizeof a->err, "unknown option '%s' (see snowregime map --help)", argv[a->i]);
        *rc = sr_usage_error(cmd, a->err);
        return 1;
    }
    return 0;
}

/* A rough wall's terms for the map: no --angle, one --vt value is the map's
 * v_t (the list dropped), and the stick-probability table within
 * SWW_TABLE_MAX values. 0, or -1 with the message in err. */
static int rough_checks(const swr_model *m, sr_mapopt *mo, double **axis, int *naxis,
                        int axis_angle, char *err, size_t errlen)
{
    if (swr_model_rough(m) && *axis) {
        if (axis_angle) {
            snprintf(err, errlen, "--angle: not with a rough wall (wall lattice): its table's "
                                  "third axis is the tangential speed: give --vt V or --vt 0,V1,...");
            return -1;
        }
        if (*naxis == 1) {
            mo->o.vt = (*axis)[0];   /* one value: a single map at that v_t */
            free(*axis);
            *axis = NULL;
            *naxis = 0;
        } else if ((*axis)[0] == 0.0 && (long)mo->g.nd * mo->g.nv * *naxis > SWW_TABLE_MAX) {
            /* the combined table of a rough wall over v_t: refused before any map */
            snprintf(err, errlen, "--nd x --nv x --vt: %d x %d x %d cells exceed the %d values "
                     "of the stick-probability table in regime.coeffs (rough wall over v_t): give "
                     "a smaller grid or fewer --vt values", mo->g.nd, mo->g.nv, *naxis, SWW_TABLE_MAX);
            return -1;
        }
    }
    if (swr_model_rough(m) && (long)mo->g.nd * mo->g.nv > SWW_TABLE_MAX) {
        snprintf(err, errlen, "--nd x --nv: %d x %d cells exceed the %d values of the stick-"
                 "probability table in regime.coeffs (rough wall)", mo->g.nd, mo->g.nv, SWW_TABLE_MAX);
        return -1;
    }
    return 0;
}

/* Before any map: the file names checked, the run's estimate (refused beyond
 * SR_LONG_RUN_S without --force), the automatic speed range and the grid.
 * 0, or the exit status with the message printed. */
static int map_before_work(const map_job *job, int nmaps)
{
    sr_mapopt *mo = job->mo;
    char err[400];
    if (sr_map_check_names(job->os, job->axis, job->naxis, job->axis_angle, err, sizeof err) != 0)
        return sr_out_fail(job->cmd, job->os, err);
    /* the speed range (automatic: from the first map's settings) is common to all maps */
    swt_vcrit_opts o0 = mo->o;
    if (job->axis) {
        if (job->axis_angle) o0.tan_angle = tan(job->axis[0] * M_PI / 180.0);
        else o0.vt = job->axis[0];
    }
    /* the estimate, before any work: a run of hours (a typo in --points) is
     * announced, and refused beyond SR_LONG_RUN_S without --force */
    {
        const swt_grid gp = sr_pilot_grid(mo);
        const double work = sr_auto_vrange_work(job->m, mo->set_vmin, mo->set_vmax, &o0)
                          + nmaps * sr_map_work(job->m, mo, &o0);
        if (swt_grid_check(&gp, err, sizeof err) == 0
            && sr_estimate(job->cmd, job->m, &gp, &o0, work, job->threads, mo->force, mo->progress,
                           &mo->pg, err, sizeof err) != 0)
            return sr_usage_error(job->cmd, err);
    }
    if ((!mo->set_vmin || !mo->set_vmax) &&
        sr_auto_vrange(job->m, &mo->g, mo->set_vmin, mo->set_vmax, &o0, mo->pg, err, sizeof err) != 0)
        return sr_fail(job->cmd, err);
    if (swt_grid_check(&mo->g, err, sizeof err) != 0)
        return sr_usage_error(job->cmd, err);
    return 0;
}

/* The d_crit(v_n, v_t) table of a --vt list from 0 on a flat wall within
 * SWW_TABLE_MAX values: 0, or -1 with the message in err. */
static int oblique_table_check(const sr_mapopt *mo, int naxis, char *err, size_t errlen)
{
    /* the table has oblique_nodes() speeds per v_t: a list too long for it is
     * refused here, before any map (it used to coarsen the speeds silently) */
    double v_lo, v_hi;
    const long nodes = oblique_nodes(&mo->g, &v_lo, &v_hi);
    if (nodes * naxis > SWW_TABLE_MAX) {
        snprintf(err, errlen, "--vt: %d values x %ld speed nodes (the map's --nv %d "
                 "spacing over [%g, %g] m/s) exceed the %d values of the d_crit(v_n, v_t) "
                 "table: give at most %ld values, or a smaller --nv", naxis, nodes, mo->g.nv,
                 v_lo, v_hi, SWW_TABLE_MAX, SWW_TABLE_MAX / nodes);
        return -1;
    }
    return 0;
}

/* What the combined regime.coeffs needs of map k (r) into c: on a rough wall
 * the map's p, from the v_t = 0 map its fit and on a flat wall the table's
 * speed nodes. */
static void keep_combined(const map_job *job, int k, const sr_mapres *r, map_combined *c)
{
    if (c->rough_vt) {
        const size_t nc = (size_t)r->mp->g.nd * r->mp->g.nv;
        if (k == 0) {
            c->pvt = malloc((size_t)job->naxis * nc * sizeof *c->pvt);
            c->pd0 = malloc((size_t)r->mp->g.nd * sizeof *c->pd0);
            c->pv0 = malloc((size_t)r->mp->g.nv * sizeof *c->pv0);
            if (c->pd0) memcpy(c->pd0, r->mp->d, (size_t)r->mp->g.nd * sizeof *c->pd0);
            if (c->pv0) memcpy(c->pv0, r->mp->v, (size_t)r->mp->g.nv * sizeof *c->pv0);
            c->points0 = r->mp->points;
        }
        if (c->pvt) memcpy(c->pvt + (size_t)k * nc, r->mp->p, nc * sizeof *c->pvt);
    }
    if (c->combined && k == 0 && r->fit_ok) {
        c->fit0 = r->fit;
        c->have_fit0 = 1;
        c->d0min = r->mp->g.dmin;
        c->d0max = r->mp->g.dmax;
    }
    if (c->oblique && k == 0 && r->fit_ok) {
        /* table speeds: the map's log spacing, extended a decade below
         * and half a decade above its range (the wall model clamps v_n
         * to the table for the tangential limit) */
        double v_lo, v_hi;
        c->nvn0 = oblique_nodes(&r->mp->g, &v_lo, &v_hi);   /* fits: checked before the maps */
        if (c->nvn0 >= 2) {
            c->vn0 = malloc((size_t)c->nvn0 * sizeof *c->vn0);
            for (int j = 0; c->vn0 && j < c->nvn0; j++)
                c->vn0[j] = v_lo * pow(v_hi / v_lo, (double)j / (c->nvn0 - 1));
        }
    }
}

/* Map k of the run (of the k-th --vt or --angle value, or the one map):
 * computed, its files written, its summary printed, and what the combined
 * regime.coeffs needs of it kept in c. Returns the exit status. */
static int map_one(const map_job *job, int k, map_combined *c)
{
    const double *axis = job->axis;
    const swr_params *p = job->p;
    int rc = 0;
    char err[400];
    swt_vcrit_opts o = job->mo->o;
    char sfx[64] = "", what[160];
    char ocb[160];
    const char *outc = sr_outcome_text(&o, ocb, sizeof ocb);
    if (axis && job->axis_angle) {
        o.tan_angle = tan(axis[k] * M_PI / 180.0);
        snprintf(sfx, sizeof sfx, "-angle%g", axis[k]);
        snprintf(what, sizeof what, "%s, impact angle %g deg", outc, axis[k]);
    } else if (axis) {
        o.vt = axis[k];
        snprintf(sfx, sizeof sfx, "-vt%g", axis[k]);
        snprintf(what, sizeof what, "%s, vt %g m/s", outc, axis[k]);
    } else if (swr_model_rough(job->m)) {
        snprintf(what, sizeof what, "%s, rough wall (%s lattice, asperity r %g m, spacing %g m%s)",
                 outc, p->lattice == SWR_LATTICE_HEX ? "hex" : "square", p->asperity_r,
                 p->asperity_spacing, p->asperity_jitter > 0.0 || p->asperity_dz > 0.0 ? ", random" : "");
    } else {
        snprintf(what, sizeof what, "%s", outc);
    }
    sr_mapres r;
    if (sr_map_compute(job->m, job->mo, &o, job->threads, &r, err, sizeof err) != 0) {
        rc = sr_usage_error(job->cmd, err);
    } else if (c->combined && ((k == 0 && swt_rebound_init(&c->rb0, r.mp, axis, job->naxis, err, sizeof err) != 0)
                               || swt_rebound_layer(&c->rb0, k, r.mp, err, sizeof err) != 0)) {
        rc = sr_fail(job->cmd, err);
    } else if (!r.fit_ok && !axis) {
        rc = sr_fail(job->cmd, r.fit_err);
    } else if (sr_map_write_files(job->os, sfx, &r, p, what, job->mo->plot, job->threads, err,
                                  sizeof err) != 0) {
        rc = sr_out_fail(job->cmd, job->os, err);
    } else {
        print_map(&r, sfx, what, job->mo->o.seed, job->threads);
        keep_combined(job, k, &r, c);
    }
    sr_mapres_free(&r);
    return rc;
}

/* The combined regime.coeffs of a rough wall over a --vt list from 0: the
 * stick probability over (d, v_t, v_n) with the v_t = 0 interface. Returns
 * the exit status. */
static int write_prob_coeffs(const map_job *job, const map_combined *c)
{
    const double *axis = job->axis;
    const int naxis = job->naxis;
    const sr_mapopt *mo = job->mo;
    if (!c->have_fit0)
        return sr_fail(job->cmd, "--vt LIST: the v_t = 0 map has no fit: no combined regime.coeffs "
                                 "(widen --vmin/--vmax)");
    if (!c->pvt || !c->pd0 || !c->pv0)
        return sr_fail(job->cmd, "out of memory");
    char ocb[160], label[300], err[400];
    snprintf(label, sizeof label, "%s, rough wall, vt 0..%g m/s, gamma %g",
             sr_outcome_text(&mo->o, ocb, sizeof ocb), axis[naxis - 1], job->p->gamma);
    const swt_prob pr = { c->pd0, c->pv0, axis, mo->g.nd, mo->g.nv, naxis, c->pvt, c->points0 };
    FILE *f = swo_open(job->os, "regime.coeffs", err, sizeof err);
    if (!f)
        return sr_out_fail(job->cmd, job->os, err);
    swt_coeffs_write_prob(f, &c->fit0, job->p, c->d0min, c->d0max, label, &pr, &c->rb0);
    printf("regime.coeffs: stick probability %d x %d x %d (d x v_t 0..%g m/s x v_n), "
           "%d impact points per cell, with the v_t = 0 interface\n", mo->g.nd, naxis,
           mo->g.nv, axis[naxis - 1], c->points0);
    return 0;
}

/* The combined regime.coeffs of a flat wall over a --vt list from 0: the
 * v_t = 0 fit with the d_crit(v_n, v_t) table, computed here. Returns the
 * exit status. */
static int write_oblique_coeffs(const map_job *job, const map_combined *c)
{
    const double *axis = job->axis;
    const int naxis = job->naxis;
    if (!c->have_fit0 || !c->vn0)
        return sr_fail(job->cmd, "--vt LIST: the v_t = 0 map has no fit: no combined regime.coeffs "
                                 "(widen --vmin/--vmax)");
    int rc = 0;
    char err[400];
    swt_oblique ob;
    swt_vcrit_opts o = job->mo->o;
    if (swt_oblique_compute(&ob, job->m, axis, naxis, c->vn0, c->nvn0, &o, SWR_D_MIN, SWR_D_MAX,
                            job->threads, err, sizeof err) != 0)
        return sr_fail(job->cmd, err);
    char ocb[160], label[300];
    snprintf(label, sizeof label, "%s, vt 0..%g m/s, gamma %g",
             sr_outcome_text(&o, ocb, sizeof ocb), axis[naxis - 1], job->p->gamma);
    FILE *f = swo_open(job->os, "regime.coeffs", err, sizeof err);
    if (!f) {
        rc = sr_out_fail(job->cmd, job->os, err);
    } else {
        swt_coeffs_write_all(f, &c->fit0, job->p, c->d0min, c->d0max, label, &ob, NULL, &c->rb0);
        /* the v_t = 0 row against the fit it sits beside */
        double dev = 0.0;
        for (int j = 0; j < c->nvn0; j++)
            if (ob.status[j] == SWT_OB_FOUND && c->vn0[j] >= c->fit0.vnmin && c->vn0[j] <= c->fit0.vnmax)
                dev = fmax(dev, fabs(exp(swt_fit_eval(&c->fit0, c->vn0[j])) / ob.dcrit[j] - 1.0));
        printf("regime.coeffs: d_crit(v_n, v_t) table %d x %d (v_t 0..%g m/s, slide "
               "length %g m), %ld collisions, %.3f s; v_t = 0 row vs the fit: max %.3g; "
               "nodes sticking at every d %d, bouncing at every d %d, non-monotone %d\n",
               naxis, c->nvn0, axis[naxis - 1], o.max_slide, ob.collisions, ob.seconds,
               dev, ob.n_all_stick, ob.n_no_stick, ob.n_nonmono);
        if (o.max_slide <= 0.0)
            printf("  note: without --max-slide every kept contact comes to rest on a "
                   "flat wall: the table repeats the normal interface\n");
    }
    swt_oblique_free(&ob);
    return rc;
}

int sr_cmd_map(int argc, char **argv)
{
    const char *cmd = "map";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 2;
    sr_mapopt mo;
    sr_mapopt_default(&mo);
    double *axis = NULL, omega = 0.0;
    int naxis = 0, axis_angle = 0, rc = 0;
    if (map_options(&a, &s, &mo, &axis, &naxis, &axis_angle, &omega, &rc) != 0) goto out;
    char err[400];
    if (sr_mapopt_check(&mo, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto out; }
    mo.o.omega = omega;
    swr_params p;
    if (sr_settings_apply(&s, &p, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto out; }
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m) { rc = sr_usage_error(cmd, err); goto out; }
    if (sr_rough_only_check(&a, m, err, sizeof err) != 0
        || rough_checks(m, &mo, &axis, &naxis, axis_angle, err, sizeof err) != 0) {
        swr_model_free(m);
        rc = sr_usage_error(cmd, err);
        goto out;
    }

    /* the output folder, checked (and made) before any work */
    swo_set *os = sr_out_open(cmd, mo.out, mo.force, &rc);
    if (!os) { swr_model_free(m); goto out; }
    if (axis) mo.o.full_stick = 1;
    int nmaps = axis ? naxis : 1;
    const map_job job = { cmd, m, &p, &mo, s.threads, os, axis, naxis, axis_angle };
    rc = map_before_work(&job, nmaps);
    if (rc != 0) {
        swo_free(os);
        swr_model_free(m);
        goto out;
    }
    /* --vt LIST starting at 0: the v_t = 0 map's fit and speed nodes, for the
     * combined regime.coeffs with the d_crit(v_n, v_t) table */
    /* a list from 0: one combined regime.coeffs; on a flat wall with the
     * d_crit(v_n, v_t) table, on a rough wall with the stick probability
     * over (d, v_t, v_n) */
    map_combined c;
    memset(&c, 0, sizeof c);
    c.combined = axis && !axis_angle && naxis >= 2 && axis[0] == 0.0;
    c.oblique = c.combined && !swr_model_rough(m);
    c.rough_vt = c.combined && swr_model_rough(m);
    if (c.oblique && oblique_table_check(&mo, naxis, err, sizeof err) != 0) {
        swo_free(os);
        swr_model_free(m);
        rc = sr_usage_error(cmd, err);
        goto out;
    }
    if (axis && !axis_angle && naxis >= 2 && axis[0] != 0.0) {
        printf("  note: --vt LIST does not start with 0: no combined regime.coeffs with the "
               "d_crit(v_n, v_t) table\n");
    }
    for (int k = 0; k < nmaps && rc == 0; k++)
        rc = map_one(&job, k, &c);
    if (rc == 0 && c.rough_vt)
        rc = write_prob_coeffs(&job, &c);
    free(c.pvt);
    free(c.pd0);
    free(c.pv0);
    if (rc == 0 && c.oblique)
        rc = write_oblique_coeffs(&job, &c);
    free(c.vn0);
    swt_rebound_free(&c.rb0);
    if (rc == 0 && swo_commit(os, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, os, err);
    if (rc == 0) printf("written to %s/\n", mo.out);
    swo_free(os);
    swr_model_free(m);
out:
    swt_progress_free(mo.pg);
    free(axis);
    return rc;
}
