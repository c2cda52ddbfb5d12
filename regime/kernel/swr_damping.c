/* swr_damping.c - COR-calibrated Hertz dashpot (see swr_damping.h). */
#include "swr_damping.h"

#include <math.h>
#include <pthread.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_roots.h>

#include "swp_cor.h"

static const double BETA = 1.3693063937629153; /* sqrt(15/8) */

/* -x'' of the dimensionless impact: Hertz, plus the dashpot while loading
 * (both: whatever the direction). */
static double decel(double x, double v, double alpha, int both)
{
    if (x <= 0.0)
        return 0.0;
    const double s = sqrt(x);
    return 1.25 * x * s + (v > 0.0 || both ? BETA * alpha * sqrt(s) * v : 0.0);
}

/* One classical RK4 step of the dimensionless impact. */
static void rk4(double x, double v, double h, double alpha, int both, double *xn, double *vn)
{
    const double k1x = v, k1v = -decel(x, v, alpha, both);
    const double k2x = v + 0.5 * h * k1v, k2v = -decel(x + 0.5 * h * k1x, k2x, alpha, both);
    const double k3x = v + 0.5 * h * k2v, k3v = -decel(x + 0.5 * h * k2x, k3x, alpha, both);
    const double k4x = v + h * k3v, k4v = -decel(x + h * k3x, k4x, alpha, both);
    *xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    *vn = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

/* COR and loading time (turning point, in units of delta_H / v).
 * Classical RK4 through the loading phase; the unloading is elastic, so the
 * rebound energy is the Hertz energy at the turning point:
 * e^2 = x_max^(5/2) (energy 1/2 at first contact, U = x^(5/2)/2).
 * The x^(1/4) of the dashpot is singular at first contact: the run starts at
 * t0 from the series x = t - (16/45) b t^(9/4), x' = 1 - (4/5) b t^(5/4)
 * (b = sqrt(15/8) alpha; the Hertz term is O(t^(5/2))) and the step grows
 * geometrically (h <= t/8) up to H_MAX / (1 + alpha/4), the loading getting
 * short with strong damping. */
#define H_MAX 1.0e-3
static double cor_and_time(double alpha, double *t_load)
{
    const double b = BETA * alpha, hmax = H_MAX / (1.0 + 0.25 * alpha);
    double t = 1e-7 * hmax;
    double x = t - (16.0 / 45.0) * b * pow(t, 2.25), v = 1.0 - 0.8 * b * pow(t, 1.25);
    for (long i = 0; i < 100000000L; i++) {
        const double h = t / 8.0 < hmax ? t / 8.0 : hmax;
        double xn, vn;
        rk4(x, v, h, alpha, 0, &xn, &vn);
        if (vn <= 0.0) {
            /* turning point inside this step: cubic Hermite in time through
             * (x, v) and (xn, vn), maximum where its derivative vanishes */
            const double f = v / (v - vn);            /* linear estimate of the root */
            double tau = f;
            for (int it = 0; it < 20; it++) {         /* Newton on the Hermite derivative */
                const double t2 = tau * tau;
                const double dp = (6.0 * t2 - 6.0 * tau) * (x - xn) / h
                                + (3.0 * t2 - 4.0 * tau + 1.0) * v + (3.0 * t2 - 2.0 * tau) * vn;
                const double ddp = (12.0 * tau - 6.0) * (x - xn) / h
                                 + (6.0 * tau - 4.0) * v + (6.0 * tau - 2.0) * vn;
                if (ddp == 0.0)
                    break;
                const double step = dp / ddp;
                tau -= step;
                if (fabs(step) < 1e-14)
                    break;
            }
            if (!(tau >= 0.0 && tau <= 1.0))
                tau = f;
            const double t2 = tau * tau, t3 = t2 * tau;
            const double xm = (2.0 * t3 - 3.0 * t2 + 1.0) * x + (t3 - 2.0 * t2 + tau) * h * v
                            + (-2.0 * t3 + 3.0 * t2) * xn + (t3 - t2) * h * vn;
            *t_load = t + tau * h;
            return pow(xm, 1.25);
        }
        x = xn;
        v = vn;
        t += h;
    }
    *t_load = INFINITY;
    return 0.0;
}

/* COR of the dimensionless Hertz impact with the dashpot acting on both
 * branches (loading and unloading, x > 0): RK4 through the whole contact on
 * the same graded mesh, to the exit x = 0 (linear interpolation of the
 * speed there). A strongly damped contact creeps out (the dashpot, ~x^(1/4),
 * outweighs the spring, ~x^(3/2), near the exit; e falls below 1e-3 at
 * alpha = 1.6): the run stops after 100 Hertz times with the speed it has
 * then. */
static double cor_both(double alpha)
{
    const double b = BETA * alpha, hmax = H_MAX / (1.0 + 0.25 * alpha);
    double t = 1e-7 * hmax;
    double x = t - (16.0 / 45.0) * b * pow(t, 2.25), v = 1.0 - 0.8 * b * pow(t, 1.25);
    while (t < 1e2) {
        const double h = t / 8.0 < hmax ? t / 8.0 : hmax;
        double xn, vn;
        rk4(x, v, h, alpha, 1, &xn, &vn);
        if (xn <= 0.0 && vn < 0.0)
            return -(v + (vn - v) * x / (x - xn));
        x = xn;
        v = vn;
        t += h;
    }
    return v < 0.0 ? -v : 0.0;
}

double swr_damping_cor_both(double alpha)
{
    return alpha > 0.0 ? cor_both(alpha) : 1.0;
}

double swr_damping_cor(double alpha)
{
    double t;
    return cor_and_time(alpha > 0.0 ? alpha : 0.0, &t);
}

/* Table: alpha over y = -ln e, monotone (Steffen) interpolation. */
#define NTAB 161
#define ALPHA_MAX 2000.0
static double tab_y[NTAB], tab_alpha[NTAB], tab_g[NTAB];
static gsl_interp *tab_interp, *tab_ginterp;
static int tab_ok;
static pthread_once_t tab_once = PTHREAD_ONCE_INIT;

static void build_table(void)
{
    /* alpha = 0, then geometric from 1e-3 to ALPHA_MAX */
    tab_alpha[0] = 0.0;
    tab_y[0] = 0.0;
    double t0;
    cor_and_time(0.0, &t0);
    tab_g[0] = 1.0;
    const double r = pow(ALPHA_MAX / 1e-3, 1.0 / (NTAB - 2));
    double a = 1e-3;
    for (int i = 1; i < NTAB; i++, a *= r) {
        tab_alpha[i] = i == NTAB - 1 ? ALPHA_MAX : a;
        double ti;
        tab_y[i] = -log(cor_and_time(tab_alpha[i], &ti));
        tab_g[i] = ti / t0;
        if (!(tab_y[i] > tab_y[i - 1]))
            return; /* not monotone: leave tab_ok = 0 */
    }
    tab_interp = gsl_interp_alloc(gsl_interp_steffen, NTAB);
    tab_ginterp = gsl_interp_alloc(gsl_interp_steffen, NTAB);
    if (tab_interp && gsl_interp_init(tab_interp, tab_y, tab_alpha, NTAB) == GSL_SUCCESS
        && tab_ginterp && gsl_interp_init(tab_ginterp, tab_alpha, tab_g, NTAB) == GSL_SUCCESS)
        tab_ok = 1;
}

int swr_damping_init(void)
{
    pthread_once(&tab_once, build_table);
    return tab_ok ? 0 : -1;
}

double swr_damping_e_min(void)
{
    swr_damping_init();
    return exp(-tab_y[NTAB - 1]);
}

/* alpha for e from a table of alpha over y = -ln e (n points, built): e >= 1
 * gives 0, an e below the table its largest alpha. */
static double table_alpha(const gsl_interp *in, const double *ty, const double *ta, int n,
                          double e)
{
    const double y = -log(e);
    if (y >= ty[n - 1])
        return ta[n - 1];
    return gsl_interp_eval(in, ty, ta, y, NULL);
}

double swr_damping_alpha(double e)
{
    if (!(e < 1.0))
        return 0.0;
    if (swr_damping_init() != 0)
        return NAN;
    return table_alpha(tab_interp, tab_y, tab_alpha, NTAB, e);
}

double swr_damping_time_factor(double alpha)
{
    if (!(alpha > 0.0))
        return 1.0;
    if (swr_damping_init() != 0)
        return 1.0;
    if (alpha >= ALPHA_MAX)
        return tab_g[NTAB - 1];
    return gsl_interp_eval(tab_ginterp, tab_alpha, tab_g, alpha, NULL);
}

/* Table for the dashpot acting on both branches: alpha over -ln e up to
 * e = 1e-3 (alpha about 1.6; beyond, the contact creeps out). */
#define NTAB_B 121
static double tabb_y[NTAB_B], tabb_alpha[NTAB_B];
static int tabb_n;
static gsl_interp *tabb_interp;
static pthread_once_t tabb_once = PTHREAD_ONCE_INIT;

static void build_table_both(void)
{
    tabb_alpha[0] = 0.0;
    tabb_y[0] = 0.0;
    const double r = pow(2.0 / 1e-3, 1.0 / (NTAB_B - 2));
    double a = 1e-3;
    int n = 1;
    for (int i = 1; i < NTAB_B; i++, a *= r) {
        const double e = cor_both(a);
        if (!(e > 0.0) || !(-log(e) > tabb_y[n - 1]))
            break;
        tabb_alpha[n] = a;
        tabb_y[n] = -log(e);
        n++;
        if (e < 1e-3)
            break;
    }
    tabb_interp = gsl_interp_alloc(gsl_interp_steffen, (size_t)n);
    if (n >= 3 && tabb_interp
        && gsl_interp_init(tabb_interp, tabb_y, tabb_alpha, (size_t)n) == GSL_SUCCESS)
        tabb_n = n;
}

double swr_damping_alpha_both(double e)
{
    if (!(e < 1.0))
        return 0.0;
    pthread_once(&tabb_once, build_table_both);
    if (tabb_n == 0)
        return NAN;
    return table_alpha(tabb_interp, tabb_y, tabb_alpha, tabb_n, e);
}

double swr_damping_e_min_both(void)
{
    pthread_once(&tabb_once, build_table_both);
    return tabb_n ? exp(-tabb_y[tabb_n - 1]) : 1.0;
}

static double cor_minus(double alpha, void *params)
{
    return swr_damping_cor(alpha) - *(const double *)params;
}

double swr_damping_alpha_exact(double e)
{
    if (!(e < 1.0))
        return 0.0;
    double a = swr_damping_alpha(e);
    if (!(a > 0.0) || a >= ALPHA_MAX)
        return a;
    /* bracket around the table value (the table is accurate to ~1e-5) */
    double lo = 0.97 * a, hi = 1.03 * a + 1e-9;
    /* the bracket must straddle the root (GSL's default handler aborts) */
    if (cor_minus(lo, &e) < 0.0 || cor_minus(hi, &e) > 0.0)
        return a;
    gsl_function F = { cor_minus, &e };
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return a;
    if (gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 60; it++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS)
                break;
            lo = gsl_root_fsolver_x_lower(s);
            hi = gsl_root_fsolver_x_upper(s);
            if (gsl_root_test_interval(lo, hi, 0.0, 1e-10) == GSL_SUCCESS)
                break;
        }
        a = gsl_root_fsolver_root(s);
    }
    gsl_root_fsolver_free(s);
    return a;
}

