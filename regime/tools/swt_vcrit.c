/* swt_vcrit.c - v_crit by scan + log bisection. */
#include "swt_vcrit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_rng.h>

void swt_vcrit_opts_default(swt_vcrit_opts *o)
{
    o->vmin = 1e-3;
    o->vmax = 50.0;
    o->rtol = 1e-3;
    o->scan_ratio = 2.0;
    o->full_stick = 0;
    o->vt = 0.0;
    o->tan_angle = 0.0;
    o->omega = 0.0;
    o->max_slide = 0.0;
    o->points = 64;
    o->seed = 1;
    o->level = 0.5;
}

int swt_outcome(const swt_vcrit_opts *o, const swr_result *res)
{
    if (o->max_slide > 0.0) return res->stick != 0 && res->s_rest <= o->max_slide;
    return o->full_stick ? (res->stick != 0) : (res->contact_kept != 0);
}

static void count(swt_vcrit_result *r, swr_status st, const swr_result *res)
{
    r->collisions++;
    r->steps += res->steps;
    if (st == SWR_STEP_BOUND) r->step_bound++;
    if (r->dt_min == 0.0 || res->dt < r->dt_min) r->dt_min = res->dt;
    if (res->dt > r->dt_max) r->dt_max = res->dt;
}

/* The stick fraction over the impact points, in their fixed order. With
 * `decide` it stops as soon as the remaining points cannot change whether the
 * count reaches o->level (swt_fraction_sticks): the same answer as the whole
 * count, from fewer impacts (f->points then counts those run). */
static int fraction_run(const swr_model *m, double d, double vn, const swt_vcrit_opts *o,
                        int decide, swt_fraction *f, swt_vcrit_result *r, char *msg,
                        size_t msglen)
{
    memset(f, 0, sizeof *f);
    double lx, ly;
    swr_model_sample_area(m, &lx, &ly);
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    if (!g) {
        if (msg) snprintf(msg, msglen, "out of memory");
        return -1;
    }
    gsl_rng_set(g, o->seed);
    int nb = 0;
    for (int k = 0; k < o->points; k++) {
        swr_impact in = { .d = d, .vn = vn, .vt = o->tan_angle > 0.0 ? vn * o->tan_angle : o->vt,
                          .omega = o->omega };
        in.x = lx * gsl_rng_uniform(g);
        in.y = ly * gsl_rng_uniform(g);
        swr_result res;
        memset(&res, 0, sizeof res);
        const swr_status st = swr_collide(m, &in, &res, NULL);
        if (st == SWR_EINVAL) {
            if (msg) snprintf(msg, msglen, "%s", res.msg);
            gsl_rng_free(g);
            return -1;
        }
        if (r) count(r, st, &res);
        if (msg && res.msg[0] && !msg[0]) snprintf(msg, msglen, "%s", res.msg);
        f->points++;
        f->steps += res.steps;
        f->contacts += res.contacts;
        if (st == SWR_STEP_BOUND) f->bound++;
        if (swt_outcome(o, &res)) {
            f->sticks++;
        } else if (!res.contact_kept) {
            f->e_n += res.e_n;
            nb++;
        }
        if (decide && (swt_fraction_sticks(f->sticks, o->points, o->level)
                       || !swt_fraction_sticks(f->sticks + o->points - 1 - k, o->points, o->level)))
            break;
    }
    if (nb) f->e_n /= nb;
    gsl_rng_free(g);
    return 0;
}

int swt_stick_fraction(const swr_model *m, double d, double vn, const swt_vcrit_opts *o,
                       swt_fraction *f, swt_vcrit_result *r, char *msg, size_t msglen)
{
    return fraction_run(m, d, vn, o, 0, f, r, msg, msglen);
}

