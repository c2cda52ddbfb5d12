/* swp_cor.h - coefficient of restitution models (pure functions, SI units).
 *
 * Thornton (1997) elastic-perfectly-plastic impact with limiting contact
 * pressure p_y = 2.5 sigma_y. Reference: doc/physics-brief.md section 4.
 */
#ifndef SWP_COR_H
#define SWP_COR_H

#ifdef __cplusplus
extern "C" {
#endif

/* Limiting contact pressure p_y = 2.5 sigma_y. */
double swp_limiting_pressure(double sigma_y);
/* Yield velocity, particle-wall: V_y = 1.56 (p_y^5 / (E*^4 rho))^(1/2). */
double swp_yield_velocity_wall(double p_y, double Estar, double rho);
/* Yield velocity, particle-particle: V_y = 3.194 (p_y^5 R*^3 / (E*^4 m*))^(1/2). */
double swp_yield_velocity_pp(double p_y, double Estar, double Rstar, double mstar);
/* Full Thornton (1997) plastic COR as a function of V_y / V_i:
 * e = (6 sqrt3 / 5)^(1/2) [1 - (1/6) x^2]^(1/2)
 *     [ x / (x + 2 sqrt(6/5 - x^2/5)) ]^(1/4),   x = V_y / V_i,
 * and e = 1 for V_i <= V_y (x >= 1). For x -> 0 it tends to 1.185 x^(1/4). */
double swp_cor_thornton(double vy_over_vi);
/* Large-velocity asymptote, particle-wall, exactly as the original work used it:
 * e_p = 1.324 (p_y^5 / (E*^4 rho))^(1/8) V_i^(-1/4), capped at 1. */
double swp_cor_thornton_wall_asymptote(double p_y, double Estar, double rho, double v_i);
/* Large-velocity asymptote, particle-particle: e_p = 1.185 (V_y/V_i)^(1/4), capped at 1. */
double swp_cor_thornton_pp_asymptote(double vy_over_vi);
/* Combine plastic and adhesive losses (Thornton & Ning 1998):
 * 1 - e^2 = (1 - e_p^2) + (1 - e_a^2); returns e (0 when the losses exceed 1). */
double swp_cor_combine(double e_p, double e_a);

#ifdef __cplusplus
}
#endif
#endif
