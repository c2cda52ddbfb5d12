/* swp_jkr.c - JKR contact as a function of the overlap, tangential and rolling
 * stiffnesses (see swp_jkr.h). */
#include "swp_jkr.h"

#include <math.h>

#include "swp_contact.h"

double swp_jkr_a_jump(double Gamma, double Estar, double Rstar)
{
    return cbrt(2.0 * M_PI * Gamma * Rstar * Rstar / Estar);
}

/* Largest real root x of x^4 - c x - q = 0 (c >= 0), or the double root
 * (c/4)^(1/3) when the quartic has no real root there (q below its minimum).
 * Ferrari: with y > 0 the root of y^3 + q y - c^2/8 = 0,
 * (x^2 + y)^2 = 2 y (x + c/(4y))^2, and the larger root of
 * x^2 - s x + y - c/(2s) = 0, s = sqrt(2y), is x = (s + sqrt(2c/s - s^2))/2. */
static double quartic_root(double c, double q)
{
    if (c == 0.0)
        return q > 0.0 ? sqrt(sqrt(q)) : 0.0;
    /* y^3 + p y + r = 0, p = q, r = -c^2/8: exactly one positive root */
    const double p = q, h = c * c / 16.0;            /* -r/2 */
    const double disc = h * h + p * p * p / 27.0;
    double y;
    if (disc >= 0.0) {
        /* y = u + v, u^3 = h + sqrt(disc), v = -p/(3u); written as
         * (u^3 + v^3) / (u^2 - uv + v^2) to avoid cancellation for p > 0 */
        const double u = cbrt(h + sqrt(disc));
        const double v = -p / (3.0 * u);
        y = (2.0 * h) / (u * u - u * v + v * v);
    } else {
        /* three real roots (p < 0): the largest is the positive one */
        const double m = sqrt(-p / 3.0);
        const double arg = h / (m * m * m);
        y = 2.0 * m * cos(acos(arg > 1.0 ? 1.0 : arg) / 3.0);
    }
    const double s = sqrt(2.0 * y);
    const double w = 2.0 * c / s - s * s;
    double x = 0.5 * (s + sqrt(w > 0.0 ? w : 0.0));
    /* one Newton polish on the quartic (never below the branch point) */
    const double xf = cbrt(0.25 * c);
    const double fp = 4.0 * x * x * x - c;
    if (fp > 0.0) {
        const double xn = x - (x * x * x * x - c * x - q) / fp;
        if (xn > xf)
            x = xn;
    }
    return x > xf ? x : xf;
}

double swp_jkr_radius(double delta, double Gamma, double Estar, double Rstar)
{
    const double c = Rstar * sqrt(2.0 * M_PI * Gamma / Estar);
    const double x = quartic_root(c, Rstar * delta);
    return x * x;
}

/* Antiderivative of F(a) delta'(a): with F = A a^3 - B a^(3/2) and
 * delta' = 2a/R - (C/2) a^(-1/2), A = 4 E* / (3R), B = sqrt(8 pi Gamma E*),
 * C = sqrt(2 pi Gamma / E*):
 * (2A/(5R)) a^5 - (2/7) (A C/2 + 2B/R) a^(7/2) + (B C/4) a^2. */
static double jkr_energy_primitive(double a, double Gamma, double Estar, double R)
{
    const double A = 4.0 * Estar / (3.0 * R);
    const double B = sqrt(8.0 * M_PI * Gamma * Estar);
    const double C = sqrt(2.0 * M_PI * Gamma / Estar);
    const double a2 = a * a;
    return (2.0 * A / (5.0 * R)) * a2 * a2 * a
         - (2.0 / 7.0) * (0.5 * A * C + 2.0 * B / R) * a2 * a * sqrt(a)
         + 0.25 * B * C * a2;
}

double swp_jkr_energy(double a, double Gamma, double Estar, double Rstar)
{
    return jkr_energy_primitive(a, Gamma, Estar, Rstar)
         - jkr_energy_primitive(swp_jkr_a_jump(Gamma, Estar, Rstar), Gamma, Estar, Rstar);
}

double swp_jkr_separation_energy(double Gamma, double Estar, double Rstar)
{
    return swp_jkr_energy(swp_jkr_af(Gamma, Estar, Rstar), Gamma, Estar, Rstar);
}

double swp_effective_shear_modulus(double E1, double nu1, double E2, double nu2)
{
    return 1.0 / ((2.0 - nu1) / swp_shear_modulus(E1, nu1) + (2.0 - nu2) / swp_shear_modulus(E2, nu2));
}

double swp_tangential_stiffness(double Gstar, double a)
{
    return 8.0 * Gstar * a;
}

double swp_sliding_limit(double mu, double Fn, double Fc)
{
    return mu * fabs(Fn + 2.0 * Fc);
}

double swp_rolling_stiffness(double Fc, double a, double a0)
{
    if (!(a0 > 0.0))
        return 0.0;
    const double r = a / a0;
    return 4.0 * Fc * r * sqrt(r);
}
