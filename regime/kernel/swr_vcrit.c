/* swr_vcrit.c - critical normal sticking velocity by bisection (see swr_collide.h). */
#include <math.h>

#include "swr_collide.h"

static int kept(const swr_model *m, double d, double v)
{
    swr_impact in = { .d = d, .vn = v, .vt = 0.0, .omega = 0.0 };
    swr_result r;
    swr_collide(m, &in, &r, NULL);
    return r.contact_kept;
}

int swr_vcrit_normal(const swr_model *m, double d, double vlo, double vhi, double rtol,
                     double *vcrit)
{
    if (!kept(m, d, vlo)) {
        *vcrit = 0.0;
        return -1;
    }
    if (kept(m, d, vhi)) {
        *vcrit = vhi;
        return -1;
    }
    /* kept at vlo, bounces at vhi: bisect in ln v */
    while (vhi > vlo * (1.0 + rtol)) {
        const double mid = sqrt(vlo * vhi);
        if (kept(m, d, mid))
            vlo = mid;
        else
            vhi = mid;
    }
    *vcrit = sqrt(vlo * vhi);
    return 0;
}
