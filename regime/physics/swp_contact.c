/* swp_contact.c - closed forms of Hertz and JKR contact mechanics (see swp_contact.h). */
#include "swp_contact.h"

#include <math.h>

double swp_effective_modulus(double E1, double nu1, double E2, double nu2)
{
    return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

double swp_effective_radius(double R1, double R2)
{
    return isinf(R2) ? R1 : 1.0 / (1.0 / R1 + 1.0 / R2);
}

double swp_effective_mass(double m1, double m2)
{
    return isinf(m2) ? m1 : m1 * m2 / (m1 + m2);
}

double swp_shear_modulus(double E, double nu)
{
    return E / (2.0 * (1.0 + nu));
}

double swp_hertz_force(double Estar, double Rstar, double delta)
{
    return delta > 0.0 ? (4.0 / 3.0) * Estar * sqrt(Rstar) * delta * sqrt(delta) : 0.0;
}

double swp_hertz_energy(double Estar, double Rstar, double delta)
{
    return delta > 0.0 ? (8.0 / 15.0) * Estar * sqrt(Rstar) * delta * delta * sqrt(delta) : 0.0;
}

double swp_jkr_delta(double a, double Gamma, double Estar, double Rstar)
{
    return a * a / Rstar - sqrt(2.0 * M_PI * Gamma * a / Estar);
}

double swp_jkr_force(double a, double Gamma, double Estar, double Rstar)
{
    return 4.0 * Estar * a * a * a / (3.0 * Rstar) - sqrt(8.0 * M_PI * Gamma * Estar * a * a * a);
}

double swp_jkr_a0(double Gamma, double Estar, double Rstar)
{
    return cbrt(9.0 * M_PI * Gamma * Rstar * Rstar / (2.0 * Estar));
}

double swp_jkr_pulloff_force(double Gamma, double Rstar)
{
    return 1.5 * M_PI * Gamma * Rstar;
}

double swp_jkr_af(double Gamma, double Estar, double Rstar)
{
    return swp_jkr_a0(Gamma, Estar, Rstar) / pow(6.0, 2.0 / 3.0);
}

double swp_jkr_delta_c(double Gamma, double Estar, double Rstar)
{
    const double af = swp_jkr_af(Gamma, Estar, Rstar);
    return -3.0 * af * af / Rstar;
}

double swp_tabor(double Gamma, double Estar, double Rstar, double z0)
{
    return cbrt(Rstar * Gamma * Gamma / (Estar * Estar * z0 * z0 * z0));
}

double swp_sticking_velocity_tn(double Gamma, double rho, double Estar, double Rstar)
{
    const double g5 = pow(Gamma, 5.0), r5 = pow(Rstar, 5.0);
    return 1.84 * pow(g5 / (rho * rho * rho * Estar * Estar * r5), 1.0 / 6.0);
}
