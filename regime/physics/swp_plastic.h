/* swp_plastic.h - adhesive elastic-plastic contact after Thornton & Ning
 * (1998, Powder Technology 99, 154-162), pure functions in any consistent
 * units (SI in the comments). The derivation is in doc/kernel.md.
 *
 * The contact law, for a sphere of radius R* on a flat wall (x = contact
 * radius a; JKR symbols of swp_contact.h):
 *   1. Elastic JKR loading about R*, from the jump-in at delta = 0, while the
 *      pressure at the centre of the JKR distribution,
 *          p(0) = 2 E* a / (pi R*) - sqrt(2 Gamma E* / (pi a)),
 *      is below the limiting contact pressure p_y (Thornton & Ning's yield
 *      criterion). It reaches p_y at the yield radius a_y
 *      (swp_plastic_yield_radius); if a_y is below the jump-in radius the
 *      contact yields from the first touch.
 *   2. Yield: the force grows linearly with the overlap,
 *          F = F_y + pi p_y R* (delta - delta_y),
 *      and the contact radius as in Hertz geometry, a^2 = a_y^2 + R* (delta - delta_y)
 *      ((F_y, delta_y) the JKR point at a_y). With Gamma = 0 this is
 *      Thornton's (1997) elastic-perfectly-plastic loading.
 *   3. Unloading (and reloading below the largest overlap delta*) is elastic
 *      JKR about a flattened contact: the radius of curvature R_p and the
 *      offset delta_p are those of the JKR curve through the state at delta*
 *      (force F*, contact radius a*):
 *          F* = 4 E* a*^3 / (3 R_p) - sqrt(8 pi Gamma E* a*^3),
 *          delta* - delta_p = a*^2 / R_p - sqrt(2 pi Gamma a* / E*),
 *      so the pull-off force 1.5 pi Gamma R_p and the separation energy grow
 *      with the plastic flattening; the contact breaks at the displacement-
 *      controlled separation of that curve. Without yield R_p = R*, delta_p = 0.
 * Without adhesion the rebound COR is Thornton's closed form
 * swp_cor_thornton(V_y / V_i) exactly; without yield it is elastic JKR.
 */
#ifndef SWP_PLASTIC_H
#define SWP_PLASTIC_H

#ifdef __cplusplus
extern "C" {
#endif

/* Pressure at the centre of a JKR contact of radius a [Pa]:
 * 2 E* a / (pi R*) - sqrt(2 Gamma E* / (pi a)). */
double swp_plastic_centre_pressure(double a, double Gamma, double Estar, double Rstar);

/* Yield contact radius a_y: the root of centre pressure = p_y (increasing in
 * a; bisection-safeguarded Newton to 1e-14 relative). Gamma = 0: the Hertz
 * value pi R* p_y / (2 E*). Returns NaN for a non-positive p_y, E* or R*. */
double swp_plastic_yield_radius(double p_y, double Gamma, double Estar, double Rstar);

/* Radius of curvature of the unloading curve through (a*, F*):
 * R_p = 4 E* a*^3 / (3 (F* + sqrt(8 pi Gamma E* a*^3))). */
double swp_plastic_unload_radius(double a_star, double F_star, double Gamma, double Estar);

/* Slope of the yield branch, dF/d delta = pi p_y R*. */
double swp_plastic_stiffness(double p_y, double Rstar);

#ifdef __cplusplus
}
#endif
#endif
