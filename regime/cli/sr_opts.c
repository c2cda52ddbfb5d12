/* sr_opts.c - the option handling the snowregime commands share: options and
 * flags, settings (--config/--set/--threads), the rough-wall options, messages
 * and exit codes, the automatic speed range. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

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
    /* a rough-wall key set (from --set or --config) while the wall stays flat is
     * refused, not ignored ('asperity_r=2e-6' on the flat wall would give the
     * flat answer without a word). Detected as a value that differs
     * from the default: a key set to its default changes nothing either way. */
    /* likewise the work of adhesion without adhesion */
    if (p->adhesion == SWR_ADHESION_NONE) {
        swr_params d;
        swr_params_default(&d);
        if (p->gamma != d.gamma) {
            snprintf(err, errlen, "settings: gamma: %g is not used with adhesion none (no "
                     "adhesive contact); drop it or set adhesion=jkr", p->gamma);
            return -1;
        }
    }
    if (p->wall == SWR_WALL_KIND_FLAT) {
        swr_params d;
        swr_params_default(&d);
        const char *key = NULL;
        double v = 0.0;
        if (p->lattice != d.lattice) key = "lattice";
        else if (p->rough_step != d.rough_step) key = "rough_step";
        else if (p->asperity_shape != d.asperity_shape) key = "asperity_shape";
        else if (p->asperity_yield != d.asperity_yield) key = "asperity_yield";
        else if (p->asperity_r != d.asperity_r) { key = "asperity_r"; v = p->asperity_r; }
        else if (p->asperity_spacing != d.asperity_spacing) { key = "asperity_spacing"; v = p->asperity_spacing; }
        else if (p->asperity_jitter != d.asperity_jitter) { key = "asperity_jitter"; v = p->asperity_jitter; }
        else if (p->asperity_dz != d.asperity_dz) { key = "asperity_dz"; v = p->asperity_dz; }
        else if (p->wall_seed != d.wall_seed) { key = "wall_seed"; v = p->wall_seed; }
        else if (p->rough_hold != d.rough_hold) { key = "rough_hold"; v = p->rough_hold; }
        if (key) {
            if (strcmp(key, "lattice") == 0)
                snprintf(err, errlen, "settings: lattice: hex is not used on a flat wall (wall flat); "
                         "set wall=lattice for a rough wall");
            else if (strcmp(key, "asperity_yield") == 0)
                snprintf(err, errlen, "settings: asperity_yield: %s is not used on a flat wall (wall "
                         "flat); set wall=lattice for a rough wall",
                         p->asperity_yield == SWR_YIELD_PARTICLE ? "particle" : "elastic");
            else if (strcmp(key, "asperity_shape") == 0)
                snprintf(err, errlen, "settings: asperity_shape: sphere is not used on a flat wall "
                         "(wall flat); set wall=lattice for a rough wall");
            else if (strcmp(key, "rough_step") == 0)
                snprintf(err, errlen, "settings: rough_step: fixed is not used on a flat wall (wall "
                         "flat); set wall=lattice for a rough wall");
            else
                snprintf(err, errlen, "settings: %s: %g is not used on a flat wall (wall flat); "
                         "set wall=lattice for a rough wall", key, v);
            return -1;
        }
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

swo_set *sr_out_open(const char *cmd, const char *dir, int force, int *rc)
{
    char tool[64], err[600];
    snprintf(tool, sizeof tool, "snowregime %s", cmd);
    const swo_spec spec = { tool, "--out", dir, force, 1 };
    swo_set *o = NULL;
    const int c = swo_alloc(&spec, &o, err, sizeof err);
    if (c != SWO_OK) {
        fprintf(stderr, "snowregime %s: %s\n", cmd, err);
        *rc = c == SWO_EREFUSED ? SR_EXIT_USAGE : SR_EXIT_FAIL;
        return NULL;
    }
    if (swo_note(o))
        fprintf(stderr, "snowregime %s: note: %s\n", cmd, swo_note(o));
    *rc = 0;
    return o;
}

int sr_out_fail(const char *cmd, const swo_set *o, const char *msg)
{
    fprintf(stderr, "snowregime %s: %s\n", cmd, msg);
    return swo_code(o) == SWO_EREFUSED ? SR_EXIT_USAGE : SR_EXIT_FAIL;
}

int sr_list(sr_args *a, const char *opt, const char *text, double lo, double hi, double **out,
            int *n)
{
    char note[600];
    free(*out);
    *out = NULL;
    if (swo_list_numbers(opt, text, lo, hi, 0, 0, out, n, note, sizeof note, a->err,
                         sizeof a->err) != SWO_OK)
        return -1;
    if (note[0])
        fprintf(stderr, "snowregime %s: note: %s\n", a->cmd, note);
    return 0;
}

int sr_fail(const char *cmd, const char *msg)
{
    fprintf(stderr, "snowregime%s%s: %s\n", cmd ? " " : "", cmd ? cmd : "", msg);
    return SR_EXIT_FAIL;
}

/* v_crit of diameter d for the automatic speed range, or -1 with a message. */
static int auto_vcrit(const swr_model *m, double d, const swt_vcrit_opts *vo, double *vcrit,
                      swt_progress *pg, char *err, size_t errlen)
{
    swt_vcrit_result r;
    swt_vcrit(m, d, vo, &r);
    swt_progress_add(pg, r.collisions);
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

/* the options of the automatic range's searches */
static swt_vcrit_opts auto_opts(const swt_vcrit_opts *o)
{
    swt_vcrit_opts vo = *o;
    vo.vmin = 1e-4;
    vo.vmax = SWR_V_MAX;
    vo.rtol = 1e-2;
    return vo;
}

/* Evaluations of one v_crit search: the scan by the ratio over [vmin, vmax]
 * and the bisection to rtol (an estimate's upper side). */
static double search_evals(const swt_vcrit_opts *o)
{
    const double ratio = o->scan_ratio > 1.0 ? o->scan_ratio : 2.0;
    return ceil(log(o->vmax / o->vmin) / log(ratio)) + ceil(log2(log(ratio) / o->rtol)) + 2.0;
}

/* Impacts of one evaluation: the points on a rough wall, of which the early
 * decision (swt_sticks) runs about 60 % on the average */
static double eval_impacts(const swr_model *m, const swt_vcrit_opts *o)
{
    return swr_model_rough(m) ? 0.6 * o->points : 1.0;
}

double sr_auto_vrange_work(const swr_model *m, int set_min, int set_max, const swt_vcrit_opts *o)
{
    const swt_vcrit_opts vo = auto_opts(o);
    return (double)(!set_min + !set_max) * search_evals(&vo) * eval_impacts(m, &vo);
}

double sr_vcrit_work(const swr_model *m, int nd, const swt_vcrit_opts *o)
{
    return nd * search_evals(o) * eval_impacts(m, o);
}

int sr_estimate(const char *cmd, const swr_model *m, const swt_grid *g, const swt_vcrit_opts *o,
                double work, int threads, int force, swt_progress_mode mode, swt_progress **pg,
                char *err, size_t errlen)
{
    *pg = NULL;
    const double cost = swt_pilot_cost(m, g, o);
    const double est = cost * work / (threads > 1 ? threads : 1);
    char what[64], b[48];
    snprintf(what, sizeof what, "snowregime %s", cmd);
    if (est > SR_LONG_RUN_S && !force) {
        snprintf(err, errlen, "about %s for %.3g impacts on %d thread%s (estimated from a pilot "
                 "of a few impacts): more than %.0f min; give --force to run it, or fewer "
                 "--points, a smaller grid or more --threads", swt_duration_text(est, b, sizeof b),
                 work, threads, threads == 1 ? "" : "s", SR_LONG_RUN_S / 60.0);
        return -1;
    }
    *pg = swt_progress_alloc(what, "impacts", work, est, threads, mode);
    return 0;
}

int sr_auto_vrange(const swr_model *m, swt_grid *g, int set_min, int set_max,
                   const swt_vcrit_opts *o, swt_progress *pg, char *err, size_t errlen)
{
    const swt_vcrit_opts vo = auto_opts(o);
    double v;
    if (!set_min) {
        if (auto_vcrit(m, g->dmax, &vo, &v, pg, err, errlen) != 0)
            return -1;
        g->vmin = v / 1.5;
    }
    if (!set_max) {
        if (auto_vcrit(m, g->dmin, &vo, &v, pg, err, errlen) != 0)
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