int swt_sticks(const swr_model *m, double d, double vn, const swt_vcrit_opts *o,
               swt_vcrit_result *r, char *msg, size_t msglen)
{
    if (swr_model_rough(m)) {
        /* only the decision is wanted: stop once the points left cannot change it */
        swt_fraction f;
        if (fraction_run(m, d, vn, o, 1, &f, r, msg, msglen) != 0) return -1;
        return swt_fraction_sticks(f.sticks, o->points, o->level);
    }
    swr_impact in = { .d = d, .vn = vn, .vt = o->tan_angle > 0.0 ? vn * o->tan_angle : o->vt,
                      .omega = o->omega };
    swr_result res;
    memset(&res, 0, sizeof res);
    swr_status st = swr_collide(m, &in, &res, NULL);
    if (st == SWR_EINVAL) {
        if (msg) snprintf(msg, msglen, "%s", res.msg);
        return -1;
    }
    if (r) count(r, st, &res);
    if (msg && res.msg[0] && !msg[0]) snprintf(msg, msglen, "%s", res.msg);
    return swt_outcome(o, &res);
}

typedef struct {
    const swr_model *m;
    double d;
    const swt_vcrit_opts *o;
} kernel_ctx;

static int kernel_outcome(void *p, double v, swt_vcrit_result *r)
{
    kernel_ctx *c = p;
    return swt_sticks(c->m, c->d, v, c->o, r, r->msg, sizeof r->msg);
}

swt_vcrit_status swt_vcrit(const swr_model *m, double d, const swt_vcrit_opts *o,
                           swt_vcrit_result *r)
{
    kernel_ctx c = { m, d, o };
    return swt_vcrit_search(kernel_outcome, &c, o, r);
}

swt_vcrit_status swt_vcrit_search(int (*sticks)(void *ctx, double v, swt_vcrit_result *r),
                                  void *ctx, const swt_vcrit_opts *o, swt_vcrit_result *r)
{
    memset(r, 0, sizeof *r);
    const double ratio = o->scan_ratio > 1.0 ? o->scan_ratio : 2.0;
    const double rtol = o->rtol > 0.0 ? o->rtol : 1e-3;
    const int nscan = 1 + (int)ceil(log(o->vmax / o->vmin) / log(ratio) - 1e-9);
    const double step = log(o->vmax / o->vmin) / (nscan > 1 ? nscan - 1 : 1);

    int prev = -1, first_change = -1, s_first = 0;
    double v_prev = 0.0;
    for (int k = 0; k < nscan; k++) {
        double v = (k == nscan - 1) ? o->vmax : o->vmin * exp(step * k);
        int s = sticks(ctx, v, r);
        if (s < 0) { r->status = SWT_VCRIT_ERROR; r->vcrit = o->vmin; return r->status; }
        if (k > 0 && s != prev) {
            r->changes++;
            if (first_change < 0 && prev == 1) {
                first_change = k;
                r->v_lo = v_prev;
                r->v_hi = v;
            } else if (first_change >= 0 && s == 1 && r->v_restick == 0.0) {
                r->v_restick = v;
            }
        }
        if (k == 0) s_first = s;
        prev = s;
        v_prev = v;
    }
    if (first_change < 0) {
        /* no stick -> bounce change: sticks everywhere or never, or starts bouncing */
        if (s_first == 1) { r->status = SWT_VCRIT_ALL_STICK; r->vcrit = o->vmax; }
        else { r->status = SWT_VCRIT_NO_STICK; r->vcrit = o->vmin; }
        r->v_lo = r->v_hi = r->vcrit;
        return r->status;
    }
    /* bisection in log(v); the loop bound guards against a bad rtol */
    for (int it = 0; it < 200 && r->v_hi / r->v_lo > 1.0 + rtol; it++) {
        double v = sqrt(r->v_lo * r->v_hi);
        int s = sticks(ctx, v, r);
        if (s < 0) { r->status = SWT_VCRIT_ERROR; r->vcrit = o->vmin; return r->status; }
        if (s) r->v_lo = v; else r->v_hi = v;
    }
    r->vcrit = sqrt(r->v_lo * r->v_hi);
    r->status = SWT_VCRIT_FOUND;
    return r->status;
}
