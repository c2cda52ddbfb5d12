/* swp_plastic.c - Thornton & Ning adhesive elastic-plastic contact formulas
 * (see swp_plastic.h). */
#include "swp_plastic.h"

#include <math.h>

double swp_plastic_centre_pressure(double a, double Gamma, double Estar, double Rstar)
{
    return 2.0 * Estar * a / (M_PI * Rstar) - sqrt(2.0 * Gamma * Estar / (M_PI * a));
}

double swp_plastic_yield_radius(double p_y, double Gamma, double Estar, double Rstar)
{
    if (!(p_y > 0.0 && Estar > 0.0 && Rstar > 0.0 && Gamma >= 0.0))
        return NAN;
    const double aH = M_PI * Rstar * p_y / (2.0 * Estar);
    if (Gamma == 0.0)
        return aH;
    /* f(a) = p(0) - p_y is increasing; f(aH) < 0. Bracket [aH, hi]. */
    double lo = aH, hi = 2.0 * aH;
    for (int i = 0; i < 2000 && swp_plastic_centre_pressure(hi, Gamma, Estar, Rstar) < p_y; i++)
        hi *= 2.0;
    double a = hi;
    for (int i = 0; i < 200; i++) {
        const double f = swp_plastic_centre_pressure(a, Gamma, Estar, Rstar) - p_y;
        if (f > 0.0)
            hi = a;
        else
            lo = a;
        const double fp = 2.0 * Estar / (M_PI * Rstar)
                        + 0.5 * sqrt(2.0 * Gamma * Estar / M_PI) * pow(a, -1.5);
        double an = a - f / fp;
        if (!(an > lo && an < hi))
            an = 0.5 * (lo + hi);
        if (fabs(an - a) <= 1e-14 * a)
            return an;
        a = an;
    }
    return a;
}

double swp_plastic_unload_radius(double a_star, double F_star, double Gamma, double Estar)
{
    const double a3 = a_star * a_star * a_star;
    return 4.0 * Estar * a3 / (3.0 * (F_star + sqrt(8.0 * M_PI * Gamma * Estar * a3)));
}

double swp_plastic_stiffness(double p_y, double Rstar)
{
    return M_PI * p_y * Rstar;
}
