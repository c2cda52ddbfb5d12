/* swt_map.c - regime map (threaded), interface extraction. */
#include "swt_map.h"
#include "swt_progress.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "swt_io.h"

typedef struct {
    int n, threads, t;
    void (*fn)(void *, int);
    void *ctx;
} swt_pf_arg;

static void *pf_worker(void *p)
{
    swt_pf_arg *a = p;
    for (int k = a->t; k < a->n; k += a->threads) a->fn(a->ctx, k);
    return NULL;
}

int swt_parallel_for(int n, int threads, void (*fn)(void *ctx, int k), void *ctx)
{
    if (threads < 1) threads = 1;
    if (threads > 64) threads = 64;
    if (threads > n) threads = n > 0 ? n : 1;
    pthread_t tid[64];
    swt_pf_arg arg[64];
    int started = 0;
    for (int t = 0; t < threads; t++) {
        arg[t] = (swt_pf_arg){ n, threads, t, fn, ctx };
        if (t == 0) continue;   /* the calling thread does share 0 */
        if (pthread_create(&tid[t], NULL, pf_worker, &arg[t]) != 0) break;
        started = t;
    }
    /* shares whose thread could not start run here */
    for (int t = started + 1; t < threads; t++) pf_worker(&arg[t]);
    pf_worker(&arg[0]);
    for (int t = 1; t <= started; t++) pthread_join(tid[t], NULL);
    return 0;
}

int swt_grid_check(const swt_grid *g, char *err, size_t errlen)
{
    if (g->nd < 2 || g->nd > 100000) { snprintf(err, errlen, "--nd: '%d' must be in [2, 100000]", g->nd); return -1; }
    if (g->nv < 2 || g->nv > 100000) { snprintf(err, errlen, "--nv: '%d' must be in [2, 100000]", g->nv); return -1; }
    if (!(g->dmin > 0.0) || !isfinite(g->dmin)) { snprintf(err, errlen, "--dmin: '%g' must be > 0", g->dmin); return -1; }
    if (!(g->dmax > g->dmin) || !isfinite(g->dmax)) { snprintf(err, errlen, "--dmax: '%g' must be > --dmin (%g)", g->dmax, g->dmin); return -1; }
    if (!(g->vmin > 0.0) || !isfinite(g->vmin)) { snprintf(err, errlen, "--vmin: '%g' must be > 0", g->vmin); return -1; }
    if (!(g->vmax > g->vmin) || !isfinite(g->vmax)) { snprintf(err, errlen, "--vmax: '%g' must be > --vmin (%g)", g->vmax, g->vmin); return -1; }
    return 0;
}

swt_map *swt_map_alloc(const swt_grid *g, char *err, size_t errlen)
{
    if (swt_grid_check(g, err, errlen) != 0) return NULL;
    swt_map *mp = calloc(1, sizeof *mp);
    if (!mp) { snprintf(err, errlen, "out of memory"); return NULL; }
    size_t n = (size_t)g->nd * (size_t)g->nv;
    mp->g = *g;
    mp->d = malloc((size_t)g->nd * sizeof *mp->d);
    mp->v = malloc((size_t)g->nv * sizeof *mp->v);
    mp->stick = calloc(n, 1);
    mp->kept = calloc(n, 1);
    mp->status = calloc(n, 1);
    mp->e_n = calloc(n, sizeof *mp->e_n);
    mp->e_t = calloc(n, sizeof *mp->e_t);
    mp->p = calloc(n, sizeof *mp->p);
    if (!mp->d || !mp->v || !mp->stick || !mp->kept || !mp->status || !mp->e_n || !mp->e_t
        || !mp->p) {
        swt_map_free(mp);
        snprintf(err, errlen, "out of memory for a %d x %d map", g->nd, g->nv);
        return NULL;
    }
    for (int i = 0; i < g->nd; i++)
        mp->d[i] = g->dmin + (g->dmax - g->dmin) * i / (g->nd - 1);
    for (int j = 0; j < g->nv; j++)
        mp->v[j] = g->vlog ? g->vmin * pow(g->vmax / g->vmin, (double)j / (g->nv - 1))
                           : g->vmin + (g->vmax - g->vmin) * j / (g->nv - 1);
    return mp;
}

void swt_map_free(swt_map *mp)
{
    if (!mp) return;
    free(mp->d); free(mp->v); free(mp->stick); free(mp->kept); free(mp->status);
    free(mp->e_n); free(mp->e_t); free(mp->p); free(mp);
}

