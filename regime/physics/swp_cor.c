/* swp_cor.c - coefficient of restitution models (see swp_cor.h). */
#include "swp_cor.h"

#include <math.h>

double swp_limiting_pressure(double sigma_y)
{
    return 2.5 * sigma_y;
}

double swp_yield_velocity_wall(double p_y, double Estar, double rho)
{
    return 1.56 * sqrt(pow(p_y, 5.0) / (pow(Estar, 4.0) * rho));
}

double swp_yield_velocity_pp(double p_y, double Estar, double Rstar, double mstar)
{
    return 3.194 * sqrt(pow(p_y, 5.0) * pow(Rstar, 3.0) / (pow(Estar, 4.0) * mstar));
}

double swp_cor_thornton(double x)
{
    if (isnan(x)) /* tested first: comparing a NaN raises FE_INVALID (trapped) */
        return NAN;
    if (x >= 1.0) /* V_i <= V_y: no plastic loss claimed */
        return 1.0;
    if (x <= 0.0)
        return 0.0;
    const double pre = sqrt(6.0 * sqrt(3.0) / 5.0);
    const double e = pre * sqrt(1.0 - x * x / 6.0)
                   * pow(x / (x + 2.0 * sqrt(6.0 / 5.0 - x * x / 5.0)), 0.25);
    return e > 1.0 ? 1.0 : e;
}

double swp_cor_thornton_wall_asymptote(double p_y, double Estar, double rho, double v_i)
{
    const double e = 1.324 * pow(pow(p_y, 5.0) / (pow(Estar, 4.0) * rho), 0.125) * pow(v_i, -0.25);
    return e > 1.0 ? 1.0 : e;
}

double swp_cor_thornton_pp_asymptote(double x)
{
    const double e = 1.185 * pow(x, 0.25);
    return e > 1.0 ? 1.0 : e;
}

double swp_cor_combine(double e_p, double e_a)
{
    const double e2 = 1.0 - ((1.0 - e_p * e_p) + (1.0 - e_a * e_a));
    return e2 > 0.0 ? sqrt(e2) : 0.0;
}
