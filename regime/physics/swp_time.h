/* swp_time.h - contact time scales used to choose integration steps (SI units).
 * Reference: doc/physics-brief.md section 5. */
#ifndef SWP_TIME_H
#define SWP_TIME_H

#ifdef __cplusplus
extern "C" {
#endif

/* Hertz contact duration of an elastic, non-adhesive impact at speed v:
 * t_H = 2.87 (m*^2 / (R* E*^2 v))^(1/5). */
double swp_hertz_contact_time(double mstar, double Rstar, double Estar, double v);
/* Rayleigh time t_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766). */
double swp_rayleigh_time(double R, double rho, double G, double nu);

#ifdef __cplusplus
}
#endif
#endif
