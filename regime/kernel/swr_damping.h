/* swr_damping.h - normal damping sub-model: a dashpot set from a coefficient
 * of restitution (COR).
 *
 * Dashpot of the Hertz tangent-stiffness form
 *     F_d = alpha sqrt(m* k_t(delta)) d delta/dt,   k_t = 2 E* sqrt(R* delta),
 * acting while the contact is loaded (delta > 0 and approaching) and not
 * while it unloads. This is Thornton's (1997) picture of an elastic-plastic
 * impact: the loss is plastic work done while loading, the unloading is
 * elastic. For a Hertz contact the dashpot gives a COR that depends on alpha
 * only, not on the velocity or the size: in units of the Hertz overlap
 * delta_H and of delta_H / v the loading is
 *     x'' = -(5/4) x^(3/2) - sqrt(15/8) alpha x^(1/4) x',  x(0) = 0, x'(0) = 1,
 * and since the unloading is elastic e = x_max^(5/4). The usual closed form
 * alpha(e) is only approximate for it; swr_damping_cor() solves this ODE, a
 * table of alpha over ln e built once per process gives alpha(e) to about
 * 1e-6 in e, and a GSL root finder refines one alpha (swr_damping_alpha_exact).
 *
 * With JKR adhesion the same dashpot acts while loading; unloading and the
 * necking phase (delta < 0, tensile) are undamped, so the adhesive hysteresis
 * loss (the energy U(a_f) left at the separation) adds to the plastic loss,
 * as Thornton & Ning (1998) combine them: for v >> V_s,
 * e_n^2 = e_p^2 - U_c/(m v^2/2), i.e. 1 - e_n^2 = (1 - e_p^2) + (1 - e_a^2).
 * A dashpot that also acts while unloading breaks this: it cancels the
 * elastic push-back while the adhesion keeps pulling, so the particle must
 * climb out of the adhesive well across the whole overlap (doc/kernel.md has
 * the numbers).
 */
#ifndef SWR_DAMPING_H
#define SWR_DAMPING_H

#include <math.h>

#include "swr_params.h"

/* The dashpot over one step of velocity Verlet, for the flat and the rough
 * wall's integrators alike. Its impulse over a step is exact:
 *     int c(delta) u dt = Phi(delta1) - Phi(delta0),  Phi = pk delta^(5/4),
 * pk = (4/5) alpha kd, kd = sqrt(2 E* sqrt(R*)) (units of the particle mass),
 * which also removes the error of the delta^(1/4) singularity of c at first
 * contact. The opening half kick applies h/2 F_d of the last step; the rest
 * of the exact impulse is applied after the closing kick. */
static inline double swr_dashpot_potential(double pk, double delta)
{
    return delta > 0.0 ? pk * delta * sqrt(sqrt(delta)) : 0.0;
}

/* The approach speed after the rest of the step's dashpot impulse: ue the
 * approach speed after the closing kick, dphi = Phi(delta1) - Phi(delta0),
 * kick_old = h/2 F_d(old) (the part the opening kick applied). The dashpot
 * stops the motion, it never reverses it. Its work over the step, with u0
 * the approach speed at the step's start, is added to *w. */
static inline double swr_dashpot_step(double ue, double dphi, double kick_old, double u0, double *w)
{
    double u = ue - (dphi - kick_old);
    if (ue > 0.0 ? u < 0.0 : (ue < 0.0 && u > 0.0))
        u = 0.0;
    *w += dphi * 0.5 * (u0 + (ue > 0.0 ? fmax(u, 0.0) : fmin(u, 0.0)));
    return u;
}

/* The dashpot force alpha kd delta^(1/4) u at overlap delta and approach
 * speed u (the next opening kick's). */
static inline double swr_dashpot_force(double alpha, double kd, double delta, double u)
{
    return alpha * kd * sqrt(sqrt(delta)) * u;
}

/* COR of the dimensionless Hertz impact with this dashpot (accurate ODE solve). */
double swr_damping_cor(double alpha);

/* alpha for a COR e in (0, 1] from the per-process table (e = 1: 0). e below
 * swr_damping_e_min() gets the table's largest alpha. Thread-safe; builds the
 * table on first use. */
double swr_damping_alpha(double e);
/* Loading time of the damped Hertz impact over that of the undamped one
 * (<= 1): the integrator scales its step by it, so the loading phase, where
 * the dashpot acts, gets the same number of steps whatever the damping. */
double swr_damping_time_factor(double alpha);
/* The smallest COR the table covers. */
double swr_damping_e_min(void);
/* The same with the dashpot acting on both branches (`dashpot both`): the
 * COR of the whole damped Hertz impact (ODE solve), and alpha(e) from a table
 * built on first use (Steffen spline in -ln e, e down to 1e-3; a smaller e
 * gets the table's largest alpha, about 1.6). */
double swr_damping_cor_both(double alpha);
double swr_damping_alpha_both(double e);
double swr_damping_e_min_both(void);
/* The dashpot's alpha for the COR e per the settings p: dashpot both
 * swr_damping_alpha_both(e); cor constant alpha_const (the model's, root-found
 * once); else the table swr_damping_alpha(e). Used by the flat and the rough
 * wall's integrators alike. */
double swr_damping_alpha_for(const swr_params *p, double alpha_const, double e);
/* alpha for e by a GSL Brent root finder on swr_damping_cor (about 1 ms). */
double swr_damping_alpha_exact(double e);
/* Build the table now (idempotent, thread-safe); 0 or -1 on failure. */
int swr_damping_init(void);

/* Plastic COR the dashpot is set to for one impact, per the `cor` mode:
 * elastic 1; constant cor_value; thornton: swp_cor_thornton(V_y / V_i) with
 * V_y of the particle-wall pair, or for cor_pair particle of two equal
 * spheres of this size (R* = R/2, m* = m/2); thornton-asymptote: the
 * large-velocity asymptote of the same pair (the wall form
 * 1.324 (p_y^5/(E*^4 rho))^(1/8) V_i^(-1/4) as the original work used it).
 * thornton-ning: no dashpot (the caller sets none); the value is Thornton's
 * wall COR, which that contact law gives without adhesion (informative).
 * Estar is the particle-wall E*, R the particle radius, m its mass, vi the
 * normal impact speed. */
double swr_damping_target(const swr_params *p, double Estar, double R, double m, double vi);

#endif
