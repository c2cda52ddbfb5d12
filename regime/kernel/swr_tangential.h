/* swr_tangential.h - tangential sub-model: Mindlin spring with history and a
 * Coulomb limit on the adhesion-augmented normal load; one law for the flat
 * wall's tangential axis (swr_collide.c) and the rough wall's 3-D contacts
 * (swr_rough.c).
 *
 * The spring displacement xi is the accumulated slip of the contact point
 * (its velocity in the contact's tangent plane: v_t + R omega on the flat
 * wall) since the contact formed; the force on the particle is F_t = -k_t xi
 * with k_t = 8 G* a. When |F_t| would exceed mu |F_n + 2 F_c| (F_n the normal
 * force, F_c = 1.5 pi Gamma R*) the contact slides: F_t is held at the limit
 * (kinetic friction, same mu) and xi is cut to the displacement that carries
 * it, the difference being dissipated (swr_spring.h: how the work is booked).
 * The law is written once (swr_tangential_stiffness, swr_tangential_limit,
 * swr_tangential_slide); swr_tangential_update applies it to a signed scalar
 * spring, swr_tangential_update3 to a 3-D spring kept in the contact's tangent
 * plane. Unit-free (the caller's consistent units).
 */
#ifndef SWR_TANGENTIAL_H
#define SWR_TANGENTIAL_H

#include <math.h>

#include "swr_spring.h"

/* Mindlin stiffness k_t = 8 G* a (contact radius a). */
static inline double swr_tangential_stiffness(double Gstar, double a)
{
    return 8.0 * Gstar * a;
}

/* Coulomb limit mu |F_n + 2 F_c| on the whole normal load fn (on the flat
 * wall the dashpot's force is in it: it stands for the plastic contact
 * pressure while loading). */
static inline double swr_tangential_limit(double mu, double fn, double Fc)
{
    return mu * fabs(fn + 2.0 * Fc);
}

/* The Coulomb law on a trial spring of any dimension, squared length x2
 * (xdx = dxi . xi, the step's increment dotted into it): 1 when its force
 * kt |xi| exceeds flim (it slides), with *f = flim / (kt |xi|) the factor
 * that cuts xi to the limit and *w the work of the sliding; 0 when it sticks. */
static inline int swr_tangential_slide(double kt, double x2, double xdx, double flim, double *f,
                                       double *w)
{
    if (!(kt * kt * x2 > flim * flim))
        return 0;
    *f = flim / (kt * sqrt(x2));
    *w = swr_spring_cut_work(kt, x2, xdx, *f);
    return 1;
}

typedef struct {
    double xi;      /* elastic tangential displacement */
    int sliding;    /* 1 while at the Coulomb limit */
    double w_slip;  /* energy dissipated by sliding */
} swr_tangential;

/* Advance the scalar spring by the slip increment ds with the current
 * stiffness kt and limit flim; returns the tangential force on the particle. */
static inline double swr_tangential_update(swr_tangential *s, double ds, double kt, double flim)
{
    s->xi += ds;
    double f, w;
    if (swr_tangential_slide(kt, s->xi * s->xi, ds * s->xi, flim, &f, &w)) {
        /* on one axis the cut keeps the sign: the force is -sign(xi) flim */
        const double fl = copysign(flim, -s->xi);
        s->xi = -fl / kt;
        s->w_slip += w;
        s->sliding = 1;
        return fl;
    }
    s->sliding = 0;
    return -kt * s->xi;
}

/* Advance the 3-D spring xi (in the contact's tangent plane) by the slip
 * increment dxi (in that plane) with stiffness kt and limit flim; sets the
 * tangential force ft on the particle and returns the work of the sliding
 * (0 while it sticks). */
static inline double swr_tangential_update3(double xi[3], const double dxi[3], double kt,
                                            double flim, double ft[3])
{
    for (int q = 0; q < 3; q++)
        xi[q] += dxi[q];
    double f, w = 0.0;
    if (swr_tangential_slide(kt, swr_dot3(xi, xi), swr_dot3(dxi, xi), flim, &f, &w))
        for (int q = 0; q < 3; q++)
            xi[q] *= f;
    for (int q = 0; q < 3; q++)
        ft[q] = -kt * xi[q];
    return w;
}

/* Arrest of the tangential motion of a sphere adhered to a flat wall, once
 * the normal contact has settled at its equilibrium (F_n = 0, a = a0): the
 * sliding resistance is then fs = mu 2 F_c, the rolling resistance moment
 * ml = k_r(a0) xi_crit = 4 F_c xi_crit. With these constant resistances the
 * motion is piecewise uniformly decelerated: sliding (contact-point velocity
 * v_c = v_t + R omega) and irreversible rolling (v_r = -R omega) stop one
 * after the other, each phase solved in closed form. The elastic spring
 * displacements (at most mu 2F_c / k_t and xi_crit) are neglected.
 * m, R, I: mass, radius, moment of inertia; vt, omega: state at the start.
 * Returns 1 and the time and the displacement of the centre along the wall
 * until rest, or 0 (with INFINITY) when the motion never stops (fs = 0 with
 * slip, or ml = 0 with rolling). */
int swr_tangential_rest(double m, double R, double I, double fs, double ml, double vt,
                        double omega, double *t_rest, double *s_rest);

#endif