double swr_damping_target(const swr_params *p, double Estar, double R, double m, double vi)
{
    const double py = swp_limiting_pressure(p->sigma_y);
    double vy;
    switch (p->cor) {
    case SWR_COR_ELASTIC:
        return 1.0;
    case SWR_COR_CONSTANT:
        return p->cor_value;
    case SWR_COR_THORNTON_NING:
        /* no dashpot; the COR the contact law gives without adhesion */
        return swp_cor_thornton(swp_yield_velocity_wall(py, Estar, p->rho) / vi);
    case SWR_COR_THORNTON:
        vy = p->cor_pair == SWR_PAIR_PARTICLE
           ? swp_yield_velocity_pp(py, Estar, 0.5 * R, 0.5 * m)
           : swp_yield_velocity_wall(py, Estar, p->rho);
        return swp_cor_thornton(vy / vi);
    case SWR_COR_THORNTON_ASYMPTOTE:
        if (p->cor_pair == SWR_PAIR_PARTICLE)
            return swp_cor_thornton_pp_asymptote(swp_yield_velocity_pp(py, Estar, 0.5 * R, 0.5 * m) / vi);
        return swp_cor_thornton_wall_asymptote(py, Estar, p->rho, vi);
    }
    return 1.0;
}

double swr_damping_alpha_for(const swr_params *p, double alpha_const, double e)
{
    return p->dashpot == SWR_DASHPOT_BOTH ? swr_damping_alpha_both(e)
         : p->cor == SWR_COR_CONSTANT ? alpha_const
                                      : swr_damping_alpha(e);
}
