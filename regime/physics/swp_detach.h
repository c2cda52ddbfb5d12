/* swp_detach.h - detachment of an adhered sphere by a wall shear flow
 * (pure closed forms, SI units).
 *
 * A sphere of radius R resting on a wall in the viscous sublayer sees the
 * linear shear flow u(y) = (tau_w / mu_air) y. Creeping-flow results for a
 * sphere touching a wall (O'Neill 1968; Goldman, Cox & Brenner 1967):
 *   drag    F_D = 1.7009 * 3 pi mu_air d u_c,  u_c = (tau_w/mu_air) R  (speed at the centre)
 *               = 1.7009 * 6 pi tau_w R^2             (mu_air cancels)
 *   torque  T_D = 0.944 * 4 pi mu_air R^3 (tau_w/mu_air) = 0.944 * 4 pi tau_w R^3
 * Resisting the flow, the JKR contact (doc/physics-brief.md section 3):
 *   pull-off force F_c = 1.5 pi Gamma R (times an optional roughness factor k in (0,1]),
 *   contact radius a0, a0^3 = 9 pi Gamma R^2 / (2 E*).
 * Rolling detachment (moment about the contact edge, lever arm of the drag R):
 *   F_D R + T_D >= F_c a0
 * Sliding detachment (friction coefficient mu_s):
 *   F_D >= mu_s F_c
 * The critical wall shear stress is the smaller of the two thresholds.
 * Reference: doc/physics-brief.md section 8 (order 10 Pa for 50 um on a smooth wall).
 */
#ifndef SWP_DETACH_H
#define SWP_DETACH_H

#ifdef __cplusplus
extern "C" {
#endif

#define SWP_ONEILL_DRAG   1.7009   /* drag factor of a sphere touching a wall */
#define SWP_ONEILL_TORQUE 0.944    /* torque factor of a sphere touching a wall */

/* Drag on a wall-attached sphere of radius R in wall shear tau_w [Pa]: 1.7009*6 pi tau_w R^2. */
double swp_shear_drag(double tau_w, double R);
/* Hydrodynamic torque about its centre: 0.944*4 pi tau_w R^3. */
double swp_shear_torque(double tau_w, double R);
/* Detaching moment about the contact edge: F_D R + T_D. */
double swp_shear_moment(double tau_w, double R);
/* Critical wall shear stress for rolling detachment: tau with F_D R + T_D = k F_c a0
 * (k: roughness factor on the pull-off force, 1 for a smooth wall). */
double swp_tau_roll(double Gamma, double Estar, double R, double k);
/* Critical wall shear stress for sliding detachment: tau with F_D = mu_s k F_c. */
double swp_tau_slide(double Gamma, double R, double mu_s, double k);
/* Critical wall shear stress, min(swp_tau_roll, swp_tau_slide); with mu_s <= 0 (or NaN)
 * sliding is ignored and the rolling threshold is returned. */
double swp_tau_detach(double Gamma, double Estar, double R, double mu_s, double k);

#ifdef __cplusplus
}
#endif
#endif
