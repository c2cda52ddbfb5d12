/* The deposition channel in Code_Saturne, the Lagrangian model: the flow frozen,
 * one-way, first order; the near-wall treatment from CH_TREAT (default
 * langevin):
 *   langevin     Code_Saturne's Langevin model of the velocity seen (idistu 1)
 *   deposition   that with its deposition submodel (Guingo & Minier)
 *   nearwall     the C core's near-wall model with its sublayer closure
 *                (swcs_nearwall; Code_Saturne's own dispersion off)
 *   crw          the same without the closure */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "bft_error.h"
#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_lagr_model(void)
{
  const char *t = getenv("CH_TREAT");
  if (!t) t = "langevin";
  const int nearwall = !strcmp(t, "nearwall") || !strcmp(t, "crw");
  if (!nearwall && strcmp(t, "langevin") && strcmp(t, "deposition"))
    bft_error(__FILE__, __LINE__, 0, "CH_TREAT '%s' is not langevin, deposition, nearwall or crw\n", t);
  cs_glob_lagr_time_scheme->iilagr = CS_LAGR_FROZEN_CONTINUOUS_PHASE;
  cs_glob_lagr_time_scheme->isuila = 0;
  cs_glob_lagr_time_scheme->t_order = 1;
  cs_glob_lagr_time_scheme->idistu = nearwall ? 0 : 1;
  cs_glob_lagr_time_scheme->idiffl = 0;
  cs_glob_lagr_time_scheme->modcpl = 0;
  cs_glob_lagr_model->physical_model = 0;
  cs_glob_lagr_model->deposition = !strcmp(t, "deposition");
  cs_glob_lagr_model->n_stat_classes = 0;
  if (nearwall)
    swcs_nearwall_model();
}

END_C_DECLS
