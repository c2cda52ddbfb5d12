/* The deposition channel in Code_Saturne, the particles: CH_N (default 2000)
 * ice spheres (920 kg/m3) released uniformly at the start at the fluid's
 * velocity, of the diameter d = sqrt(18 mu tau+ nu / (rho_p u_tau^2)) of the
 * tau+ given as CH_TAU (default 1). */
#include "cs_defs.h"

#include <math.h>
#include <stdlib.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"
#include "cs_volume_zone.h"

BEGIN_C_DECLS

void
cs_user_lagr_volume_conditions(void)
{
  const char *e = getenv("CH_TAU");
  const double tau = e ? atof(e) : 1.0, nu = 1.5e-5, mu = 1.8e-5, utau = 314 * nu / 0.00635;
  cs_lagr_zone_data_t *vc = cs_lagr_get_volume_conditions();
  cs_lagr_injection_set_t *zis = cs_lagr_get_injection_set(vc, 0, 0);
  e = getenv("CH_N");
  zis->n_inject = e ? atoi(e) : 2000;
  zis->injection_frequency = 0;
  zis->velocity_profile = -1;
  zis->stat_weight = 1.0;
  zis->flow_rate = 0;
  zis->diameter = sqrt(18 * mu * tau * nu / (920.0 * utau * utau));
  zis->diameter_variance = 0;
  zis->density = 920.0;
  zis->fouling_index = 100.0;
  zis->temperature_profile = 0;
  zis->cp = 1400.0;
  zis->emissivity = 0.7;
}

END_C_DECLS
