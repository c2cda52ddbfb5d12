/* swp_nearwall.h - the turbulent wall layer in wall units (pure closed forms).
 *
 * Wall units: u_tau the friction velocity, nu the kinematic viscosity,
 * y+ = y u_tau / nu, t+ = t u_tau^2 / nu, u+ = u / u_tau.
 *
 * Fluid velocity fluctuations of a fully developed channel / pipe flow, as fits
 * to direct numerical simulation, the fits that continuous-random-walk (CRW)
 * deposition models use:
 *   streamwise  u'+ = 0.4 y+ / (1 + 0.0239 y+^1.496)      (Kallio & Reeks 1989,
 *   spanwise    w'+ = 0.19 y+ / (1 + 0.0361 y+^1.21)        Int. J. Multiphase Flow 15, 433)
 *   wall-normal v'+ = 0.005 y+^2 / (1 + 0.002923 y+^2.128) (Guha 1997, J. Aerosol
 *                                                           Sci. 28, 1517)
 * and the fluid Lagrangian integral time scale (Kallio & Reeks 1989)
 *   T_L+ = 10                                   for y+ < 5
 *   T_L+ = 7.122 + 0.5731 y+ - 0.00129 y+^2     for 5 <= y+ <= 200
 * (continuous at y+ = 5 within 0.03; beyond y+ = 200 held at its y+ = 200
 * value). The near-wall limits are the physical ones: u', w' ~ y, v' ~ y^2
 * (the wall blocks wall-normal motion), which is what an isotropic random walk
 * with sigma = sqrt(2k/3) misses.
 *
 * Mean velocity: Reichardt's law of the wall (1951), smooth through the
 * viscous sublayer, buffer and log layers (kappa = 0.41):
 *   u+ = ln(1 + kappa y+)/kappa + 7.8 (1 - exp(-y+/11) - (y+/11) exp(-y+/3)).
 *
 * Every function takes y+ >= 0 (a negative or NaN y+ gives NaN) and returns
 * the value in wall units.
 */
#ifndef SWP_NEARWALL_H
#define SWP_NEARWALL_H

#ifdef __cplusplus
extern "C" {
#endif

#define SWP_KARMAN 0.41

/* rms of the streamwise, wall-normal and spanwise fluid velocity, u'+(y+). */
double swp_urms_plus(double yplus);
double swp_vrms_plus(double yplus);
double swp_wrms_plus(double yplus);
/* d u'+ / d y+, d v'+ / d y+, d w'+ / d y+: the exact derivatives of the
 * three fits (the drift of the random walk needs the gradient of each). */
double swp_durms_plus(double yplus);
double swp_dvrms_plus(double yplus);
double swp_dwrms_plus(double yplus);
/* All three at once, u', v', w' in rms[0..2] and, when slope is not NULL,
 * their derivatives d/dy+ in slope[0..2] (the random walk's hot path: one
 * power a fit for both). NaN for a bad y+. */
void swp_rms_plus(double yplus, double rms[3], double slope[3]);
/* Lagrangian integral time scale of the fluid, T_L+(y+). */
double swp_tl_plus(double yplus);
/* Reichardt's mean velocity u+(y+) and its derivative du+/dy+. */
double swp_uplus(double yplus);
double swp_duplus(double yplus);

/* Particle relaxation time [s] of a sphere of density rho_p, diameter d in a
 * fluid of dynamic viscosity mu, with the Schiller-Naumann drag correction
 * f = 1 + 0.15 Re^0.687 (Re = particle Reynolds number, >= 0; 0 gives Stokes'
 * rho_p d^2 / (18 mu)). NaN for a non-positive or non-finite input. */
double swp_tau_p(double rho_p, double d, double mu, double re);
/* Dimensionless relaxation time tau+ = tau_p u_tau^2 / nu of the Stokes
 * particle (re = 0), the abscissa of the deposition measurements. */
double swp_tau_plus(double rho_p, double d, double mu, double nu, double u_tau);
/* The diameter with a given Stokes tau+ (inverse of swp_tau_plus). */
double swp_d_of_tau_plus(double tau_plus, double rho_p, double mu, double nu, double u_tau);

/* Wood's (1981) correlation of measured turbulent deposition in pipes and
 * channels: V+ = 0.057 Sc^(-2/3) + 4.5e-4 tau+^2, capped at the plateau
 * V+ = 0.13 of the inertia-moderated regime. Sc = nu / D_B the particle
 * Schmidt number; sc <= 0 or infinite leaves the Brownian term out. NaN for
 * a negative or NaN tau+. */
double swp_wood_vplus(double tau_plus, double sc);
/* Brownian diffusivity D_B = k_B T C_c / (3 pi mu d) [m2/s] of a sphere of
 * diameter d in a gas at temperature T [K], viscosity mu, mean free path
 * lambda [m], with the Cunningham slip correction
 * C_c = 1 + Kn (1.257 + 0.4 exp(-1.1 / Kn)), Kn = 2 lambda / d. */
double swp_brownian_diffusivity(double d, double T, double mu, double lambda);

#ifdef __cplusplus
}
#endif
#endif
