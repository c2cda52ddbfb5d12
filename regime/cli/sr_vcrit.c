/* sr_vcrit.c - snowregime vcrit: v_crit per diameter (output contract: see --help). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"
#include "swp_contact.h"

typedef struct {
    const swr_model *m;
    const swt_vcrit_opts *o;
    const double *d;
    swt_vcrit_result *r;
    swt_progress *pg;
} vc_ctx;

static void vc_one(void *p, int k)
{
    vc_ctx *c = p;
    swt_vcrit(c->m, c->d[k], c->o, &c->r[k]);
    swt_progress_add(c->pg, c->r[k].collisions);
}

/* The options of snowregime vcrit besides the settings and the search's. */
typedef struct {
    double *d;
    int nd, have_angle, have_vt, force;
    swt_progress_mode mode;
    double angle;
} vc_args;

/* The options of snowregime vcrit into s, o and va: 0 to go on, or 1 when the
 * command is done (--help, or an error printed) with its exit status in *rc. */
static int vcrit_options(sr_args *a, sr_settings *s, swt_vcrit_opts *o, vc_args *va, int *rc)
{
    const char *cmd = a->cmd;
    char **argv = a->argv;
    const char *v;
    for (; a->i < a->argc; a->i++) {
        int r = sr_settings_opt(a, s);
        if (r == 0) r = sr_rough_opt(a, o);
        if (r < 0) { *rc = sr_usage_error(cmd, a->err); return 1; }
        if (r > 0) continue;
        if (sr_flag(a, "--help") || sr_flag(a, "-h")) { sr_help(cmd); return 1; }
        if (sr_flag(a, "--full-stick")) { o->full_stick = 1; continue; }
        if (sr_flag(a, "--force")) { va->force = 1; continue; }
        if (sr_flag(a, "--progress")) { va->mode = SWT_PROGRESS_ON; continue; }
        double *x = NULL;
        const char *name = NULL;
        double lo = 0, hi = 0;
        if (sr_opt(a, "--d", &v)) {
            if (!v || sr_list(a, "--d", v, SWR_D_MIN, SWR_D_MAX, &va->d, &va->nd)) {
                *rc = sr_usage_error(cmd, a->err); return 1;
            }
            continue;
        }
        if (sr_opt(a, "--vt", &v)) { x = &o->vt; name = "--vt"; lo = 0; hi = SWR_V_MAX; va->have_vt = 1; }
        else if (sr_opt(a, "--angle", &v)) { x = &va->angle; name = "--angle"; lo = 0; hi = 89.9; va->have_angle = 1; }
        else if (sr_opt(a, "--omega", &v)) { x = &o->omega; name = "--omega"; lo = -1e12; hi = 1e12; }
        else if (sr_opt(a, "--tol", &v)) { x = &o->rtol; name = "--tol"; lo = 1e-12; hi = 0.5; }
        else if (sr_opt(a, "--vmin", &v)) { x = &o->vmin; name = "--vmin"; lo = SWR_V_MIN; hi = SWR_V_MAX; }
        else if (sr_opt(a, "--vmax", &v)) { x = &o->vmax; name = "--vmax"; lo = SWR_V_MIN; hi = SWR_V_MAX; }
        else if (sr_opt(a, "--scan-ratio", &v)) { x = &o->scan_ratio; name = "--scan-ratio"; lo = 1.01; hi = 100; }
        else if (sr_opt(a, "--max-slide", &v)) { x = &o->max_slide; name = "--max-slide"; lo = 1e-300; hi = 1e3; }
        else {
            snprintf(a->err, sizeof a->err, "unknown option '%s' (see snowregime vcrit --help)", argv[a->i]);
            *rc = sr_usage_error(cmd, a->err); return 1;
        }
        if (!v || swt_parse_double(name, v, lo, hi, x, a->err, sizeof a->err)) {
            *rc = sr_usage_error(cmd, a->err); return 1;
        }
    }
    return 0;
}

/* The lines of diameter d's search r: d and v_crit (nan when not found), its
 * bracket, counts and warnings; a diameter without v_crit also on stderr.
 * Returns 0, or SR_EXIT_FAIL when there is no v_crit in the range. */
static int vcrit_row(const swr_model *m, const swr_params *p, const swt_vcrit_opts *o, double Es,
                     double d, const swt_vcrit_result *r)
{
    if (r->status == SWT_VCRIT_FOUND) printf("%.9g\t%.9g\n", d, r->vcrit);
    else printf("%.9g\tnan\n", d);
    printf("# d %.6g: ", d);
    if (r->status == SWT_VCRIT_FOUND) printf("bracket [%.9g, %.9g]", r->v_lo, r->v_hi);
    else if (r->status == SWT_VCRIT_NO_STICK) printf("bounces over the whole range: v_crit < %g m/s", o->vmin);
    else printf("sticks over the whole range: v_crit > %g m/s", o->vmax);
    printf(", %ld collisions, %ld steps, dt %.3g..%.3g s", r->collisions, r->steps,
           r->dt_min, r->dt_max);
    if (p->adhesion == SWR_ADHESION_JKR && p->cor == SWR_COR_ELASTIC)
        printf(", Thornton-Ning V_s %.6g m/s",
               swp_sticking_velocity_tn(p->gamma, p->rho, Es, 0.5 * d));
    printf("\n");
    if (r->changes > 1 || (r->status != SWT_VCRIT_FOUND && r->changes > 0)) {
        if (r->v_restick > 0)
            printf("# warning: d %.6g: non-monotone outcome: %d stick/bounce changes in the "
                   "scan, sticks again at %.6g m/s\n", d, r->changes, r->v_restick);
        else
            printf("# warning: d %.6g: non-monotone outcome: %d stick/bounce changes in the "
                   "scan\n", d, r->changes);
    }
    if (r->step_bound)
        printf("# %s: d %.6g: %ld collisions ended on the step bound%s\n",
               swr_model_rough(m) ? "note" : "warning", d, r->step_bound,
               swr_model_rough(m) ? " (still held after rough_hold contact times: counted as stick)" : "");
    if (r->msg[0]) printf("# warning: d %.6g: %s\n", d, r->msg);
    if (r->status != SWT_VCRIT_FOUND) {
        fprintf(stderr, "snowregime vcrit: d %g m: no v_crit in [%g, %g] m/s (%s)\n", d,
                o->vmin, o->vmax, r->status == SWT_VCRIT_NO_STICK ? "bounces everywhere"
                                                                 : "sticks everywhere");
        return SR_EXIT_FAIL;
    }
    return 0;
}

