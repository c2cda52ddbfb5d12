/* swc_channel.c - 1-D channel deposition with the near-wall dispersion model
 * (see swc_channel.h). */
#include "swc_channel.h"
#include "swp_nearwall.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define NBATCH 20

void swc_params_default(swc_params *p)
{
    p->re_tau = 314.0;
    p->tau_plus = 1.0;
    p->r_plus = 0.0;
    p->n = 2000;
    p->t_warm = 2000.0;
    p->t_run = 20000.0;
    p->dt_max = 2.0;
    p->c_tl = 0.1;
    p->c_y = 0.2;
    p->y_sub = 10.0;
    p->g_plus = 0.0;
    p->scheme = SWC_EXACT;
    p->seed = 1;
}

/* lo < x <= hi (lo_open) or lo <= x <= hi, quiet for a NaN (refused) */
static int within(double x, double lo, double hi, int lo_open)
{
    return (lo_open ? isgreater(x, lo) : isgreaterequal(x, lo)) && islessequal(x, hi);
}

static int bad(char *err, size_t n, const char *what, double v, const char *range)
{
    snprintf(err, n, "%s = %g: %s", what, v, range);
    return -1;
}

int swc_params_check(const swc_params *p, char *err, size_t n)
{
    if (!within(p->re_tau, 10.0, 1e5, 1))
        return bad(err, n, "Re_tau", p->re_tau, "must lie in (10, 1e5]");
    if (!within(p->tau_plus, 0.0, 1e4, 1))
        return bad(err, n, "tau+", p->tau_plus, "must lie in (0, 1e4]");
    if (!(isgreaterequal(p->r_plus, 0.0) && isless(p->r_plus, 0.5 * p->re_tau)))
        return bad(err, n, "r+", p->r_plus, "must lie in [0, Re_tau/2)");
    if (p->n < 1 || p->n > 100000000)
        return bad(err, n, "particles", (double)p->n, "must lie in 1 .. 1e8");
    if (!within(p->t_warm, 0.0, 1e9, 0))
        return bad(err, n, "warm-up t+", p->t_warm, "must lie in [0, 1e9]");
    if (!within(p->t_run, 0.0, 1e9, 1))
        return bad(err, n, "window t+", p->t_run, "must lie in (0, 1e9]");
    if (!within(p->dt_max, 0.0, 100.0, 1))
        return bad(err, n, "dtMax+", p->dt_max, "must lie in (0, 100]");
    if (!within(p->c_tl, 0.0, 1.0, 1))
        return bad(err, n, "cT", p->c_tl, "must lie in (0, 1]");
    if (!within(p->c_y, 0.0, 1.0, 1))
        return bad(err, n, "cY", p->c_y, "must lie in (0, 1]");
    if (!(isgreater(p->y_sub, 0.0) && isless(p->y_sub, p->re_tau)))
        return bad(err, n, "sublayer y+", p->y_sub, "must lie in (0, Re_tau)");
    if (!within(p->g_plus, 0.0, 1.0, 0))
        return bad(err, n, "g+", p->g_plus, "must lie in [0, 1]");
    if (p->scheme != SWC_EXACT && p->scheme != SWC_HOST)
        return bad(err, n, "scheme", (double)p->scheme, "must be exact (0) or host (1)");
    return 0;
}

typedef struct {
    double y, v, w[3];
} particle;

/* the bulk of a fully developed channel in wall units (see the header):
   k, its wall-normal gradient (the walk's drift needs the gradient of the
   same k) and eps at the particle */
static void bulk(double yp, double h, swd_local *at)
{
    const double f = 1.0 - 0.6 * yp / h;
    at->k = f / sqrt(0.09);
    at->grad_k[1] = -0.6 / (h * sqrt(0.09));
    at->eps = f / (SWP_KARMAN * fmax(yp, 1.0));
}

