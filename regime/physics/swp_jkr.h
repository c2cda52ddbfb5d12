/* swp_jkr.h - JKR contact in terms of the overlap, and the tangential and
 * rolling stiffnesses of an adhesive contact (pure functions, any consistent
 * units; SI in the comments).
 *
 * The JKR relations of swp_contact.h give delta and F as functions of the
 * contact radius a. With x = sqrt(a) the overlap relation becomes the quartic
 *     x^4 - c x - R* delta = 0,   c = R* sqrt(2 pi Gamma / E*),
 * whose largest real root is the contact radius on the stable branch of the
 * displacement-controlled curve (a >= a_f). Its closed form (Ferrari, with the
 * resolvent cubic y^3 + q y - c^2/8 = 0, q = R* delta) is swp_jkr_radius().
 * References: Johnson, Kendall & Roberts (1971); Thornton & Ning (1998);
 * Mindlin (1949); Dominik & Tielens (1995); Marshall (2009).
 */
#ifndef SWP_JKR_H
#define SWP_JKR_H

#ifdef __cplusplus
extern "C" {
#endif

/* Contact radius at the jump-in (delta = 0 on the JKR curve):
 * a(0)^3 = 2 pi Gamma R*^2 / E*. */
double swp_jkr_a_jump(double Gamma, double Estar, double Rstar);

/* Contact radius on the stable JKR branch (a >= a_f) for overlap delta, closed
 * form. For delta <= delta_c (no contact possible) it returns a_f. With
 * Gamma = 0 it is the Hertz radius sqrt(R* delta) (0 for delta <= 0). */
double swp_jkr_radius(double delta, double Gamma, double Estar, double Rstar);

/* Elastic energy stored in a JKR contact of radius a, relative to the jump-in
 * state (delta = 0, a = a_jump): U(a) = int_{a_jump}^{a} F(a') (d delta/da') da'.
 * U >= 0 on the whole branch; U(a_f) is the energy lost at the displacement-
 * controlled separation. With Gamma = 0 it is the Hertz energy. */
double swp_jkr_energy(double a, double Gamma, double Estar, double Rstar);

/* Energy that a particle must bring to break an elastic JKR contact that formed
 * at delta = 0: U(a_f); the elastic sticking velocity is sqrt(2 U(a_f) / m*)
 * (= 1.8402 (Gamma^5/(rho^3 E*^2 R*^5))^(1/6) for a sphere on a wall, which
 * Thornton & Ning round to 1.84). */
double swp_jkr_separation_energy(double Gamma, double Estar, double Rstar);

/* Mindlin effective shear modulus of a contact:
 * 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2,  G_i = E_i / (2 (1 + nu_i)). */
double swp_effective_shear_modulus(double E1, double nu1, double E2, double nu2);

/* Tangential (Mindlin) stiffness k_t = 8 G* a. */
double swp_tangential_stiffness(double Gstar, double a);

/* Coulomb limit of the tangential force with the adhesion-augmented normal
 * load (Thornton & Yin 1991, Marshall 2009): mu |F_n + 2 F_c|. */
double swp_sliding_limit(double mu, double Fn, double Fc);

/* Rolling stiffness of an adhesive contact (Dominik & Tielens 1995,
 * Marshall 2009): k_r = 4 F_c (a/a0)^(3/2) [N]; the resisting moment is
 * M = k_r xi for a rolling displacement xi, limited to k_r xi_crit. */
double swp_rolling_stiffness(double Fc, double a, double a0);

#ifdef __cplusplus
}
#endif
#endif
