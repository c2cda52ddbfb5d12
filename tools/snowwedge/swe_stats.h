/* swe_stats.h - the statistics of the wedge's rear face: records of parcels
 * on the face sorted into its regions, their effective sample size, the
 * composition of per-diameter clouds into a spray with the propagated
 * standard error, and the test of two halves of a sampling window.
 *
 * Regions (as snowphoto's): with u = (y - y0) / (y1 - y0) across the face
 * seen from behind and v = (z1 - z) / (z1 - z0) down it, edges where u or v
 * lies outside [0.1, 0.9], else left side u < 0.35, right side u > 0.65,
 * centre 0.3 <= v <= 0.7 (between them), else no region; the whole face holds
 * every record. Their areas over the face's: left and right 0.2 each, centre
 * 0.12, edges 0.36.
 *
 * The effective sample size of a region is n_eff = (sum_a W_a)^2 / sum_a W_a^2
 * over the independent origins a (injected parcels whose copies a splitting
 * made share their origin), W_a the mass of origin a's records; 1/sqrt(n_eff)
 * is the relative standard error of the region's mass (the sums by origin:
 * tools/snowpost/spo_origin.h). */
#ifndef SWE_STATS_H
#define SWE_STATS_H

#include <stddef.h>

enum { SWE_LEFT = 0, SWE_RIGHT, SWE_CENTRE, SWE_EDGES, SWE_FACE, SWE_NREGION };

/* "left side", "right side", "centre", "edges", "whole face" */
const char *swe_region_name(int r);
/* the region's area over the face's */
double swe_region_area(int r);
/* the region of (y, z) on the face [y0, y1] x [z0, z1]; -1 for none (the face) */
int swe_region_of(const double outline[4], double y, double z);

/* one record: a parcel on the face */
typedef struct {
    double y, z;  /* its position on the face */
    double mass;  /* its mass [kg] */
    long proc, id; /* its origin */
} swe_record;

/* a region's statistics */
typedef struct {
    long n;       /* records */
    long origins; /* independent origins */
    double mass;  /* their mass */
    double neff;  /* effective sample size (0 without records) */
} swe_region_stats;

/* the statistics of the records in every region (out[SWE_NREGION]) */
int swe_rear_stats(const swe_record *rec, size_t n, const double outline[4],
                   swe_region_stats out[SWE_NREGION], char *err, size_t errlen);

/* one class of a composition: its share of the spray's mass and its regions'
   mass and n_eff */
typedef struct {
    double w;
    double mass[SWE_NREGION];
    double neff[SWE_NREGION];
} swe_class;

/* the composed deposit of every region sum_k s w_k M_k,r and its variance
   sum_k (s w_k M_k,r)^2 / n_eff_k,r (classes without n_eff add none), s the
   scale (1 for a window, 2 for a half of it) */
void swe_compose(const swe_class *c, size_t n, double scale, double sum[SWE_NREGION],
                 double var[SWE_NREGION]);

/* does a region stand out from the face: its deposit against the face's
   times its area, beyond 2 standard errors? +1 higher, -1 lower, 0 no */
int swe_stands_out(double region, double var, double face, int r);

/* z = (b - a) / sqrt(va + vb) of two independent estimates (0 when both
   variances are 0); two-sided p-value in *p when p is given */
double swe_ztest(double a, double va, double b, double vb, double *p);

/* the run time that takes a relative error e at run time t to the target:
   t (e / target)^2, the error of n independent samples falling as 1/sqrt(n)
   and the time growing as n; 0 when target <= 0 or t, e not positive */
double swe_time_for_error(double t, double e, double target);

#endif