typedef struct {
    swt_map *mp;
    const swr_model *m;
    const swt_vcrit_opts *o;
    long *collisions, *steps, *step_bound;   /* per row */
    int *bad;                                 /* per row: kernel error */
    char (*msg)[200];                         /* per row */
} map_ctx;

static void map_row(void *p, int i)
{
    map_ctx *c = p;
    swt_map *mp = c->mp;
    const int nv = mp->g.nv;
    if (swr_model_rough(c->m)) {
        for (int j = 0; j < nv; j++) {
            const size_t k = (size_t)i * nv + j;
            swt_fraction f;
            if (swt_stick_fraction(c->m, mp->d[i], mp->v[j], c->o, &f, NULL, c->msg[i],
                                   sizeof c->msg[i]) != 0) {
                c->bad[i] = 1;
                return;
            }
            mp->p[k] = (float)((double)f.sticks / f.points);
            mp->stick[k] = mp->kept[k] = swt_fraction_sticks(f.sticks, f.points, c->o->level);
            mp->status[k] = f.bound > 0;
            mp->e_n[k] = (float)f.e_n;
            mp->e_t[k] = 0.0f;
            c->collisions[i] += f.points;
            c->steps[i] += f.steps;
            c->step_bound[i] += f.bound;
            swt_progress_add(mp->progress, f.points);
        }
        return;
    }
    for (int j = 0; j < nv; j++) {
        double vn = mp->v[j];
        swr_impact in = { .d = mp->d[i], .vn = vn,
                          .vt = c->o->tan_angle > 0.0 ? vn * c->o->tan_angle : c->o->vt,
                          .omega = c->o->omega };
        swr_result r;
        memset(&r, 0, sizeof r);
        swr_status st = swr_collide(c->m, &in, &r, NULL);
        size_t k = (size_t)i * nv + j;
        if (st == SWR_EINVAL) {
            c->bad[i] = 1;
            snprintf(c->msg[i], sizeof c->msg[i], "d %g m, v_n %g m/s: %s", mp->d[i], vn, r.msg);
            return;
        }
        if (r.msg[0] && !c->msg[i][0]) snprintf(c->msg[i], sizeof c->msg[i], "%s", r.msg);
        mp->kept[k] = r.contact_kept != 0;
        mp->stick[k] = (unsigned char)swt_outcome(c->o, &r);
        mp->p[k] = mp->stick[k];
        mp->status[k] = (unsigned char)st;
        mp->e_n[k] = (float)(isfinite(r.e_n) ? r.e_n : 0.0);
        mp->e_t[k] = (float)(isfinite(r.e_t) ? r.e_t : 0.0);
        c->collisions[i]++;
        c->steps[i] += r.steps;
        if (st == SWR_STEP_BOUND) c->step_bound[i]++;
    }
    swt_progress_add(mp->progress, nv);   /* a flat row: one impact a cell */
}

int swt_map_run(swt_map *mp, const swr_model *m, const swt_vcrit_opts *o, int threads,
                char *err, size_t errlen)
{
    const int nd = mp->g.nd;
    map_ctx c = { mp, m, o, calloc((size_t)nd, sizeof(long)), calloc((size_t)nd, sizeof(long)),
                  calloc((size_t)nd, sizeof(long)), calloc((size_t)nd, sizeof(int)),
                  calloc((size_t)nd, sizeof(char[200])) };
    int rc = 0;
    if (!c.collisions || !c.steps || !c.step_bound || !c.bad || !c.msg) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
        goto done;
    }
    mp->points = swr_model_rough(m) ? o->points : 0;
    double t0 = swt_now();
    swt_parallel_for(nd, threads, map_row, &c);
    mp->seconds = swt_now() - t0;
    mp->collisions = mp->steps = mp->step_bound = mp->nstick = 0;
    mp->msg[0] = '\0';
    for (int i = 0; i < nd; i++) {
        if (c.bad[i] && rc == 0) {
            snprintf(err, errlen, "%s", c.msg[i]);
            rc = -1;
        }
        if (!mp->msg[0] && c.msg[i][0]) snprintf(mp->msg, sizeof mp->msg, "%s", c.msg[i]);
        mp->collisions += c.collisions[i];
        mp->steps += c.steps[i];
        mp->step_bound += c.step_bound[i];
    }
    for (size_t k = 0; k < (size_t)nd * mp->g.nv; k++) mp->nstick += mp->stick[k];
