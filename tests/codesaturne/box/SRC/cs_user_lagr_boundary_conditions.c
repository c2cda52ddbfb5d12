/* The box of tests/openfoam/box in Code_Saturne: SnowWall on the wall y = 0
 * with the OpenFOAM box's settings (fixture regime, tangential gate vtMax
 * 0.5 m/s, adhesion shear gate with roughness 0.01), the top and the sides
 * escape. The calls are those of doc/codesaturne.md.
 *
 * For the test's bad-input runs (tests/codesaturne/test_box.sh) the
 * environment variable SWCS_BOX picks one wrong call: noregime, badzone,
 * notwall, badtype, twice, unnamed; unset: the normal case. */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "cs_boundary_zone.h"
#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"
#include "cs_lagr_tracking.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_lagr_boundary_conditions(const int  bc_type[])
{
  const char *t = getenv("SWCS_BOX");
  if (!t) t = "";
  cs_lagr_zone_data_t *bcs = cs_lagr_get_boundary_conditions();
  for (int z = 0; z < cs_boundary_zone_n_zones(); z++)
    bcs->zone_type[z] = CS_LAGR_OUTLET;
  if (strcmp(t, "unnamed") == 0)
    bcs->zone_type[cs_boundary_zone_by_name("top")->id] = CS_LAGR_BC_USER;

  swcs_regime(strcmp(t, "noregime") == 0 ? "missing.coeffs" : "regime.coeffs");
  swcs_zone(bc_type, strcmp(t, "badzone") == 0 ? "wal" : "wall",
            strcmp(t, "badtype") == 0 ? "snowy" : "snow");
  if (strcmp(t, "twice") == 0)
    swcs_zone(bc_type, "wall", "escape");
  if (strcmp(t, "unnamed") != 0)
    swcs_zone(bc_type, "top", "escape");
  swcs_zone(bc_type, "sides", strcmp(t, "notwall") == 0 ? "snow" : "escape");
  swcs_tangential_gate(0.5, 5e-5, 0);
  swcs_shear_gate_adhesion(0.01);
  swcs_output(10);
  swcs_verbose(1);
  /* the near-wall model's set-up errors */
  if (!strcmp(t, "nw-order") || !strcmp(t, "nw-nok"))
    swcs_nearwall("wall", NULL);
  else if (!strcmp(t, "nw-zone"))
    swcs_nearwall("wall,wal", NULL);
  else if (!strcmp(t, "nw-escape"))
    swcs_nearwall("top", NULL);
  else if (!strcmp(t, "nw-twice"))
    swcs_nearwall("wall,wall", NULL);
  else if (!strcmp(t, "nw-closure"))
    swcs_nearwall("wall", "missing.coeffs");
}

void
cs_lagr_user_boundary_interaction(cs_lagr_particle_set_t    *particles,
                                  cs_lnum_t                  p_id,
                                  cs_lnum_t                  face_id,
                                  const cs_real_t            face_norm[3],
                                  const cs_real_t            c_intersect[3],
                                  cs_real_t                  t_intersect,
                                  int                        b_zone_id,
                                  int                       *event_flag,
                                  cs_lagr_tracking_state_t  *tracking_state)
{
  swcs_boundary_interaction(particles, p_id, face_id, face_norm, c_intersect,
                            t_intersect, b_zone_id, event_flag, tracking_state);
}

END_C_DECLS
