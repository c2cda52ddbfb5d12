/* swr_tangential.h - tangential sub-model: Mindlin spring with history and a
 * Coulomb limit on the adhesion-augmented normal load.
 *
 * The spring displacement xi is the accumulated slip of the contact point
 * (velocity v_t + R omega) since the contact formed; the force on the
 * particle is F_t = -k_t xi with k_t = 8 G* a. When |F_t| would exceed
 * mu |F_n + 2 F_c| (F_n the elastic normal force, F_c = 1.5 pi Gamma R*) the
 * contact slides: F_t is held at the limit (kinetic friction, same mu) and xi
 * is reset to the displacement that carries it, the difference being
 * dissipated. Unit-free (the caller's consistent units).
 */
#ifndef SWR_TANGENTIAL_H
#define SWR_TANGENTIAL_H

#include <math.h>

typedef struct {
    double xi;      /* elastic tangential displacement */
    int sliding;    /* 1 while at the Coulomb limit */
    double w_slip;  /* energy dissipated by sliding */
} swr_tangential;

/* Advance by the slip increment ds with the current stiffness kt and limit
 * flim; returns the tangential force on the particle. */
static inline double swr_tangential_update(swr_tangential *s, double ds, double kt, double flim)
{
    s->xi += ds;
    double f = -kt * s->xi;
    if (fabs(f) > flim) {
        const double fl = copysign(flim, f);
        const double xn = kt > 0.0 ? -fl / kt : 0.0;
        s->w_slip += 0.5 * kt * (s->xi * s->xi - xn * xn);
        s->xi = xn;
        s->sliding = 1;
        return fl;
    }
    s->sliding = 0;
    return f;
}

#endif

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
