/* The box of tests/openfoam/box in Code_Saturne: laminar flow of a fluid with
 * rho 1 kg/m3 and mu 1 Pa s (so the Couette flow U_x = 2 y has a wall shear
 * stress of 2 Pa, as the OpenFOAM box's frozen field), no gravity, dt 5 ms,
 * 21 steps (the particles start moving after the first: cs_user_lagr_particle.c). */
#include "cs_defs.h"
#include "cs_domain.h"
#include "cs_physical_constants.h"
#include "cs_prototypes.h"
#include "cs_time_step.h"
#include "cs_turbulence_model.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_model(void)
{
  cs_get_glob_turb_model()->iturb = CS_TURB_NONE;
}

void
cs_user_parameters(cs_domain_t *domain)
{
  cs_get_glob_time_step_options()->idtvar = 0;
  domain->time_step->dt_ref = 0.005;
  domain->time_step->nt_max = 21;
  cs_fluid_properties_t *fp = cs_get_glob_fluid_properties();
  fp->ro0 = 1.0;
  fp->viscl0 = 1.0;
  cs_physical_constants_t *pc = cs_get_glob_physical_constants();
  pc->gravity[0] = pc->gravity[1] = pc->gravity[2] = 0.0;
  /* SnowWall's deposit as a boundary field in the post-processing output */
  swcs_deposit_field();
}

END_C_DECLS
