/* sr_mapcompute.c - one computed map (snowregime map and sensitivity): the
 * grid, its interface and fit, and on a rough wall the p = 0.1 and 0.9
 * contours. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

void sr_mapres_free(sr_mapres *r)
{
    swt_map_free(r->mp);
    swt_interface_free(&r->it);
    if (r->contours) {
        swt_interface_free(&r->contours->lo);
        swt_interface_free(&r->contours->hi);
        free(r->contours);
    }
    memset(r, 0, sizeof *r);
}

int sr_map_contours(const swr_model *m, const sr_mapres *r, const swt_vcrit_opts *o,
                    int threads, sr_contours *c, char *err, size_t errlen)
{
    /* the interface extraction reads the grid at each options' level */
    memset(c, 0, sizeof *c);
    swt_vcrit_opts o1 = *o, o9 = *o;
    o1.level = 0.1;
    o9.level = 0.9;
    if (swt_interface_extract(r->mp, m, &o1, 1, threads, &c->lo, err, errlen) != 0) return -1;
    return swt_interface_extract(r->mp, m, &o9, 1, threads, &c->hi, err, errlen);
}

int sr_map_compute(const swr_model *m, const sr_mapopt *mo, const swt_vcrit_opts *o,
                   int threads, sr_mapres *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    double t0 = swt_now();
    r->mp = swt_map_alloc(&mo->g, err, errlen);
    if (!r->mp) return -1;
    r->mp->progress = mo->pg;
    if (swt_map_run(r->mp, m, o, threads, err, errlen) != 0) return -1;
    if (swt_interface_extract(r->mp, m, o, mo->refine, threads, &r->it, err, errlen) != 0) return -1;
    r->fit_ok = swt_fit_interface(&r->it, mo->degree, &r->fit, r->fit_err, sizeof r->fit_err) == 0;
    if (r->mp->points > 0) {
        r->contours = calloc(1, sizeof *r->contours);
        if (!r->contours) { snprintf(err, errlen, "out of memory"); return -1; }
        if (sr_map_contours(m, r, o, threads, r->contours, err, errlen) != 0) return -1;
    }
    r->seconds_total = swt_now() - t0;
    return 0;
}

