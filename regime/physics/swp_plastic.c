/* swp_plastic.c - Thornton & Ning adhesive elastic-plastic contact formulas
 * (see swp_plastic.h). */
#include "swp_plastic.h"

#include <math.h>

#include "swp_root.h"

double swp_plastic_centre_pressure(double a, double Gamma, double Estar, double Rstar)
{
    return 2.0 * Estar * a / (M_PI * Rstar) - sqrt(2.0 * Gamma * Estar / (M_PI * a));
}

typedef struct {
    double p_y, Gamma, Estar, Rstar;
} yield_ctx;

/* centre pressure - p_y and its derivative in a */
static double yield_f(double a, void *ctx, double *dfdx)
{
    const yield_ctx *c = ctx;
    if (dfdx)
        *dfdx = 2.0 * c->Estar / (M_PI * c->Rstar)
              + 0.5 * sqrt(2.0 * c->Gamma * c->Estar / M_PI) * pow(a, -1.5);
    return swp_plastic_centre_pressure(a, c->Gamma, c->Estar, c->Rstar) - c->p_y;
}

double swp_plastic_yield_radius(double p_y, double Gamma, double Estar, double Rstar)
{
    if (!(p_y > 0.0 && Estar > 0.0 && Rstar > 0.0 && Gamma >= 0.0))
        return NAN;
    const double aH = M_PI * Rstar * p_y / (2.0 * Estar);
    if (Gamma == 0.0)
        return aH;
    /* f(a) = p(0) - p_y is increasing; f(aH) < 0 */
    const yield_ctx c = { p_y, Gamma, Estar, Rstar };
    return swp_root_increasing(yield_f, (void *)&c, aH, 2.0 * aH, 2000, 1e-14, 200);
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
