/* swe_spray.h - the spray of the wind-tunnel wedge: droplet mass log-normal in
 * the diameter, truncated to a range of droplet diameters, each droplet
 * frozen to an ice particle of freeze x its diameter; its size classes (the
 * diameters of the per-diameter clouds and the share of the spray's mass each
 * stands for) and the mass median diameters of the spray and of a deposit
 * composed from the classes.
 *
 * Diameters are in um. The cumulative mass below an ice diameter x is
 *   F(x) = Phi((ln(x / freeze) - ln(mvd)) / ln(sigma_g)),
 * Phi the standard normal distribution function (GSL's gsl_cdf_ugaussian_P).
 * A class of diameter d_k stands for the diameters between the geometric means
 * of d_k and its neighbours; the outer classes reach the ends of the range
 * (dmin x freeze, dmax x freeze). Every function takes const inputs and returns
 * 0 or SWE_EINVAL with a one-line message in err (when err is given). */
#ifndef SWE_SPRAY_H
#define SWE_SPRAY_H

#include <stddef.h>

enum { SWE_EINVAL = 1, SWE_ENOMEM = 2, SWE_EIO = 3 };

typedef struct {
    double mvd;     /* median volume diameter of the droplets [um], in [0.1, 1000] */
    double sigma_g; /* geometric standard deviation, in (1, 10] */
    double dmin;    /* droplet diameters dmin .. dmax [um], 0 < dmin < dmax <= 10000 */
    double dmax;
    double freeze;  /* ice diameter / droplet diameter, in [0.5, 2] */
} swe_spray;

/* the tunnel's spray: MVD 20 um, sigma_g 1.8, 2 .. 150 um, freeze 1.03 */
void swe_spray_default(swe_spray *s);
/* 0, or SWE_EINVAL naming the first setting outside its range */
int swe_spray_check(const swe_spray *s, char *err, size_t errlen);
/* F(x): the spray's (untruncated) mass fraction below the ice diameter x > 0 */
double swe_spray_cdf(const swe_spray *s, double x);
/* the mass density of the ice diameter x (in m, as OpenFOAM's general
   distribution reads it; 1/m x 1e-6): the log-normal of median mvd x freeze */
double swe_spray_density(const swe_spray *s, double x_m);

/* the classes d[0] < d[1] < ... < d[n-1] (ice diameters, um): their edges
   e0[k], e1[k] and mass shares w[k] of the truncated spray (summing to 1) */
int swe_spray_classes(const swe_spray *s, const double *d, size_t n, double *w, double *e0,
                      double *e1, char *err, size_t errlen);

/* the mass median diameter of the truncated spray: F(x) = (F(lo) + F(hi)) / 2 */
int swe_spray_median(const swe_spray *s, double *x, char *err, size_t errlen);

/* the mass median diameter of a deposit composed from the classes: class k
   (edges e0[k], e1[k], share w[k]) captures the fraction c[k] of its mass,
   the same across the class, the spray log-normal within it; the root of
   G(x) = G(hi) / 2 with G(x) = sum_k c_k w_k (F(min(x, e1)) - F(e0)) /
   (F(e1) - F(e0)). SWE_EINVAL when nothing is captured. */
int swe_deposit_median(const swe_spray *s, const double *e0, const double *e1, const double *w,
                       const double *c, size_t n, double *x, char *err, size_t errlen);

#endif