static void release(particle *q, const swd_model *m, double h, double rmin, double vs,
                    gsl_rng *rng)
{
    q->y = rmin + (h - rmin) * gsl_rng_uniform_pos(rng);
    for (int i = 0; i < 3; i++)
        q->w[i] = gsl_ran_gaussian_ziggurat(rng, 1.0);
    swd_local at = { .y = q->y, .u_tau = 1.0, .nu = 1.0 };
    bulk(q->y, h, &at);
    swd_stats s;
    swd_stats_at(m, &at, &s);
    q->v = s.sigma[1] * q->w[1] - vs;   /* the fluid's velocity plus settling */
}

int swc_run(const swd_model *m, const swc_params *p, swc_result *r, char *err, size_t n)
{
    if (swc_params_check(p, err, n))
        return -1;
    if (!swd_ready(m)) {
        snprintf(err, n, "the near-wall model is not committed");
        return -1;
    }
    particle *ps = malloc(p->n * sizeof *ps);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!ps || !rng) {
        free(ps);
        if (rng)
            gsl_rng_free(rng);
        snprintf(err, n, "out of memory for %zu particles", p->n);
        return -2;
    }
    gsl_rng_set(rng, p->seed);
    const double h = p->re_tau, tau = p->tau_plus, ymin = p->r_plus;
    const double vs = p->g_plus * tau;   /* settling velocity, towards the wall */
    const double t_end = p->t_warm + p->t_run;
    for (size_t i = 0; i < p->n; i++)
        release(&ps[i], m, h, ymin, vs, rng);

    /* per batch: tracked deposits plus the closure's expected ones (its
       probabilities summed: the same mean as its draws, far less noise) */
    double batch[NBATCH] = { 0 }, eclosure = 0.0;
    size_t ntracked = 0, nclosure = 0;
    double steps = 0.0, tsum = 0.0, tlayer = 0.0, twall = 0.0;
    const int closure = swd_closure_on(m);
    const double layer = swd_get(m, "layerYPlus");
    for (size_t i = 0; i < p->n; i++) {
        particle *q = &ps[i];
        double t = 0.0;
        while (t < t_end) {
            swd_local at = { .y = q->y, .u_tau = 1.0, .nu = 1.0 };
            bulk(q->y, h, &at);
            swd_stats s;
            swd_stats_at(m, &at, &s);
            double dt = p->dt_max;
            if (isfinite(s.tl))
                dt = fmin(dt, p->c_tl * s.tl);
            dt = fmin(dt, p->c_y * fmax(q->y, 0.5) / (fabs(q->v) + s.sigma[1] + 1e-12));
            dt = fmin(dt, t_end - t);
            if (!(dt > 0.0))
                break;
            /* the fluctuation advanced first, then the particle moved with
               it (the hosts' order: swd.h) */
            double xi[3];
            for (int c = 0; c < 3; c++)
                xi[c] = gsl_ran_gaussian_ziggurat(rng, 1.0);
            double kick[3];
            swd_advance(m, &at, dt, tau, q->w, xi, kick, NULL);
            const double e = exp(-dt / tau), one_e = -expm1(-dt / tau);
            /* the fluid's fluctuation over the step (sigma at its midpoint),
               and the velocity the particle relaxes to: that minus settling */
            const double vf = kick[1] / one_e - vs;
            double ynew;
            if (p->scheme == SWC_EXACT)
                ynew = q->y + vf * dt + (q->v - vf) * tau * one_e;
            else
                ynew = q->y + q->v * dt;
            const double vnew = vf + (q->v - vf) * e;
            if (t >= p->t_warm) {
                steps += 1.0;
                tsum += dt;
                if (q->y < layer)
                    tlayer += dt;
                if (q->y < p->y_sub)
                    twall += dt;
            }
            int deposit = 0;
            if (closure) {
                const double lambda = swd_deposit_rate(m, &s, 1.0, tau);
                const double prob = -expm1(-lambda * dt);
                if (lambda > 0.0 && t + dt > p->t_warm) {
                    int b = (int)((t + dt - p->t_warm) / p->t_run * NBATCH);
                    batch[b < NBATCH ? b : NBATCH - 1] += prob;
                    eclosure += prob;
                }
                if (lambda > 0.0 && gsl_rng_uniform(rng) < prob)
                    deposit = 1;
            }
            t += dt;
            q->y = ynew;
            q->v = vnew;
            if (q->y > h) {   /* the centreplane is a mirror */
                q->y = 2.0 * h - q->y;
                q->v = -q->v;
                q->w[1] = -q->w[1];
            }
            if (deposit || q->y <= ymin) {
                if (t > p->t_warm) {
                    if (q->y <= ymin) {   /* reached the wall by its own motion */
                        int b = (int)((t - p->t_warm) / p->t_run * NBATCH);
                        batch[b < NBATCH ? b : NBATCH - 1] += 1.0;
                        ntracked++;
                    } else {
                        nclosure++;
                    }
                }
                release(q, m, h, ymin, vs, rng);
            }
        }
    }

    double d = 0.0;
    for (int b = 0; b < NBATCH; b++)
        d += batch[b];
    const double scale = h / ((double)p->n * p->t_run);
    double mean = d / NBATCH, var = 0.0;
    for (int b = 0; b < NBATCH; b++)
        var += (batch[b] - mean) * (batch[b] - mean);
    var /= (NBATCH - 1);
    r->deposits = ntracked;
    r->deposits_closure = nclosure;
    r->expected_closure = eclosure;
    r->vplus = d * scale;
    /* the batch scatter, never below the Poisson error of the tracked count */
    const double se_batch = sqrt(var / NBATCH) * NBATCH * scale;
    const double se_pois = sqrt((double)(ntracked > 0 ? ntracked : 1)) * scale;
    r->vplus_se = fmax(se_batch, se_pois);
    r->steps = steps;
    r->dt_mean = steps > 0 ? tsum / steps : 0.0;
    r->frac_layer = tsum > 0 ? tlayer / tsum : 0.0;
    /* time fraction in y+ < y_sub over the volume fraction of that slab */
    r->c_sub = tsum > 0 ? (twall / tsum) / ((p->y_sub - ymin) / (h - ymin)) : 0.0;
    gsl_rng_free(rng);
    free(ps);
    return 0;
}

