/* swt_fit.h - polynomial fit of the interface and the regime.coeffs writer.
 *
 * Fit (GSL least squares, gsl_multifit_linear) in the log basis of
 * doc/regime-coeffs.md: ln(d_crit / 1 m) = sum_i c_i (ln(v_n / 1 m/s))^i.
 * Residuals are relative residuals of d_crit: d_fit / d_point - 1.
 */
#ifndef SWT_FIT_H
#define SWT_FIT_H

#include <stdio.h>

#include "swr_params.h"
#include "swt_map.h"
#include "swt_oblique.h"
#include "swt_rebound.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SWT_FIT_MAXDEG 8

typedef struct {
    int degree;                    /* degree actually fitted */
    int degree_asked;
    double c[SWT_FIT_MAXDEG + 1];  /* c0 first */
    double rms, maxres;            /* relative residuals of d_crit */
    double chisq;                  /* of the ln fit */
    double vnmin, vnmax;           /* span of the points [m/s] */
    double slope_lo, slope_hi;     /* log-log slopes near each end (from the points) */
    int decreasing;                /* 1: fit non-increasing over [vnmin, vnmax] */
    int npts;
    char note[200];                /* what was adjusted and why ("" if nothing) */
} swt_fit;

/* ln d_crit from the fitted polynomial at vn. */
double swt_fit_eval(const swt_fit *f, double vn);
/* Fit degree `degree` (1..SWT_FIT_MAXDEG) to the interface. When the fit is
 * not non-increasing over its span, lower degrees are tried (note says so).
 * 0, or -1 with a message (fewer than degree+1 points, no decreasing fit). */
int swt_fit_interface(const swt_interface *it, int degree, swt_fit *f, char *err, size_t errlen);
/* Write regime.coeffs per doc/regime-coeffs.md. */
void swt_coeffs_write(FILE *fp, const swt_fit *f, const swr_params *p, double dmin, double dmax,
                      const char *label);
/* The same with the d_crit(v_n, v_t) table of oblique impacts (ob may be NULL). */
void swt_coeffs_write_ex(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                         double dmax, const char *label, const swt_oblique *ob);
/* A rough wall's: the fit of the p = 0.5 contour with the stick-probability
 * table of the map (probabilityD/Vn/Stick/Points, doc/regime-coeffs.md). */
void swt_coeffs_write_rough(FILE *fp, const swt_fit *f, const swr_params *p, const swt_map *mp,
                            const char *label);
/* A rough wall's stick-probability table: p over (d, v_n), or with nvt > 0
 * over (v_t, d, v_n): p[(k nd + i) nv + j] (one map per v_t, k the layer). */
typedef struct {
    const double *d, *v, *vt;   /* [nd], [nv], [nvt] (vt NULL when nvt = 0) */
    int nd, nv, nvt;
    const float *p;
    int points;                 /* impact points per cell */
} swt_prob;
/* The fit with a probability table (over v_t too) and the rebound tables. */
void swt_coeffs_write_prob(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                           double dmax, const char *label, const swt_prob *pr,
                           const swt_rebound *rb);
/* Everything: the oblique table (ob), a rough wall's probability table (rough)
 * and the kernel's rebound tables (rb), each NULL when absent. */
void swt_coeffs_write_all(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                          double dmax, const char *label, const swt_oblique *ob,
                          const swt_map *rough, const swt_rebound *rb);

#ifdef __cplusplus
}
#endif
#endif