done:
    free(c.collisions); free(c.steps); free(c.step_bound); free(c.bad); free(c.msg);
    return rc;
}

typedef struct {
    const swt_map *mp;
    const swr_model *m;
    const swt_vcrit_opts *o;
    int refine;
    double *dc;        /* [nv], 0: no point */
    int *kind;         /* [nv]: 0 point, 1 all stick, 2 all bounce, 3 starts bouncing */
    int *nonmono;      /* [nv] */
    long *coll;        /* [nv] */
} itf_ctx;

/* Grid point k sticks: its outcome; on a rough wall its stick count (p x points,
 * exact: p is a count over points) at the options' level. */
static int grid_sticks(const swt_map *mp, const swt_vcrit_opts *o, size_t k)
{
    if (mp->points > 0)
        return swt_fraction_sticks((int)lround((double)mp->p[k] * mp->points), mp->points,
                                   o->level);
    return mp->stick[k];
}

static void itf_col(void *p, int j)
{
    itf_ctx *c = p;
    const swt_map *mp = c->mp;
    const int nd = mp->g.nd, nv = mp->g.nv;
    int first = -1, changes = 0;
    for (int i = 1; i < nd; i++) {
        int a = grid_sticks(mp, c->o, (size_t)(i - 1) * nv + j);
        int b = grid_sticks(mp, c->o, (size_t)i * nv + j);
        if (a != b) {
            changes++;
            if (first < 0 && a == 1 && b == 0) first = i;
        }
    }
    c->nonmono[j] = changes > 1;
    c->dc[j] = 0.0;
    if (first < 0) {
        int s0 = grid_sticks(mp, c->o, (size_t)j);
        c->kind[j] = changes == 0 ? (s0 ? 1 : 2) : 3;
        return;
    }
    c->kind[j] = 0;
    double lo = mp->d[first - 1], hi = mp->d[first];
    if (c->refine) {
        swt_vcrit_result acc;
        memset(&acc, 0, sizeof acc);
        for (int it = 0; it < 100 && hi / lo > 1.0 + c->o->rtol; it++) {
            double d = sqrt(lo * hi);
            const long before = acc.collisions;
            int s = swt_sticks(c->m, d, mp->v[j], c->o, &acc, NULL, 0);
            swt_progress_add(mp->progress, acc.collisions - before);
            if (s < 0) break;
            if (s) lo = d; else hi = d;
        }
        c->coll[j] = acc.collisions;
    }
    c->dc[j] = sqrt(lo * hi);
}

int swt_interface_extract(const swt_map *mp, const swr_model *m, const swt_vcrit_opts *o,
                          int refine, int threads, swt_interface *it, char *err, size_t errlen)
{
    const int nv = mp->g.nv;
    memset(it, 0, sizeof *it);
    itf_ctx c = { mp, m, o, refine, calloc((size_t)nv, sizeof(double)),
                  calloc((size_t)nv, sizeof(int)), calloc((size_t)nv, sizeof(int)),
                  calloc((size_t)nv, sizeof(long)) };
    it->vn = malloc((size_t)nv * sizeof(double));
    it->dcrit = malloc((size_t)nv * sizeof(double));
    if (!c.dc || !c.kind || !c.nonmono || !c.coll || !it->vn || !it->dcrit) {
        free(c.dc); free(c.kind); free(c.nonmono); free(c.coll);
        swt_interface_free(it);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    swt_parallel_for(nv, threads, itf_col, &c);
    for (int j = 0; j < nv; j++) {
        it->collisions += c.coll[j];
        it->cols_nonmono += c.nonmono[j];
        if (c.kind[j] == 1) it->cols_all_stick++;
        else if (c.kind[j] == 2) it->cols_all_bounce++;
        if (c.kind[j] == 0 && c.dc[j] > 0.0) {
            it->vn[it->n] = mp->v[j];
            it->dcrit[it->n] = c.dc[j];
            it->n++;
        }
    }
    free(c.dc); free(c.kind); free(c.nonmono); free(c.coll);
    return 0;
}

void swt_interface_free(swt_interface *it)
{
    if (!it) return;
    free(it->vn); free(it->dcrit);
    it->vn = it->dcrit = NULL;
    it->n = 0;
}
