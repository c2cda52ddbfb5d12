/* swp_root.c - safeguarded Newton for increasing functions (see swp_root.h). */
#include "swp_root.h"

#include <math.h>
#include <stddef.h>

double swp_root_increasing(swp_root_fn f, void *ctx, double lo, double hi, int nexpand,
                           double rtol, int maxit)
{
    for (int i = 0; i < nexpand && f(hi, ctx, NULL) < 0.0; i++)
        hi *= 2.0;
    double x = hi;
    for (int i = 0; i < maxit; i++) {
        double slope;
        const double fx = f(x, ctx, &slope);
        if (fx > 0.0)
            hi = x;
        else
            lo = x;
        double xn = slope > 0.0 ? x - fx / slope : 0.5 * (lo + hi);
        if (!(xn > lo && xn < hi))
            xn = 0.5 * (lo + hi);
        if (fabs(xn - x) <= rtol * x)
            return xn;
        x = xn;
    }
    return x;
}
