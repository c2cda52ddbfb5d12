/* swr_rolling.h - rolling resistance of an adhesive contact (Dominik &
 * Tielens 1995; Marshall 2009); one law for the flat wall (swr_collide.c) and
 * the rough wall's 3-D contacts (swr_rough.c).
 *
 * The rolling displacement xi_r of a sphere on a wall grows at the rolling
 * velocity: on the flat wall v_r = -R omega (omega with the sign of
 * swr_impact: positive spin makes the contact point slide along +v_t, so pure
 * forward rolling has omega = -v_t/R), on a 3-D contact of normal n the part
 * of R (omega x n) in the tangent plane. The contact resists with the moment
 * M = k_r xi_r, k_r = 4 F_c (a/a0)^(3/2), up to the critical rolling
 * displacement xi_crit; beyond it the contact rolls irreversibly at the
 * constant moment k_r xi_crit, dissipating M per unit rolling angle (the
 * spring's work, swr_spring.h, divided by R). The moment on the particle is
 * +k_r xi_r on the flat wall (it decelerates v_r), -k_r (n x xi_r) on a 3-D
 * contact. A non-adhesive contact has no rolling resistance (F_c = 0).
 * The law is written once (swr_rolling_stiffness, swr_rolling_slide);
 * swr_rolling_update applies it to a signed scalar displacement,
 * swr_rolling_update3 to a 3-D one.
 *
 * Twisting resistance is not modelled: a sphere hitting a flat wall with no
 * spin about the wall normal never acquires one (no force or moment of the
 * model has a component about the normal), so it would never act.
 */
#ifndef SWR_ROLLING_H
#define SWR_ROLLING_H

#include <math.h>

#include "swr_spring.h"

/* Rolling stiffness k_r = 4 F_c (a/a0)^(3/2) (contact radius a, its
 * equilibrium a0). */
static inline double swr_rolling_stiffness(double Fc, double a, double a0)
{
    const double ra = a / a0;
    return 4.0 * Fc * ra * sqrt(ra);
}

/* The rolling limit on a trial displacement of any dimension, squared length
 * x2 (xdx = dxi . xi): 1 when it exceeds xi_crit (irreversible rolling), with
 * *f = xi_crit / |xi| the factor that cuts it to the limit and *w the
 * spring's work of the cut (divide by R for the energy dissipated); 0 when
 * the contact holds. */
static inline int swr_rolling_slide(double kr, double x2, double xdx, double xi_crit, double *f,
                                    double *w)
{
    if (!(x2 > xi_crit * xi_crit))
        return 0;
    *f = xi_crit / sqrt(x2);
    *w = swr_spring_cut_work(kr, x2, xdx, *f);
    return 1;
}

typedef struct {
    double xi;      /* rolling displacement held by the contact, |xi| <= xi_crit */
    int rolling;    /* 1 while at the limit moment (irreversible rolling) */
    double w_roll;  /* spring work of irreversible rolling (swr_rolling_slide) */
} swr_rolling;

/* Advance the scalar displacement by the rolling increment dxi with
 * stiffness kr and critical displacement xi_crit; returns the resisting
 * moment on the particle. */
static inline double swr_rolling_update(swr_rolling *s, double dxi, double kr, double xi_crit)
{
    s->xi += dxi;
    double f, w;
    if (swr_rolling_slide(kr, s->xi * s->xi, dxi * s->xi, xi_crit, &f, &w)) {
        s->xi = copysign(xi_crit, s->xi);   /* on one axis the cut keeps the sign */
        s->w_roll += w;
        s->rolling = 1;
    } else {
        s->rolling = 0;
    }
    return kr * s->xi;
}

/* Advance the 3-D displacement xr (in the tangent plane of the contact's
 * unit normal n) by the increment dxr with stiffness kr and critical
 * displacement xi_crit; sets the moment mr = -kr (n x xr) on the particle and
 * returns the spring's work of irreversible rolling (0 while it holds). */
static inline double swr_rolling_update3(double xr[3], const double dxr[3], double kr,
                                         double xi_crit, const double n[3], double mr[3])
{
    for (int q = 0; q < 3; q++)
        xr[q] += dxr[q];
    double f, w = 0.0;
    if (swr_rolling_slide(kr, swr_dot3(xr, xr), swr_dot3(dxr, xr), xi_crit, &f, &w))
        for (int q = 0; q < 3; q++)
            xr[q] *= f;
    double nx[3];
    swr_cross3(n, xr, nx);
    for (int q = 0; q < 3; q++)
        mr[q] = -kr * nx[q];
    return w;
}

#endif
