/* The box in Code_Saturne: no external force but, for the near-wall model's
 * set-up errors (SWCS_BOX=nw-nok), the near-wall model's force. */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "cs_lagr.h"
#include "cs_lagr_prototypes.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_lagr_ef(cs_real_t            dt_p,
                const cs_real_t      taup[],
                const cs_real_3_t    tlag[],
                const cs_real_3_t    piil[],
                const cs_real_33_t   bx[],
                const cs_real_t      tsfext[],
                const cs_real_33_t   vagaus[],
                const cs_real_3_t    gradpr[],
                const cs_real_33_t   gradvf[],
                cs_real_t            rho_p[],
                cs_real_3_t          fextla[])
{
  CS_UNUSED(tlag); CS_UNUSED(piil); CS_UNUSED(bx); CS_UNUSED(tsfext);
  CS_UNUSED(vagaus); CS_UNUSED(gradpr); CS_UNUSED(gradvf); CS_UNUSED(rho_p);
  const char *t = getenv("SWCS_BOX");
  if (t && !strcmp(t, "nw-nok"))
    swcs_nearwall_force(dt_p, taup, fextla);
}

END_C_DECLS
