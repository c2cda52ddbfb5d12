/* swr_spring.h - the history springs of a contact (tangential, rolling):
 * what the sub-models of swr_tangential.h and swr_rolling.h share, on a
 * spring of any dimension (the flat wall's one tangential axis, the rough
 * wall's 3-D contacts).
 *
 * A spring of stiffness k holds the displacement xi; a step adds the
 * increment dxi. When the trial displacement passes the sub-model's limit it
 * is cut back by a factor f (0 <= f < 1) and the difference is dissipated.
 * The work dissipated is booked as the step's forces do it (their mean over
 * the increment, as the kicks of velocity Verlet apply them): the trial
 * spring's energy above the cut one, (1/2) k |xi|^2 (1 - f^2), less
 * (1/2) k (1 - f) dxi . xi. The trial force at the step's end never acted;
 * booking it too makes the energy-balance error first order in the step.
 *
 * Also the 3-D vector helpers of the contacts' springs. Unit-free.
 */
#ifndef SWR_SPRING_H
#define SWR_SPRING_H

#include <math.h>

/* Energy (1/2) k |xi|^2 of a spring with squared displacement x2. */
static inline double swr_spring_energy(double k, double x2)
{
    return 0.5 * k * x2;
}

/* Work dissipated by cutting a trial displacement of squared length x2 by
 * the factor f, with xdx = dxi . xi (the step's increment dotted into the
 * trial displacement). */
static inline double swr_spring_cut_work(double k, double x2, double xdx, double f)
{
    return 0.5 * k * (x2 * (1.0 - f * f) - (1.0 - f) * xdx);
}

static inline double swr_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void swr_cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Rotate a 3-D spring displacement into the tangent plane of the unit normal
 * n (a contact's normal turns as the sphere moves), keeping its length. */
static inline void swr_spring_to_plane(double xi[3], const double n[3])
{
    const double l2 = swr_dot3(xi, xi);
    if (!(l2 > 0.0))
        return;
    const double p = swr_dot3(xi, n);
    for (int k = 0; k < 3; k++)
        xi[k] -= p * n[k];
    /* |xi - p n|^2 = l2 - p^2 (n a unit vector): one root instead of two */
    const double q = l2 - p * p;
    const double f = q > 1e-24 * l2 ? sqrt(l2 / q) : 0.0;
    for (int k = 0; k < 3; k++)
        xi[k] *= f;
}

#endif
