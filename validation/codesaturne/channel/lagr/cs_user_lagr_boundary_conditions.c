/* The deposition channel in Code_Saturne, the particles: the walls are a
 * SnowWall snow zone with a map on which every contact sticks
 * (every-contact-sticks.coeffs: d_crit 1 m), the deposit counted by the binding;
 * the counts CSV every CH_EVERY steps (environment, default 500); with CH_TREAT
 * nearwall or crw the C core's near-wall model on the walls. */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"
#include "cs_lagr_tracking.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_lagr_boundary_conditions(const int bc_type[])
{
  const char *e = getenv("CH_EVERY");
  swcs_regime("regime.coeffs");
  swcs_zone(bc_type, "walls", "snow");
  swcs_output(e ? atoi(e) : 500);
  /* the C core's near-wall model (CH_TREAT nearwall: with the closure of
     deposition.coeffs; crw: without) */
  const char *t = getenv("CH_TREAT");
  if (t && !strcmp(t, "nearwall"))
    swcs_nearwall("walls", "deposition.coeffs");
  else if (t && !strcmp(t, "crw"))
    swcs_nearwall("walls", NULL);
}

void
cs_lagr_user_boundary_interaction(cs_lagr_particle_set_t *particles, cs_lnum_t p_id,
                                  cs_lnum_t face_id, const cs_real_t face_norm[3],
                                  const cs_real_t c_intersect[3], cs_real_t t_intersect,
                                  int b_zone_id, int *event_flag,
                                  cs_lagr_tracking_state_t *tracking_state)
{
  swcs_boundary_interaction(particles, p_id, face_id, face_norm, c_intersect, t_intersect,
                            b_zone_id, event_flag, tracking_state);
}

END_C_DECLS
