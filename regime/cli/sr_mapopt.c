/* sr_mapopt.c - the grid and map options shared by snowregime map and
 * snowregime sensitivity: defaults, parsing, checks, the work estimate. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

void sr_mapopt_default(sr_mapopt *m)
{
    memset(m, 0, sizeof *m);
    m->g = (swt_grid){ 46, 50, 10e-6, 100e-6, 0.0, 0.0, 1 };
    m->degree = 3;
    m->refine = 1;
    m->plot = 1;
    swt_vcrit_opts_default(&m->o);
}

/* 1 taken, 0 not mine, -1 error */
int sr_mapopt_parse(sr_args *a, sr_mapopt *m)
{
    const char *v;
    long n;
    if (sr_flag(a, "--no-plot")) { m->plot = 0; return 1; }
    if (sr_flag(a, "--force")) { m->force = 1; return 1; }   /* long run and foreign --out folder */
    if (sr_flag(a, "--progress")) { m->progress = SWT_PROGRESS_ON; return 1; }
    if (sr_opt(a, "--out", &v)) {
        if (!v || !*v) { snprintf(a->err, sizeof a->err, "--out: missing folder name"); return -1; }
        m->out = v;
        return 1;
    }
#define INT_OPT(NAME, LO, HI, DST) \
    if (sr_opt(a, NAME, &v)) { \
        if (!v || swt_parse_int(NAME, v, LO, HI, &n, a->err, sizeof a->err)) return -1; \
        DST = (int)n; return 1; }
#define DBL_OPT(NAME, LO, HI, DST, EXTRA) \
    if (sr_opt(a, NAME, &v)) { \
        if (!v || swt_parse_double(NAME, v, LO, HI, &DST, a->err, sizeof a->err)) return -1; \
        EXTRA; return 1; }
    INT_OPT("--nd", 2, 10000, m->g.nd)
    INT_OPT("--nv", 2, 10000, m->g.nv)
    INT_OPT("--vlog", 0, 1, m->g.vlog)
    INT_OPT("--degree", 1, SWT_FIT_MAXDEG, m->degree)
    INT_OPT("--refine", 0, 1, m->refine)
    DBL_OPT("--dmin", SWR_D_MIN, SWR_D_MAX, m->g.dmin, (void)0)
    DBL_OPT("--dmax", SWR_D_MIN, SWR_D_MAX, m->g.dmax, (void)0)
    DBL_OPT("--vmin", SWR_V_MIN, SWR_V_MAX, m->g.vmin, m->set_vmin = 1)
    DBL_OPT("--vmax", SWR_V_MIN, SWR_V_MAX, m->g.vmax, m->set_vmax = 1)
    DBL_OPT("--tol", 1e-12, 0.5, m->o.rtol, (void)0)
    DBL_OPT("--max-slide", 1e-300, 1e3, m->o.max_slide, (void)0)
#undef INT_OPT
#undef DBL_OPT
    return 0;
}

/* Impacts of one map of mo on model m with options o (an estimate): the grid
 * (points per cell on a rough wall) and the interface bisections (the p =
 * 0.1 and 0.9 contours beside it on a rough wall), each evaluation about 60 %
 * of the points (swt_sticks stops once decided). */
double sr_map_work(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o)
{
    const int rough = swr_model_rough(m);
    const double P = rough ? o->points : 1.0, E = rough ? 0.6 * P : 1.0;
    const double cell = log(mo->g.dmax / mo->g.dmin) / (mo->g.nd - 1);
    const double bis = fmax(1.0, ceil(log2(cell / o->rtol)));
    const double levels = (mo->refine ? 1.0 : 0.0) + (rough ? 2.0 : 0.0);
    return (double)mo->g.nd * mo->g.nv * P + levels * mo->g.nv * bis * E;
}

/* The grid of the pilot before the speed range is known: the given speeds,
 * else 0.01-10 m/s (where sticking thresholds lie) */
swt_grid sr_pilot_grid(const sr_mapopt *mo)
{
    swt_grid g = mo->g;
    if (!mo->set_vmin) g.vmin = mo->set_vmax ? fmin(1e-2, 0.1 * g.vmax) : 1e-2;
    if (!mo->set_vmax) g.vmax = fmax(10.0, 10.0 * g.vmin);
    return g;
}

/* Grid size guard: a million cells is already about 45 MB of map.csv and
 * seconds to minutes of kernel time; beyond it a typo (--nd 10000 --nv 10000:
 * 4 GB, many minutes) is refused before anything runs. */
#define SR_MAX_CELLS 1000000L

int sr_mapopt_check(sr_mapopt *m, char *err, size_t errlen)
{
    if (!m->out) { snprintf(err, errlen, "--out: missing (output folder)"); return -1; }
    if ((long)m->g.nd * m->g.nv > SR_MAX_CELLS) {
        snprintf(err, errlen, "--nd x --nv: %d x %d = %ld cells, more than %ld (about %.0f MB of "
                 "map.csv); use a coarser grid", m->g.nd, m->g.nv, (long)m->g.nd * m->g.nv,
                 SR_MAX_CELLS, 45e-6 * (double)m->g.nd * m->g.nv);
        return -1;
    }
    if (!(m->g.dmax > m->g.dmin)) {
        snprintf(err, errlen, "--dmax: '%g' must be > --dmin (%g)", m->g.dmax, m->g.dmin);
        return -1;
    }
    if (m->set_vmin && m->set_vmax && !(m->g.vmax > m->g.vmin)) {
        snprintf(err, errlen, "--vmax: '%g' must be > --vmin (%g)", m->g.vmax, m->g.vmin);
        return -1;
    }
    return 0;
}