/* The report on stdout: the settings as comments, then a row per diameter
 * (vcrit_row) and the totals. Returns the exit status. */
static int vcrit_report(const swr_model *m, const swr_params *p, const swt_vcrit_opts *o,
                        const vc_args *va, const swt_vcrit_result *res, double sec, int threads)
{
    int rc = 0;
    const double Es = swp_effective_modulus(p->E, p->nu, p->E_wall, p->nu_wall);
    char oc[160];
    printf("# snowregime vcrit: critical normal sticking velocity, outcome = %s\n",
           sr_outcome_text(o, oc, sizeof oc));
    printf("# search: v in [%g, %g] m/s, scan ratio %g, bisection to v_hi/v_lo <= 1 + %g\n",
           o->vmin, o->vmax, o->scan_ratio, o->rtol);
    if (swr_model_rough(m))
        printf("# rough wall: v_crit is where the stick fraction over %d impact points "
               "(seed %lu) falls below %g\n", o->points, o->seed, o->level);
    if (va->have_angle) printf("# impact angle %g deg from the normal (vt = vn tan angle)\n", va->angle);
    else printf("# vt %g m/s, omega %g rad/s\n", o->vt, o->omega);
    swr_params_print(p, "# setting ", stdout);
    printf("# columns: d [m] <TAB> v_crit [m/s]\n");
    long coll = 0;
    for (int k = 0; k < va->nd; k++) {
        coll += res[k].collisions;
        if (vcrit_row(m, p, o, Es, va->d[k], &res[k]) != 0)
            rc = SR_EXIT_FAIL;
    }
    printf("# %d diameters, %ld collisions, %.6f s wall time, %d threads\n", va->nd, coll, sec, threads);
    return rc;
}

int sr_cmd_vcrit(int argc, char **argv)
{
    const char *cmd = "vcrit";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    s.threads = 2;
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    vc_args va = { NULL, 0, 0, 0, 0, SWT_PROGRESS_AUTO, 0.0 };
    swt_progress *pg = NULL;
    int rc = 0;
    if (vcrit_options(&a, &s, &o, &va, &rc) != 0) goto out;
    const double *d = va.d;
    const int nd = va.nd;
    if (!d) { rc = sr_usage_error(cmd, "--d: missing (comma-separated diameters in m)"); goto out; }
    if (va.have_vt && va.have_angle) { rc = sr_usage_error(cmd, "--vt and --angle exclude each other"); goto out; }
    if (va.have_angle) o.tan_angle = tan(va.angle * M_PI / 180.0);
    if (!(o.vmax > o.vmin)) {
        snprintf(a.err, sizeof a.err, "--vmax: '%g' must be > --vmin (%g)", o.vmax, o.vmin);
        rc = sr_usage_error(cmd, a.err); goto out;
    }

    swr_params p;
    char err[400];
    if (sr_settings_apply(&s, &p, err, sizeof err) != 0) { rc = sr_usage_error(cmd, err); goto out; }
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m) { rc = sr_usage_error(cmd, err); goto out; }
    if (sr_rough_only_check(&a, m, err, sizeof err) != 0) {
        swr_model_free(m);
        rc = sr_usage_error(cmd, err);
        goto out;
    }
    {
        /* the estimate, before any work: a pilot over the diameters and the
         * search's speed range */
        swt_grid gp = { 2, 2, d[0], d[0], o.vmin, o.vmax, 1 };
        for (int k = 1; k < nd; k++) {
            gp.dmin = fmin(gp.dmin, d[k]);
            gp.dmax = fmax(gp.dmax, d[k]);
        }
        if (sr_estimate(cmd, m, &gp, &o, sr_vcrit_work(m, nd, &o), nd < s.threads ? nd : s.threads,
                        va.force, va.mode, &pg, err, sizeof err) != 0) {
            swr_model_free(m);
            rc = sr_usage_error(cmd, err);
            goto out;
        }
    }
    swt_vcrit_result *res = calloc((size_t)nd, sizeof *res);
    if (!res) { swr_model_free(m); rc = sr_fail(cmd, "out of memory"); goto out; }
    vc_ctx c = { m, &o, d, res, pg };
    double t0 = swt_now();
    swt_parallel_for(nd, s.threads, vc_one, &c);
    double sec = swt_now() - t0;
    for (int k = 0; k < nd; k++)
        if (res[k].status == SWT_VCRIT_ERROR) {
            snprintf(err, sizeof err, "--d: '%g': %s", d[k], res[k].msg);
            rc = sr_usage_error(cmd, err);
            break;
        }
    if (rc == 0) rc = vcrit_report(m, &p, &o, &va, res, sec, s.threads);
    free(res);
    swr_model_free(m);
out:
    swt_progress_free(pg);
    free(va.d);
    return rc;
}
