/* swr_normal.h - normal contact sub-model: Hertz, and JKR with hysteresis.
 *
 * Unit-free: the constants are given in whatever consistent units the caller
 * integrates in (swr_collide.c uses units where the particle mass, the impact
 * speed and the contact time are 1). Overlap delta > 0 in compression, force
 * > 0 repulsive. The state of the contact is its radius a, kept as x = sqrt(a)
 * because the JKR laws are polynomials in x:
 *     delta(x) = x^4/R - C x,    F(x) = A x^6 - B x^3,
 *     A = 4 E* / (3R), B = sqrt(8 pi Gamma E*), C = sqrt(2 pi Gamma/E*).
 * Hysteresis (JKR, Gamma > 0): no force before the first touch; at delta = 0
 * the contact jumps in to a_jump = (2 pi Gamma R^2/E*)^(1/3) on the JKR curve;
 * loading and unloading follow the curve, into negative overlap (necking);
 * the contact breaks at the displacement-controlled separation
 * delta_c = -3 a_f^2/R, a_f = a0/6^(2/3), and the stored energy U_c = U(a_f)
 * is lost. With Gamma = 0 every formula reduces to Hertz (a = sqrt(R delta)).
 * Formulas: regime/physics/swp_contact.h, swp_jkr.h.
 */
#ifndef SWR_NORMAL_H
#define SWR_NORMAL_H

#include <math.h>

typedef struct {
    double R, Es, gamma;     /* R*, E*, Gamma (0: Hertz) */
    double A, B, C;          /* F = A x^6 - B x^3, delta = x^4/R - C x */
    double c;                /* quartic x^4 - c x - R delta = 0: c = R C */
    double xj, xf;           /* sqrt(a_jump), sqrt(a_f) (0 for Hertz) */
    double a0;               /* equilibrium contact radius (0 for Hertz) */
    double Fc;               /* pull-off force 1.5 pi Gamma R */
    double delta_c;          /* separation overlap (0 for Hertz) */
    double Uc;               /* energy lost at separation U(a_f) (0 for Hertz) */
    double Gj;               /* energy primitive at the jump-in */
    double e1, e2, e3;       /* energy primitive coefficients (see swr_normal.c) */
} swr_normal;

/* Set the constants from R*, E*, Gamma (Gamma = 0: Hertz). */
void swr_normal_init(swr_normal *n, double R, double Es, double gamma);

/* Largest x = sqrt(a) with U(x) = E (the turning point of a conservative
 * motion with energy E relative to the jump-in): Newton from above (x_start,
 * doubled until U >= E), bisection as a safeguard; U grows monotonically above
 * the equilibrium sqrt(a0). */
double swr_normal_turning_x(const swr_normal *n, double E, double x_start);

/* sqrt of the contact radius for overlap delta (>= delta_c), closed form. */
double swr_normal_x_closed(const swr_normal *n, double delta);

/* sqrt of the contact radius for overlap delta, starting from the previous
 * value x (warm start): safeguarded Newton on the convex quartic, which from
 * any start above the branch point x_f converges monotonically after one step;
 * it falls back to the closed form if it has not converged in a few steps.
 * This is the per-step call. */
static inline double swr_normal_x(const swr_normal *n, double delta, double x)
{
    const double q = n->R * delta;
    if (n->c == 0.0)
        return q > 0.0 ? sqrt(sqrt(q)) : 0.0;
    if (!(x > 1.0001 * n->xf))
        return swr_normal_x_closed(n, delta);
    for (int i = 0; i < 6; i++) {
        const double x3 = x * x * x;
        const double dx = (x3 * x - n->c * x - q) / (4.0 * x3 - n->c);
        x -= dx;
        if (!(x > n->xf))
            break;
        if (fabs(dx) <= 1e-13 * x)
            return x;
    }
    return swr_normal_x_closed(n, delta);
}

/* Elastic normal force at x. */
static inline double swr_normal_force(const swr_normal *n, double x)
{
    const double x3 = x * x * x;
    return n->A * x3 * x3 - n->B * x3;
}

/* Stored energy at x relative to the jump-in state (Hertz: relative to
 * delta = 0). */
static inline double swr_normal_energy(const swr_normal *n, double x)
{
    const double x2 = x * x, x4 = x2 * x2, x7 = x4 * x2 * x;
    return n->e1 * x7 * x2 * x - n->e2 * x7 + n->e3 * x4 - n->Gj;
}

#endif
