/* The deposition channel in Code_Saturne, the particles: the flow of the flow
 * run frozen (restart), time step 2 t+ = 2 nu / u_tau^2, CH_STEPS steps
 * (environment, default 5000) after the flow's 3000, gravity along the flow
 * (Liu & Agarwal's pipe was vertical). */
#include "cs_defs.h"

#include <stdlib.h>

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
  cs_get_glob_time_step_options()->idtvar = 0;
  const double nu = 1.5e-5, utau = 314 * nu / 0.00635;
  domain->time_step->dt_ref = 2 * nu / (utau * utau);
  const char *e = getenv("CH_STEPS");
  domain->time_step->nt_max = 3000 + (e ? atoi(e) : 5000);
  cs_fluid_properties_t *fp = cs_get_glob_fluid_properties();
  fp->ro0 = 1.2;
  fp->viscl0 = 1.8e-5;
  cs_turb_ref_values_t *r = cs_get_glob_turb_ref_values();
  r->uref = 12.0;
  r->almax = 0.00635;
  cs_physical_constants_t *pc = cs_get_glob_physical_constants();
  pc->gravity[0] = 9.81;
  pc->gravity[1] = pc->gravity[2] = 0.0;
}

END_C_DECLS
