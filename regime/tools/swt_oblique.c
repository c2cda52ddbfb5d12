/* swt_oblique.c - d_crit(v_n, v_t) table (see swt_oblique.h). */
#include "swt_oblique.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "swt_io.h"
#include "swt_map.h"

typedef struct {
    const swr_model *m;
    double vn;
    swt_vcrit_opts o;    /* o.vt: the tangential speed */
} dc_ctx;

static int sticks_at_d(void *ctx, double d, swt_vcrit_result *r)
{
    const dc_ctx *c = ctx;
    return swt_sticks(c->m, d, c->vn, &c->o, r, r->msg, sizeof r->msg);
}

swt_vcrit_status swt_dcrit(const swr_model *m, double vn, double vt, const swt_vcrit_opts *o,
                           double dlo, double dhi, swt_vcrit_result *r)
{
    dc_ctx c = { m, vn, *o };
    c.o.vt = vt;
    c.o.tan_angle = 0.0;
    swt_vcrit_opts so = *o;
    so.vmin = dlo;
    so.vmax = dhi;
    so.scan_ratio = 2.0;
    return swt_vcrit_search(sticks_at_d, &c, &so, r);
}

typedef struct {
    const swr_model *m;
    const swt_vcrit_opts *o;
    swt_oblique *ob;
    long *coll;
    int *nonmono;
    int *bad;
    char (*msg)[320];
} tab_ctx;

static void node(void *ctx, int k)
{
    tab_ctx *c = ctx;
    swt_oblique *ob = c->ob;
    const int i = k / ob->nvn, j = k % ob->nvn;
    swt_vcrit_result r;
    const swt_vcrit_status st = swt_dcrit(c->m, ob->vn[j], ob->vt[i], c->o, ob->dlo, ob->dhi, &r);
    c->coll[k] = r.collisions;
    c->nonmono[k] = r.changes > 1;
    switch (st) {
    case SWT_VCRIT_FOUND:
        ob->dcrit[k] = r.vcrit;
        ob->status[k] = SWT_OB_FOUND;
        break;
    case SWT_VCRIT_NO_STICK:
        ob->dcrit[k] = ob->dlo;
        ob->status[k] = SWT_OB_NO_STICK;
        break;
    case SWT_VCRIT_ALL_STICK:
        ob->dcrit[k] = ob->dhi;
        ob->status[k] = SWT_OB_ALL_STICK;
        break;
    default:
        c->bad[k] = 1;
        snprintf(c->msg[k], sizeof c->msg[k], "d_crit at vn %g m/s, vt %g m/s: %.200s", ob->vn[j],
                 ob->vt[i], r.msg);
    }
}

void swt_oblique_free(swt_oblique *ob)
{
    free(ob->vt);
    free(ob->vn);
    free(ob->dcrit);
    free(ob->status);
    memset(ob, 0, sizeof *ob);
}

int swt_oblique_compute(swt_oblique *ob, const swr_model *m, const double *vt, int nvt,
                        const double *vn, int nvn, const swt_vcrit_opts *o, double dlo,
                        double dhi, int threads, char *err, size_t errlen)
{
    memset(ob, 0, sizeof *ob);
    if (nvt < 2 || vt[0] != 0.0) {
        snprintf(err, errlen, "the tangential speeds of a d_crit(v_n, v_t) table must start "
                 "with 0 and have at least 2 values (got %d, first %g)", nvt, nvt ? vt[0] : NAN);
        return -1;
    }
    for (int i = 1; i < nvt; i++)
        if (!(vt[i] > vt[i - 1])) {
            snprintf(err, errlen, "tangential speeds must increase strictly: %g after %g",
                     vt[i], vt[i - 1]);
            return -1;
        }
    for (int j = 0; j < nvn; j++)
        if (!(vn[j] > 0.0) || (j && !(vn[j] > vn[j - 1]))) {
            snprintf(err, errlen, "normal speeds must be > 0 and increase strictly (%g)", vn[j]);
            return -1;
        }
    if (!(dlo > 0.0 && dhi > dlo)) {
        snprintf(err, errlen, "diameter range [%g, %g] is empty", dlo, dhi);
        return -1;
    }
    const size_t n = (size_t)nvt * (size_t)nvn;
    ob->nvt = nvt;
    ob->nvn = nvn;
    ob->dlo = dlo;
    ob->dhi = dhi;
    ob->max_slide = o->max_slide;
    ob->vt = malloc((size_t)nvt * sizeof *ob->vt);
    ob->vn = malloc((size_t)nvn * sizeof *ob->vn);
    ob->dcrit = malloc(n * sizeof *ob->dcrit);
    ob->status = malloc(n * sizeof *ob->status);
    long *coll = calloc(n, sizeof *coll);
    int *nonmono = calloc(n, sizeof *nonmono), *bad = calloc(n, sizeof *bad);
    char (*msg)[320] = calloc(n, sizeof *msg);
    int rc = 0;
    if (!ob->vt || !ob->vn || !ob->dcrit || !ob->status || !coll || !nonmono || !bad || !msg) {
        snprintf(err, errlen, "out of memory for a %d x %d table", nvt, nvn);
        rc = -1;
    } else {
        memcpy(ob->vt, vt, (size_t)nvt * sizeof *vt);
        memcpy(ob->vn, vn, (size_t)nvn * sizeof *vn);
        tab_ctx c = { m, o, ob, coll, nonmono, bad, msg };
        const double t0 = swt_now();
        swt_parallel_for((int)n, threads, node, &c);
        ob->seconds = swt_now() - t0;
        for (size_t k = 0; k < n; k++) {
            if (bad[k] && rc == 0) {
                snprintf(err, errlen, "%s", msg[k]);
                rc = -1;
            }
            ob->collisions += coll[k];
            ob->n_nonmono += nonmono[k];
            ob->n_no_stick += ob->status[k] == SWT_OB_NO_STICK;
            ob->n_all_stick += ob->status[k] == SWT_OB_ALL_STICK;
        }
    }
    free(coll);
    free(nonmono);
    free(bad);
    free(msg);
    if (rc != 0)
        swt_oblique_free(ob);
    return rc;
}

static void write_list(FILE *fp, const char *key, const double *v, int n, int per_line)
{
    fprintf(fp, "    %-15s (", key);
    for (int i = 0; i < n; i++)
        fprintf(fp, "%s%.9g", i == 0 ? "" : (per_line && i % per_line == 0 ? "\n                     " : " "),
                v[i]);
    fprintf(fp, ");\n");
}

void swt_oblique_write(FILE *fp, const swt_oblique *ob)
{
    fprintf(fp, "\n    // Oblique impacts (the wall model's tangential gate `model regime`):\n");
    fprintf(fp, "    // d_crit(v_n, v_t) from the kernel, stick = full stick and at rest within\n");
    fprintf(fp, "    // obliqueSlide of the impact point; rows by v_t, columns by v_n; nodes that\n");
    fprintf(fp, "    // stick at every d up to %g m hold %g, nodes that bounce at every d down\n", ob->dhi, ob->dhi);
    fprintf(fp, "    // to %g m hold %g (%d and %d nodes here).\n", ob->dlo, ob->dlo, ob->n_all_stick,
            ob->n_no_stick);
    fprintf(fp, "    obliqueSlide    %.10g;  // [m]\n", ob->max_slide);
    write_list(fp, "obliqueVt", ob->vt, ob->nvt, 0);
    write_list(fp, "obliqueVn", ob->vn, ob->nvn, 10);
    write_list(fp, "obliqueDCrit", ob->dcrit, ob->nvt * ob->nvn, ob->nvn);
}
