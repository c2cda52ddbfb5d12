/* swt_oblique.h - the stick/bounce interface over normal AND tangential speed:
 * d_crit(v_n, v_t) on a table of nodes, for the wall model's `regime`
 * tangential gate (doc/regime-coeffs.md).
 *
 * At each node (v_n, v_t) the largest diameter that "sticks" is found by the
 * same scan + bisection as swt_vcrit, run along ln d instead of ln v (small
 * particles stick, large ones bounce): swt_vcrit_search over [dlo, dhi] with
 * ratio 2 and the relative bracket rtol of the options. "Sticks" is the
 * outcome of the options: on oblique impacts full stick AND at rest within
 * max_slide of the impact point (the kernel's predicted s_rest), the one free
 * length of the criterion.
 */
#ifndef SWT_OBLIQUE_H
#define SWT_OBLIQUE_H

#include <stdio.h>

#include "swt_vcrit.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Node status */
enum { SWT_OB_FOUND = 0, SWT_OB_NO_STICK = 1, SWT_OB_ALL_STICK = 2 };

typedef struct {
    int nvt, nvn;
    double *vt, *vn;       /* nodes: vt[0] = 0 < vt[1] < ...; vn > 0 increasing */
    double *dcrit;         /* nvt * nvn, row-major by vt [m]; NO_STICK: dlo, ALL_STICK: dhi */
    int *status;           /* per node */
    double dlo, dhi;       /* diameter search range [m] */
    double max_slide;      /* the criterion's slide length [m] (0: full stick only) */
    long collisions;
    double seconds;
    int n_no_stick, n_all_stick, n_nonmono;
} swt_oblique;

/* d_crit at one (vn, vt) under o (o->vt and o->tan_angle are ignored). */
swt_vcrit_status swt_dcrit(const swr_model *m, double vn, double vt, const swt_vcrit_opts *o,
                           double dlo, double dhi, swt_vcrit_result *r);

/* Fill ob (allocated here; swt_oblique_free) on the nodes given, threads over
 * the nodes. vt must start at 0 and increase strictly, vn increase strictly.
 * 0, or -1 with a message. */
int swt_oblique_compute(swt_oblique *ob, const swr_model *m, const double *vt, int nvt,
                        const double *vn, int nvn, const swt_vcrit_opts *o, double dlo,
                        double dhi, int threads, char *err, size_t errlen);
void swt_oblique_free(swt_oblique *ob);

/* The table's keys, to be written inside regime { ... } (doc/regime-coeffs.md). */
void swt_oblique_write(FILE *fp, const swt_oblique *ob);

#ifdef __cplusplus
}
#endif
#endif
