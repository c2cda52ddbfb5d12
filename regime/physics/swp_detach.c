/* swp_detach.c - shear detachment of an adhered sphere (see swp_detach.h). */
#include "swp_detach.h"
#include "swp_contact.h"

#include <math.h>

double swp_shear_drag(double tau_w, double R)
{
    return SWP_ONEILL_DRAG * 6.0 * M_PI * tau_w * R * R;
}

double swp_shear_torque(double tau_w, double R)
{
    return SWP_ONEILL_TORQUE * 4.0 * M_PI * tau_w * R * R * R;
}

double swp_shear_moment(double tau_w, double R)
{
    return swp_shear_drag(tau_w, R) * R + swp_shear_torque(tau_w, R);
}

double swp_tau_roll(double Gamma, double Estar, double R, double k)
{
    const double resist = k * swp_jkr_pulloff_force(Gamma, R) * swp_jkr_a0(Gamma, Estar, R);
    return resist / swp_shear_moment(1.0, R); /* moment is linear in tau_w */
}

double swp_tau_slide(double Gamma, double R, double mu_s, double k)
{
    return mu_s * k * swp_jkr_pulloff_force(Gamma, R) / swp_shear_drag(1.0, R);
}

double swp_tau_detach(double Gamma, double Estar, double R, double mu_s, double k)
{
    const double roll = swp_tau_roll(Gamma, Estar, R, k);
    if (isnan(mu_s) || mu_s <= 0.0) /* NaN tested, not compared (FE_INVALID) */
        return roll;
    const double slide = swp_tau_slide(Gamma, R, mu_s, k);
    return slide < roll ? slide : roll;
}
