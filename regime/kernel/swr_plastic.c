/* swr_plastic.c - Thornton & Ning adhesive elastic-plastic normal contact
 * (see swr_plastic.h). */
#include "swr_plastic.h"

#include <math.h>

#include "swp_plastic.h"

void swr_plastic_init(swr_plastic *s, double R, double Es, double gamma, double py)
{
    swr_normal_init(&s->el, R, Es, gamma);
    s->un = s->el;
    s->py = py;
    s->k = swp_plastic_stiffness(py, R);
    const double ay = swp_plastic_yield_radius(py, s->el.gamma, Es, R);
    const double aj = s->el.xj * s->el.xj;   /* 0 for Hertz */
    /* the loading curve starts at the jump-in: yield from the first touch
     * when a_y is below it */
    const double a = ay > aj ? ay : aj;
    s->xy = sqrt(a);
    s->ay2 = a * a;
    s->dy = a > aj ? a * a / R - s->el.C * s->xy : 0.0;
    s->Fy = swr_normal_force(&s->el, s->xy);
    s->Wy = a > aj ? swr_normal_energy(&s->el, s->xy) : 0.0;
    s->branch = SWR_PL_ELASTIC;
    s->dstar = s->Fstar = s->Wstar = s->Ustar = s->dp = 0.0;
    s->xstar = s->xy;
}

static double yield_x(const swr_plastic *s, double delta)
{
    return sqrt(sqrt(s->ay2 + s->el.R * (delta - s->dy)));
}

double swr_plastic_load_work(const swr_plastic *s, double delta, double *x)
{
    if (delta < s->dy) {
        *x = swr_normal_x_closed(&s->el, delta);
        return swr_normal_energy(&s->el, *x);
    }
    const double z = delta - s->dy;
    *x = yield_x(s, delta);
    return s->Wy + s->Fy * z + 0.5 * s->k * z * z;
}

double swr_plastic_turning(const swr_plastic *s, double E)
{
    if (E > s->Wy) {
        /* F_y z + k z^2/2 = E - W_y, the positive root without cancellation */
        const double q = E - s->Wy, Fy = s->Fy, k = s->k;
        const double r = sqrt(Fy * Fy + 2.0 * k * q);
        const double z = Fy > 0.0 ? 2.0 * q / (Fy + r) : (r - Fy) / k;
        return s->dy + z;
    }
    /* elastic curve: U(x) = E below x_y (U increasing above sqrt(a0)) */
    const swr_normal *n = &s->el;
    const double x = swr_normal_turning_x(n, E, s->xy);
    return x * x * x * x / n->R - n->C * x;
}

void swr_plastic_unload(swr_plastic *s, double dstar)
{
    double x;
    s->Wstar = swr_plastic_load_work(s, dstar, &x);
    s->dstar = dstar;
    s->xstar = x;
    const double a = x * x;
    if (dstar >= s->dy) {
        s->Fstar = s->Fy + s->k * (dstar - s->dy);
        const double Rp = swp_plastic_unload_radius(a, s->Fstar, s->el.gamma, s->el.Es);
        swr_normal_init(&s->un, Rp, s->el.Es, s->el.gamma);
        s->dp = dstar - (a * a / Rp - s->el.C * x);
    } else {
        /* never yielded: unload on the loading curve (the formula above
         * gives R_p = R*, delta_p = 0 up to rounding) */
        s->Fstar = swr_normal_force(&s->el, x);
        s->un = s->el;
        s->dp = 0.0;
    }
    s->Ustar = swr_normal_energy(&s->un, x);
    s->branch = SWR_PL_UNLOAD;
}

double swr_plastic_force(swr_plastic *s, double delta, double *x)
{
    switch (s->branch) {
    case SWR_PL_UNLOAD:
        *x = swr_normal_x(&s->un, delta - s->dp, *x);
        return swr_normal_force(&s->un, *x);
    case SWR_PL_ELASTIC:
        if (delta < s->dy) {
            *x = swr_normal_x(&s->el, delta, *x);
            return swr_normal_force(&s->el, *x);
        }
        s->branch = SWR_PL_YIELD;
        /* fall through */
    case SWR_PL_YIELD:
        *x = yield_x(s, delta > s->dy ? delta : s->dy);
        return s->Fy + s->k * (delta - s->dy);
    }
    return 0.0;
}

double swr_plastic_energy(const swr_plastic *s, double delta, double x)
{
    if (s->branch == SWR_PL_UNLOAD)
        return s->Wstar - (s->Ustar - swr_normal_energy(&s->un, x));
    double xx;
    return swr_plastic_load_work(s, delta, &xx);
}

double swr_plastic_separation_energy(const swr_plastic *s)
{
    return s->Wstar - (s->Ustar - swr_normal_energy(&s->un, s->un.xf));
}

double swr_plastic_separation_overlap(const swr_plastic *s)
{
    return s->dp + s->un.delta_c;
}
