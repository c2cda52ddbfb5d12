/* The box of tests/openfoam/box in Code_Saturne: the seven particles of the
 * OpenFOAM box, injected once at the start, each in the volume zone p1 .. p7
 * of its cell (cs_user_zones.c); their places, velocities and sizes are set in
 * cs_user_lagr_particle.c. */
#include "cs_defs.h"

#include <stdio.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"
#include "cs_volume_zone.h"

BEGIN_C_DECLS

void
cs_user_lagr_volume_conditions(void)
{
  cs_lagr_zone_data_t *vc = cs_lagr_get_volume_conditions();
  for (int i = 0; i < 7; i++) {
    char name[8];
    snprintf(name, sizeof name, "p%d", i + 1);
    const cs_zone_t *z = cs_volume_zone_by_name(name);
    cs_lagr_injection_set_t *zis = cs_lagr_get_injection_set(vc, z->id, 0);
    zis->n_inject = 1;
    zis->injection_frequency = 0;   /* at the start only */
    zis->velocity_profile = -1;
    zis->stat_weight = 1.0;
    zis->flow_rate = 0;
    zis->diameter = 1e-5;
    zis->diameter_variance = 0;
    zis->density = 920.0;
    zis->fouling_index = 100.0;
    zis->temperature_profile = 0;
    zis->cp = 1400.0;
    zis->emissivity = 0.7;
  }
}

END_C_DECLS
