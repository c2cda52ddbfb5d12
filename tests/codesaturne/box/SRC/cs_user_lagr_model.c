/* The box of tests/openfoam/box in Code_Saturne: one-way coupled particles,
 * no turbulent dispersion (laminar flow), first-order scheme, no deposition
 * model of Code_Saturne's own (SnowWall decides at the wall). */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_lagr_model(void)
{
  cs_glob_lagr_time_scheme->iilagr = CS_LAGR_ONEWAY_COUPLING;
  cs_glob_lagr_time_scheme->isuila = 0;
  cs_glob_lagr_time_scheme->isttio = 0;
  cs_glob_lagr_time_scheme->t_order = 1;
  cs_glob_lagr_time_scheme->idistu = 0;
  cs_glob_lagr_time_scheme->idiffl = 0;
  cs_glob_lagr_time_scheme->modcpl = 0;
  cs_glob_lagr_model->physical_model = 0;
  cs_glob_lagr_model->deposition = 0;
  cs_glob_lagr_model->resuspension = 0;
  cs_glob_lagr_model->clogging = 0;
  cs_glob_lagr_model->roughness = 0;
  cs_glob_lagr_model->dlvo = 0;
  cs_glob_lagr_model->n_stat_classes = 0;
  /* the near-wall model's set-up errors (SWCS_BOX=nw-...; nw-order forgets
     swcs_nearwall_model) */
  const char *t = getenv("SWCS_BOX");
  if (t && !strncmp(t, "nw-", 3) && strcmp(t, "nw-order"))
    swcs_nearwall_model();
}

END_C_DECLS