/* the runs of one calibration pass, shared by the worker threads */
typedef struct {
    const swd_model *m;
    const swc_params *p;
    const double *tau;
    unsigned long seed0;
    size_t n, next;
    swc_result *res;
    int *rc;
    char (*err)[256];
    pthread_mutex_t lock;
} pass;

static void *worker(void *arg)
{
    pass *w = arg;
    for (;;) {
        pthread_mutex_lock(&w->lock);
        const size_t i = w->next++;
        pthread_mutex_unlock(&w->lock);
        if (i >= w->n)
            return NULL;
        swc_params q = *w->p;
        q.tau_plus = w->tau[i];
        q.seed = w->seed0 + i;
        w->rc[i] = swc_run(w->m, &q, &w->res[i], w->err[i], sizeof w->err[i]);
    }
}

/* one run per tau+, on as many threads as there are cores (at most 8) */
static int run_pass(const swd_model *m, const swc_params *p, const double *tau, size_t n,
                    unsigned long seed0, swc_result *res, char *err, size_t errlen)
{
    int *rc = calloc(n, sizeof *rc);
    char (*msg)[256] = calloc(n, sizeof *msg);
    if (!rc || !msg) {
        free(rc);
        free(msg);
        snprintf(err, errlen, "out of memory");
        return -2;
    }
    pass w = { m, p, tau, seed0, n, 0, res, rc, msg, PTHREAD_MUTEX_INITIALIZER };
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    size_t nt = cores < 1 ? 1 : (cores > 8 ? 8 : (size_t)cores);
    if (nt > n)
        nt = n;
    pthread_t th[8];
    size_t started = 0;
    for (size_t t = 1; t < nt; t++)
        if (pthread_create(&th[t], NULL, worker, &w) == 0)
            started = t;
        else
            break;
    worker(&w);   /* this thread works too */
    for (size_t t = 1; t <= started; t++)
        pthread_join(th[t], NULL);
    int out = 0;
    for (size_t i = 0; i < n && !out; i++)
        if (rc[i]) {
            out = rc[i];
            snprintf(err, errlen, "%s", msg[i]);
        }
    free(rc);
    free(msg);
    return out;
}

