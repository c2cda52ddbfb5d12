/* swf.c - the flux-consistent (RT0) velocity in a hexahedral cell (swf.h). */
#include "swf.h"

#include <math.h>

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The pair vectors e_k and V_E = e_0 . (e_1 x e_2); 0 for a degenerate cell. */
static double frame(const swf_hex *h, double e[3][3])
{
    double len = 1.0;
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < 3; i++) e[k][i] = h->c_hi[k][i] - h->c_lo[k][i];
        len *= sqrt(dot(e[k], e[k]));
    }
    double c[3];
    cross(e[1], e[2], c);
    const double v = dot(e[0], c);
    if (!(len > 0) || !(fabs(v) > 1e-9 * len)) return 0.0;
    return v;
}

static int finite_hex(const swf_hex *h)
{
    for (int k = 0; k < 3; k++) {
        if (!isfinite(h->phi_lo[k]) || !isfinite(h->phi_hi[k])) return 0;
        for (int i = 0; i < 3; i++)
            if (!isfinite(h->c_lo[k][i]) || !isfinite(h->c_hi[k][i])) return 0;
    }
    return 1;
}

int swf_hex_velocity(const swf_hex *h, const double x[3], double u[3])
{
    if (!h || !x || !u || !finite_hex(h) || !isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
        return SWF_EINVAL;
    double e[3][3];
    const double v = frame(h, e);
    if (v == 0.0) return SWF_EDEGENERATE;
    /* the origin: the mean of the six face centres (the centre of a
       parallelepiped), so that xi_k = e^k . (x - x0) + 1/2 */
    double x0[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) x0[i] += (h->c_lo[k][i] + h->c_hi[k][i]) / 6.0;
    const double r[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    double out[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        double dual[3];   /* e^k = (e_{k+1} x e_{k+2}) / V_E: e^k . e_j = delta_kj */
        cross(e[(k + 1) % 3], e[(k + 2) % 3], dual);
        double xi = dot(dual, r) / v + 0.5;
        xi = xi < 0.0 ? 0.0 : (xi > 1.0 ? 1.0 : xi);
        const double f = -(1.0 - xi) * h->phi_lo[k] + xi * h->phi_hi[k];
        for (int i = 0; i < 3; i++) out[i] += f * e[k][i] / fabs(v);
    }
    u[0] = out[0];
    u[1] = out[1];
    u[2] = out[2];
    return SWF_OK;
}

double swf_hex_divergence(const swf_hex *h)
{
    double e[3][3];
    if (!h || !finite_hex(h)) return NAN;
    const double v = frame(h, e);
    if (v == 0.0) return NAN;
    double s = 0.0;
    for (int k = 0; k < 3; k++) s += h->phi_lo[k] + h->phi_hi[k];
    return s / fabs(v);
}

double swf_hex_imbalance(const swf_hex *h)
{
    if (!h || !finite_hex(h)) return NAN;
    double s = 0.0, a = 0.0;
    for (int k = 0; k < 3; k++) {
        s += h->phi_lo[k] + h->phi_hi[k];
        a += fabs(h->phi_lo[k]) + fabs(h->phi_hi[k]);
    }
    return a > 0.0 ? fabs(s) / a : 0.0;
}
