/* swr_normal.c - normal contact sub-model: Hertz and JKR (see swr_normal.h). */
#include "swr_normal.h"

#include "swp_contact.h"
#include "swp_jkr.h"
#include "swp_root.h"

void swr_normal_init(swr_normal *n, double R, double Es, double gamma)
{
    n->R = R;
    n->Es = Es;
    n->gamma = gamma > 0.0 ? gamma : 0.0;
    n->A = 4.0 * Es / (3.0 * R);
    n->B = sqrt(8.0 * M_PI * n->gamma * Es);
    n->C = sqrt(2.0 * M_PI * n->gamma / Es);
    n->c = R * n->C;
    /* U(x) = e1 x^10 - e2 x^7 + e3 x^4 - Gj: the primitive of F d delta
     * (swp_jkr_energy) written in x = sqrt(a) */
    n->e1 = 2.0 * n->A / (5.0 * R);
    n->e2 = (2.0 / 7.0) * (0.5 * n->A * n->C + 2.0 * n->B / R);
    n->e3 = 0.25 * n->B * n->C;
    n->Gj = 0.0;
    if (n->gamma > 0.0) {
        n->xj = sqrt(swp_jkr_a_jump(n->gamma, Es, R));
        n->a0 = swp_jkr_a0(n->gamma, Es, R);
        n->xf = sqrt(swp_jkr_af(n->gamma, Es, R));
        n->Fc = swp_jkr_pulloff_force(n->gamma, R);
        n->delta_c = swp_jkr_delta_c(n->gamma, Es, R);
        n->Gj = swr_normal_energy(n, n->xj);
        n->Uc = swr_normal_energy(n, n->xf);
    } else {
        n->xj = n->xf = n->a0 = n->Fc = n->delta_c = n->Uc = 0.0;
    }
}

double swr_normal_x_closed(const swr_normal *n, double delta)
{
    if (n->gamma == 0.0)
        return delta > 0.0 ? sqrt(sqrt(n->R * delta)) : 0.0;
    return sqrt(swp_jkr_radius(delta, n->gamma, n->Es, n->R));
}

typedef struct {
    const swr_normal *n;
    double E;
} turning_ctx;

/* U(x) - E and its derivative F(x) delta'(x) */
static double turning_f(double x, void *ctx, double *dfdx)
{
    const turning_ctx *c = ctx;
    const swr_normal *n = c->n;
    if (dfdx) {
        const double x2 = x * x;
        *dfdx = swr_normal_force(n, x) * (4.0 * x2 * x / n->R - n->C);
    }
    return swr_normal_energy(n, x) - c->E;
}

double swr_normal_turning_x(const swr_normal *n, double E, double x_start)
{
    const double lo = n->a0 > 0.0 ? sqrt(n->a0) : 0.0;
    const turning_ctx c = { n, E };
    return swp_root_increasing(turning_f, (void *)&c, lo, x_start > lo ? x_start : 2.0 * lo + 1.0,
                               200, 1e-14, 100);
}