int swc_calibrate(const swd_model *m, const swc_params *p, double ysub, const double *tau_plus,
                  const double *law, size_t n, double *vs, double *vcrw, double *vcrw_se,
                  double *c_s, double *vtot, double *vtot_se, char *err, size_t errlen)
{
    if (n < 2) {
        snprintf(err, errlen, "the calibration needs at least 2 tau+ values (got %zu)", n);
        return -1;
    }
    for (size_t i = 0; i < n; i++)
        if (!isfinite(law[i]) || law[i] < 0.0) {
            snprintf(err, errlen, "law[%zu] = %g is not finite and >= 0", i, law[i]);
            return -1;
        }
    swd_model *w = swd_alloc();
    swc_result *r = malloc(n * sizeof *r);
    double *crw = malloc(n * sizeof *crw);
    if (!w || !r || !crw) {
        swd_free(w);
        free(r);
        free(crw);
        snprintf(err, errlen, "out of memory");
        return -2;
    }
    int rc = 0;
    for (size_t k = 0; swd_key(k) && rc == 0; k++)
        if (swd_set(w, swd_key(k), swd_get(m, swd_key(k))) != SWD_OK) {
            snprintf(err, errlen, "%s", swd_errmsg(w));
            rc = -1;
        }
    if (rc == 0 && swd_commit(w) != SWD_OK) {
        snprintf(err, errlen, "%s", swd_errmsg(w));
        rc = -1;
    }
    swc_params q = *p;
    q.y_sub = ysub;
    q.g_plus = 0.0;   /* the law is turbulent deposition: calibrated without gravity */
    /* the CRW alone */
    if (rc == 0)
        rc = run_pass(w, &q, tau_plus, n, p->seed, r, err, errlen);
    for (size_t i = 0; i < n && rc == 0; i++) {
        crw[i] = r[i].vplus;
        if (vcrw)
            vcrw[i] = r[i].vplus;
        if (vcrw_se)
            vcrw_se[i] = r[i].vplus_se;
        if (c_s)
            c_s[i] = r[i].c_sub;
        vs[i] = r[i].c_sub > 0.0 ? fmax(0.0, law[i] - crw[i]) / r[i].c_sub : 0.0;
    }
    if (rc == 0 && swd_set_closure(w, ysub, tau_plus, vs, n) != SWD_OK) {
        snprintf(err, errlen, "%s", swd_errmsg(w));
        rc = -1;
    }
    if (rc == 0 && swd_commit(w) != SWD_OK) {
        snprintf(err, errlen, "%s", swd_errmsg(w));
        rc = -1;
    }
    /* once more with the closure: correct for the sublayer's depletion */
    if (rc == 0)
        rc = run_pass(w, &q, tau_plus, n, p->seed + n, r, err, errlen);
    for (size_t i = 0; i < n && rc == 0; i++) {
        if (vtot)
            vtot[i] = r[i].vplus;
        if (vtot_se)
            vtot_se[i] = r[i].vplus_se;
        const double want = law[i] - crw[i], got = r[i].vplus - crw[i];
        if (vs[i] > 0.0 && want > 0.0 && got > 0.0)
            vs[i] *= want / got;
    }
    swd_free(w);
    free(r);
    free(crw);
    return rc;
}
