/* swp_contact.h - closed forms of Hertz and JKR contact mechanics.
 *
 * Pure, stateless functions in SI units, shared by the regime kernel
 * (regime/kernel), the wall-interaction core (wallmodel/core) and the tests.
 * Sign convention: overlap delta > 0 in compression; force > 0 is repulsive.
 * A wall is a sphere of infinite radius (pass INFINITY): R* = R, m* = m.
 * Reference: doc/physics-brief.md section 3; Johnson, Kendall & Roberts
 * (1971); Thornton & Ning (1998).
 */
#ifndef SWP_CONTACT_H
#define SWP_CONTACT_H

#ifdef __cplusplus
extern "C" {
#endif

/* 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 */
double swp_effective_modulus(double E1, double nu1, double E2, double nu2);
/* 1/R* = 1/R1 + 1/R2 (R2 = INFINITY for a flat wall) */
double swp_effective_radius(double R1, double R2);
/* m* = m1 m2 / (m1 + m2) (m2 = INFINITY for a wall) */
double swp_effective_mass(double m1, double m2);
/* Shear modulus G = E / (2 (1 + nu)) */
double swp_shear_modulus(double E, double nu);

/* Hertz: F = (4/3) E* sqrt(R*) delta^(3/2) for delta > 0, else 0. */
double swp_hertz_force(double Estar, double Rstar, double delta);
/* Hertz elastic energy stored at overlap delta: (8/15) E* sqrt(R*) delta^(5/2). */
double swp_hertz_energy(double Estar, double Rstar, double delta);

/* JKR: overlap as a function of the contact radius a,
 * delta(a) = a^2/R* - sqrt(2 pi Gamma a / E*). */
double swp_jkr_delta(double a, double Gamma, double Estar, double Rstar);
/* JKR: force as a function of a, F(a) = 4E*a^3/(3R*) - sqrt(8 pi Gamma E* a^3). */
double swp_jkr_force(double a, double Gamma, double Estar, double Rstar);
/* Equilibrium contact radius (F = 0): a0^3 = 9 pi Gamma R*^2 / (2 E*). */
double swp_jkr_a0(double Gamma, double Estar, double Rstar);
/* Pull-off force under load control, magnitude: F_c = 1.5 pi Gamma R*. */
double swp_jkr_pulloff_force(double Gamma, double Rstar);
/* Contact radius at the displacement-controlled separation: a_f = a0 / 6^(2/3). */
double swp_jkr_af(double Gamma, double Estar, double Rstar);
/* Separation overlap (displacement control), negative: delta_c = -3 a_f^2 / R*
 * (equal to delta(a_f)). */
double swp_jkr_delta_c(double Gamma, double Estar, double Rstar);

/* Tabor parameter lambda_T = (R* Gamma^2 / (E*^2 z0^3))^(1/3); JKR holds for
 * lambda_T > SWP_TABOR_JKR_MIN. */
#define SWP_TABOR_JKR_MIN 5.0
double swp_tabor(double Gamma, double Estar, double Rstar, double z0);

/* Thornton & Ning (1998) elastic-adhesive sticking velocity, particle-wall:
 * V_s = 1.84 (Gamma^5 / (rho^3 E*^2 R*^5))^(1/6). */
double swp_sticking_velocity_tn(double Gamma, double rho, double Estar, double Rstar);

#ifdef __cplusplus
}
#endif
#endif
