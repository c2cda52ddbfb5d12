/* The deposition channel in Code_Saturne, the flow: steady RANS, k-omega SST,
 * air (rho 1.2 kg/m3, mu 1.8e-5 Pa s), 3000 iterations from a uniform 12 m/s. */
#include "cs_defs.h"
#include "cs_domain.h"
#include "cs_physical_constants.h"
#include "cs_prototypes.h"
#include "cs_time_step.h"
#include "cs_turbulence_model.h"

BEGIN_C_DECLS

void
cs_user_model(void)
{
  cs_get_glob_turb_model()->iturb = CS_TURB_K_OMEGA;
}

void
cs_user_parameters(cs_domain_t *domain)
{
  cs_get_glob_time_step_options()->idtvar = -1;   /* steady algorithm */
  domain->time_step->dt_ref = 1e-4;
  domain->time_step->nt_max = 3000;
  cs_fluid_properties_t *fp = cs_get_glob_fluid_properties();
  fp->ro0 = 1.2;
  fp->viscl0 = 1.8e-5;
  cs_turb_ref_values_t *r = cs_get_glob_turb_ref_values();
  r->uref = 12.0;
  r->almax = 0.00635;
  cs_physical_constants_t *pc = cs_get_glob_physical_constants();
  pc->gravity[0] = pc->gravity[1] = pc->gravity[2] = 0.0;
}

END_C_DECLS
