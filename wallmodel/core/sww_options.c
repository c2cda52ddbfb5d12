/* sww_options.c - the model's options (see sww.h), set after the regime: the
 * tangential gate (constant, the regime's table or off, and the check of the
 * slide length against the table's), the shear gate (constant, adhesion or
 * off), the tangential rebound factor and the rebound model. */
#include "sww_internal.h"

#include <math.h>
#include <stdio.h>

int sww_set_tangential_gate(sww_model *m, double vt_max, double d_ref, double exponent)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(vt_max) || !(vt_max >= 0.0) || isinf(vt_max))
        return sww_fail(m, SWW_EINVAL, "tangential gate: vtMax %g must be a finite speed >= 0", vt_max);
    if (isnan(d_ref) || !(d_ref > 0.0) || isinf(d_ref))
        return sww_fail(m, SWW_EINVAL, "tangential gate: dRef %g must be a finite diameter > 0", d_ref);
    if (isnan(exponent) || !(fabs(exponent) <= 1e3))
        return sww_fail(m, SWW_EINVAL, "tangential gate: exponent %g is outside [-1000, 1000]",
                        exponent);
    m->vt_on = 1;
    m->vt_max = vt_max;
    m->vt_dref = d_ref;
    m->vt_exp = exponent;
    return SWW_OK;
}

int sww_set_tangential_regime(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (!m->ready || !(m->ob_ready || (m->pr_ready && m->pr_nvt > 0)))
        return sww_fail(m, SWW_EMISSING, "tangential gate 'regime': the regime map has no "
                        "oblique table (obliqueVt, obliqueVn, obliqueDCrit: make it with "
                        "snowregime map --vt 0,... --max-slide S) and no rough wall's stick "
                        "probability over v_t (probabilityVt: snowregime map --set wall=lattice "
                        "--vt 0,...)");
    m->vt_on = 2;
    return SWW_OK;
}

int sww_check_oblique_slide(sww_model *m, double slide)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (!isfinite(slide) || slide < 0.0)
        return sww_fail(m, SWW_EINVAL, "tangentialGate slideLength %g must be a finite length "
                        ">= 0 m", slide);
    if (!m->ob_ready)
        return sww_fail(m, SWW_EMISSING, "tangentialGate slideLength %g m: the regime has no "
                        "oblique table (obliqueVt, obliqueVn, obliqueDCrit) to check it against: "
                        "make regime.coeffs with snowregime map --vt 0,... --max-slide %g", slide,
                        slide);
    if (!m->has[K_OBSLIDE])
        return sww_fail(m, SWW_EMISSING, "tangentialGate slideLength %g m: the regime's oblique "
                        "table has no obliqueSlide (the slide length it was made with), so it "
                        "cannot be checked: remake regime.coeffs with snowregime map --vt 0,... "
                        "--max-slide %g (which writes obliqueSlide), or remove slideLength",
                        slide, slide);
    const double made = m->num[K_OBSLIDE];
    if (!(fabs(slide - made) <= 1e-9 * made))
        return sww_fail(m, SWW_EINVAL, "tangentialGate slideLength %g m differs from the regime "
                        "table's obliqueSlide %g m: remake regime.coeffs with snowregime map "
                        "--max-slide %g", slide, made, slide);
    return SWW_OK;
}

void sww_set_tangential_off(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    m->vt_on = 0;
}

int sww_set_shear_gate_constant(sww_model *m, double tau_c)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(tau_c) || !(tau_c >= 0.0) || isinf(tau_c))
        return sww_fail(m, SWW_EINVAL, "shear gate: tauCrit %g must be a finite stress >= 0 Pa", tau_c);
    m->shear_on = 1;
    m->tau_c = tau_c;
    return SWW_OK;
}

int sww_set_shear_gate_adhesion(sww_model *m, double roughness)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(roughness) || !(roughness > 0.0 && roughness <= 1.0))
        return sww_fail(m, SWW_EINVAL, "shear gate: roughnessFactor %g is not in (0, 1]", roughness);
    if (!m->has[K_GAMMA])
        return sww_fail(m, SWW_EMISSING, "shear gate model adhesion: missing key 'gamma' "
                        "(work of adhesion) in the regime dictionary");
    if (!m->has[K_ESTAR])
        return sww_fail(m, SWW_EMISSING, "shear gate model adhesion: missing key 'Estar' "
                        "(effective modulus) in the regime dictionary");
    m->shear_on = 2;
    m->roughness = roughness;
    return SWW_OK;
}

void sww_set_shear_off(sww_model *m)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    m->shear_on = 0;
}

int sww_set_rebound_tangential(sww_model *m, double e_t)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (isnan(e_t) || !(e_t >= 0.0 && e_t <= 1.0))
        return sww_fail(m, SWW_EINVAL, "reboundTangential %g is not in [0, 1]", e_t);
    m->e_t = e_t;
    return SWW_OK;
}

int sww_set_rebound_model(sww_model *m, int model)
{
    m->err[0] = '\0'; /* the message is of the last call only */
    if (model != SWW_REBOUND_AUTO && model != SWW_REBOUND_TABLE && model != SWW_REBOUND_CLASSIC)
        return sww_fail(m, SWW_EINVAL, "rebound model %d is not auto (0), table (1) or classic (2)",
                        model);
    if (model == SWW_REBOUND_TABLE && !m->rb_ready)
        return sww_fail(m, SWW_EMISSING, "rebound 'table': the regime map has no rebound table "
                        "(reboundD, reboundVn, reboundEn: make regime.coeffs with snowregime map)");
    m->rb_model = model;
    return SWW_OK;
}
