/* The deposition channel in Code_Saturne, the particles: one-way, on the frozen
 * flow, Code_Saturne's Langevin model of the velocity seen (idistu 1), and with
 * CH_DEPO=1 (environment) its near-wall deposition model (Guingo & Minier). */
#include "cs_defs.h"

#include <stdlib.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"

BEGIN_C_DECLS

void
cs_user_lagr_model(void)
{
  cs_glob_lagr_time_scheme->iilagr = CS_LAGR_FROZEN_CONTINUOUS_PHASE;
  cs_glob_lagr_time_scheme->isuila = 0;
  cs_glob_lagr_time_scheme->t_order = 1;
  cs_glob_lagr_time_scheme->idistu = 1;
  cs_glob_lagr_time_scheme->idiffl = 0;
  cs_glob_lagr_time_scheme->modcpl = 0;
  cs_glob_lagr_model->physical_model = 0;
  const char *e = getenv("CH_DEPO");
  cs_glob_lagr_model->deposition = e ? atoi(e) : 0;
  cs_glob_lagr_model->n_stat_classes = 0;
}

END_C_DECLS
