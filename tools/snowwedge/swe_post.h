/* swe_post.h - the per-run post-processing of the wind-tunnel wedge
 * (tutorials/wedge/post): readers of the OpenFOAM tables a run writes
 * (surfaceFieldValue.dat, the wall model's snowWall.dat and reasons.dat, raw
 * surface files, Lagrangian .post records, the solver log) and the numbers
 * made from them: the deposit per patch, the mass balance, the halves of the
 * sampling window, the Stokes number of the wake, the fill of the wake.
 *
 * Every reader returns 0, 1 for a file it cannot read, 2 for a file that
 * lacks what was asked (err then holds one line naming file and value). */
#ifndef SWE_POST_H
#define SWE_POST_H

#include <stddef.h>

/* the wake of the wedge: free stream U [m/s], height H [m]; ice density
   [kg/m3] and air viscosity [Pa s] of the Stokes number */
#define SWE_POST_SPEED 19.444
#define SWE_POST_HEIGHT 0.12
#define SWE_POST_RHO_ICE 920.0
#define SWE_POST_MU_AIR 1.641e-5
/* pi as the post scripts wrote it (to 15 digits), so that masses of
   nParticle rho pi d^3 / 6 keep their last digits */
#define SWE_POST_PI 3.14159265358979

/* a number as a shell table passes it on: an integral value as it is, any
   other rounded to 6 significant digits (awk's "%s" of a number) */
double swe_post_awk_str(double v);
/* v rounded to `digits` significant digits (printf "%.Ng" and read back) */
double swe_post_round(double v, int digits);
/* |a - t| <= 1e-9 + 1e-6 t: a written time equal to t */
int swe_post_same_time(double a, double t);

/* Times t are given as written ("0.4"), or "last": the last row or folder. */
/* column `col` of a surfaceFieldValue.dat (header "# Time ...") at time t,
   rounded to 10 significant digits */
int swe_post_field_at(const char *path, const char *col, const char *t, double *v, char *err,
                      size_t nerr);
/* "# Area : A" of a surfaceFieldValue.dat (0 when absent) */
int swe_post_area(const char *path, double *area);
/* the wall model's counts of `patch` in snowWall.dat: impacts, sticks,
   bounces, rip-offs, deposited mass (as swe_post_awk_str), of the row
   nearest to t; a missing column reads 0 */
int swe_post_counts_at(const char *path, const char *patch, const char *t, double c[5],
                       char *err, size_t nerr);
/* the time folder of `parent` that holds `file` at time t (the latest one
   holding it for "last"); "" when none */
int swe_post_time_dir(const char *parent, const char *file, const char *t, char *dir,
                      size_t ndir);
/* reasons.dat's line of `patch`: stuck, criterion, tangential, shear, probability */
int swe_post_reasons(const char *path, const char *patch, long r[5], char *err, size_t nerr);

/* the faces of a raw surface file (x y z value per line) */
typedef struct {
    double *y, *z, *v;
    size_t n;
} swe_post_raw;
int swe_post_raw_read(const char *path, swe_post_raw *r, char *err, size_t nerr);
void swe_post_raw_free(swe_post_raw *r);

/* the cloud's totals in the solver log: injected mass [kg] and parcels
   (its last report, injectors summed), airborne mass, and whether
   parcelSplitting split its parcels */
typedef struct {
    double injected, airborne;
    long parcels;
    int split;
} swe_post_log;
int swe_post_log_read(const char *path, const char *cloud, swe_post_log *l, char *err, size_t nerr);

/* the mass nParticle rho pi d^3 / 6 of the parcels in Lagrangian .post
   files (columns named by the header lines) */
int swe_post_post_mass(const char *const *files, int nfiles, double *mass, char *err, size_t nerr);

/* the convergence row of a patch from its counts at T0, TH, T1 */
typedef struct {
    double impacts, sticks; /* over the window */
    double window, half1, half2; /* deposits [kg], the halves x2 */
} swe_post_halves_t;
void swe_post_halves(const double c0[5], const double ch[5], const double c1[5],
                     swe_post_halves_t *h);
/* relative difference of the halves [%] about their mean; NAN when both are 0 */
double swe_post_halves_diff(const swe_post_halves_t *h);
/* Poisson error of the window's sticks [%] 100 / sqrt(sticks); INFINITY at 0 */
double swe_post_poisson(double sticks);

/* the Stokes number of the wake, tau_p U / H with tau_p = rho d^2 / (18 mu) */
double swe_post_stokes(double d_um);

/* the fill of the wake from rear-face impact records of a spray switched on
   at soi, over the window t0 .. t1 (ages binned in 1 ms, de-censored) */
typedef struct {
    double t, age, mass;
} swe_post_rec;
typedef struct {
    long n;              /* records in the window */
    double mass;         /* their mass */
    double a50, aF;      /* ages below which 1/2 and F of r_inf arrive [s] */
    double amax;         /* the oldest [s] */
    double fill, fill1, fill2; /* window, first half, second half */
} swe_post_fill_t;
int swe_post_fill(const swe_post_rec *r, size_t n, double soi, double t0, double t1, double F,
                  swe_post_fill_t *out);

#endif
