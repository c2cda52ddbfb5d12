/* sww_buildup.c - the deposit's build-up (see sww.h): the mass of a monolayer,
 * the covered fraction of a face, and the decision blended between the bare
 * wall's regime and the covered (snow on snow) one by that fraction. */
#include "sww_internal.h"

#include <float.h>
#include <math.h>

double sww_monolayer_mass(double rho, double d)
{
    /* isfinite first: an ordered comparison of a NaN raises FE_INVALID */
    if (!isfinite(rho) || !isfinite(d) || rho <= 0.0 || d <= 0.0)
        return NAN;
    if (rho > 1.0 && d > DBL_MAX / rho)
        return INFINITY; /* the product would overflow */
    /* hexagonally close-packed spheres on a plane: area fraction pi/(2 sqrt 3),
     * a sphere's mass over its projected area (2/3) rho d */
    return M_PI / (2.0 * sqrt(3.0)) * (2.0 / 3.0) * rho * d;
}

double sww_cover_fraction(double mass_per_area, double cover_mass)
{
    if (isnan(mass_per_area) || isnan(cover_mass) || cover_mass <= 0.0)
        return NAN;
    if (mass_per_area <= 0.0)
        return 0.0;
    /* compared before dividing: a tiny cover_mass cannot overflow the ratio */
    return mass_per_area < cover_mass ? mass_per_area / cover_mass : 1.0;
}

int sww_decide_blend(const sww_model *bare, const sww_model *covered, double w,
                     const sww_impact *in, sww_outcome *out)
{
    if (isnan(w) || !(w >= 0.0 && w <= 1.0))
        return SWW_EINVAL;
    if (w == 0.0 || !covered)
        return sww_decide(bare, in, out);
    if (w == 1.0)
        return sww_decide(covered, in, out);
    /* each regime's own stick probability with its gates, the random number
     * aside: with u = 0 a regime sticks whenever its p_stick > 0 and no gate
     * stops it; a gated-off stick candidate has p = 0 */
    sww_impact in0 = *in;
    in0.u = 0.0;
    sww_outcome ob, oc;
    int rc = sww_decide(bare, &in0, &ob);
    if (rc != SWW_OK)
        return rc;
    rc = sww_decide(covered, &in0, &oc);
    if (rc != SWW_OK)
        return rc;
    if (isnan(in->u) || !(in->u >= 0.0 && in->u < 1.0))
        return SWW_EINVAL;
    const double pb = ob.fate == SWW_STICK ? ob.p_stick : 0.0;
    const double pc = oc.fate == SWW_STICK ? oc.p_stick : 0.0;
    const double p = (1.0 - w) * pb + w * pc;
    /* sticks with the blended probability, with the outcome of the regime more
     * likely to stick; otherwise the outcome of the regime less likely to
     * stick (ties: the covered one when w >= 1/2), a bounce by the criterion
     * when that regime would have stuck at u = 0 */
    const int stick = in->u < p;
    const int use_cov = stick ? (pc > pb ? 1 : (pb > pc ? 0 : w >= 0.5))
                              : (pc < pb ? 1 : (pb < pc ? 0 : w >= 0.5));
    *out = use_cov ? oc : ob;
    out->by_draw = !stick && p > 0.0;
    if (!stick && out->fate == SWW_STICK) {
        const sww_model *r = use_cov ? covered : bare;
        out->fate = SWW_BOUNCE;
        out->reason = SWW_BY_CRITERION;
        sww_rebound(r, in->d, in->vn, in->vt, &out->e_n, &out->e_t);
    }
    out->p_stick = p;
    out->d_crit = (1.0 - w) * ob.d_crit + w * oc.d_crit;
    return SWW_OK;
}
