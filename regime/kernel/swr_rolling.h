/* swr_rolling.h - rolling resistance of an adhesive contact (Dominik &
 * Tielens 1995; Marshall 2009).
 *
 * The rolling displacement xi_r of a sphere on a wall grows at the rolling
 * velocity v_r = -R omega (omega with the sign of swr_impact: positive spin
 * makes the contact point slide along +v_t, so pure forward rolling has
 * omega = -v_t/R). The contact resists with the moment M = k_r xi_r,
 * k_r = 4 F_c (a/a0)^(3/2), up to the critical rolling displacement xi_crit;
 * beyond it the contact rolls irreversibly at the constant moment
 * k_r xi_crit, dissipating M per unit rolling angle. The moment on the
 * particle is +k_r xi_r (it decelerates v_r). A non-adhesive contact has no
 * rolling resistance (F_c = 0).
 *
 * Twisting resistance is not modelled: a sphere hitting a flat wall with no
 * spin about the wall normal never acquires one (no force or moment of the
 * model has a component about the normal), so it would never act.
 */
#ifndef SWR_ROLLING_H
#define SWR_ROLLING_H

#include <math.h>

typedef struct {
    double xi;      /* rolling displacement held by the contact, |xi| <= xi_crit */
    int rolling;    /* 1 while at the limit moment (irreversible rolling) */
    double w_roll;  /* energy dissipated by irreversible rolling */
} swr_rolling;

/* Advance by the rolling increment dxi with stiffness kr and critical
 * displacement xi_crit; returns the resisting moment on the particle. */
static inline double swr_rolling_update(swr_rolling *s, double dxi, double kr, double xi_crit)
{
    s->xi += dxi;
    if (fabs(s->xi) > xi_crit) {
        const double xn = copysign(xi_crit, s->xi);
        s->w_roll += 0.5 * kr * (s->xi * s->xi - xn * xn);
        s->xi = xn;
        s->rolling = 1;
    } else {
        s->rolling = 0;
    }
    return kr * s->xi;
}

#endif
