/* swp_nearwall.c - the turbulent wall layer in wall units (see swp_nearwall.h). */
#include "swp_nearwall.h"

#include <math.h>
#include <stddef.h>

/* wall-normal rms fit v'+ = A y^2 / (1 + B y^P) (Guha 1997) */
#define V_A 0.005
#define V_B 0.002923
#define V_P 2.128

#define WOOD_PLATEAU 0.13
#define KBOLTZMANN 1.380649e-23

/* quiet tests (no floating-point trap on a NaN) */
static int bad(double yplus)
{
    return !isfinite(yplus) || yplus < 0.0;
}

/* The three rms fits, each a y^m / (1 + b y^p): u' and w' (Kallio & Reeks
   1989), v' (Guha 1997). */
static const struct {
    double a, b, p;
    int m;
} fits[3] = {
    { 0.4, 0.0239, 1.496, 1 },
    { V_A, V_B, V_P, 2 },
    { 0.19, 0.0361, 1.21, 1 },
};

/* fit i at y+ (NaN for a bad y+) and, when slope is given, its derivative
   a y^(m-1) (m (1 + b y^p) - p b y^p) / (1 + b y^p)^2: one pow for both */
static double fit(int i, double yplus, double *slope)
{
    if (bad(yplus)) {
        if (slope)
            *slope = NAN;
        return NAN;
    }
    const double bp = fits[i].b * pow(yplus, fits[i].p);
    const double den = 1.0 + bp;
    const double ym1 = fits[i].m == 2 ? yplus : 1.0;   /* y^(m-1) */
    if (slope)
        *slope = fits[i].a * ym1 * (fits[i].m * den - fits[i].p * bp) / (den * den);
    return fits[i].a * (fits[i].m == 2 ? yplus * yplus : yplus) / den;
}

double swp_urms_plus(double yplus)
{
    return fit(0, yplus, NULL);
}

double swp_vrms_plus(double yplus)
{
    return fit(1, yplus, NULL);
}

double swp_wrms_plus(double yplus)
{
    return fit(2, yplus, NULL);
}

double swp_durms_plus(double yplus)
{
    double d;
    fit(0, yplus, &d);
    return d;
}

double swp_dvrms_plus(double yplus)
{
    double d;
    fit(1, yplus, &d);
    return d;
}

double swp_dwrms_plus(double yplus)
{
    double d;
    fit(2, yplus, &d);
    return d;
}

void swp_rms_plus(double yplus, double rms[3], double slope[3])
{
    for (int i = 0; i < 3; i++)
        rms[i] = fit(i, yplus, slope ? &slope[i] : NULL);
}

double swp_tl_plus(double yplus)
{
    if (bad(yplus))
        return NAN;
    if (yplus < 5.0)
        return 10.0;
    const double y = yplus < 200.0 ? yplus : 200.0;
    return 7.122 + 0.5731 * y - 0.00129 * y * y;
}

double swp_uplus(double yplus)
{
    if (bad(yplus))
        return NAN;
    const double y = yplus;
    return log1p(SWP_KARMAN * y) / SWP_KARMAN
        + 7.8 * (1.0 - exp(-y / 11.0) - (y / 11.0) * exp(-y / 3.0));
}

double swp_duplus(double yplus)
{
    if (bad(yplus))
        return NAN;
    const double y = yplus;
    return 1.0 / (1.0 + SWP_KARMAN * y)
        + 7.8 * (exp(-y / 11.0) / 11.0 - exp(-y / 3.0) / 11.0 + y / 33.0 * exp(-y / 3.0));
}

static int positive(double x)
{
    return isfinite(x) && x > 0.0;
}

double swp_tau_p(double rho_p, double d, double mu, double re)
{
    if (!positive(rho_p) || !positive(d) || !positive(mu) || !isfinite(re) || re < 0.0)
        return NAN;
    return rho_p * d * d / (18.0 * mu) / (1.0 + 0.15 * pow(re, 0.687));
}

double swp_tau_plus(double rho_p, double d, double mu, double nu, double u_tau)
{
    if (!positive(nu) || !positive(u_tau))
        return NAN;
    return swp_tau_p(rho_p, d, mu, 0.0) * u_tau * u_tau / nu;
}

double swp_d_of_tau_plus(double tau_plus, double rho_p, double mu, double nu, double u_tau)
{
    if (!positive(tau_plus) || !positive(rho_p) || !positive(mu) || !positive(nu)
        || !positive(u_tau))
        return NAN;
    return sqrt(18.0 * mu * tau_plus * nu / (rho_p * u_tau * u_tau));
}

double swp_wood_vplus(double tau_plus, double sc)
{
    if (!isgreaterequal(tau_plus, 0.0))
        return NAN;
    const double turb = 4.5e-4 * tau_plus * tau_plus;
    const double brown = positive(sc) ? 0.057 * pow(sc, -2.0 / 3.0) : 0.0;
    return brown + (turb < WOOD_PLATEAU ? turb : WOOD_PLATEAU);
}

double swp_brownian_diffusivity(double d, double T, double mu, double lambda)
{
    if (!positive(d) || !positive(T) || !positive(mu) || !positive(lambda))
        return NAN;
    const double kn = 2.0 * lambda / d;
    const double cc = 1.0 + kn * (1.257 + 0.4 * exp(-1.1 / kn));
    return KBOLTZMANN * T * cc / (3.0 * M_PI * mu * d);
}
