/* swp_time.c - contact time scales (see swp_time.h). */
#include "swp_time.h"

#include <math.h>

double swp_hertz_contact_time(double mstar, double Rstar, double Estar, double v)
{
    return 2.87 * pow(mstar * mstar / (Rstar * Estar * Estar * v), 0.2);
}

double swp_rayleigh_time(double R, double rho, double G, double nu)
{
    return M_PI * R * sqrt(rho / G) / (0.1631 * nu + 0.8766);
}
