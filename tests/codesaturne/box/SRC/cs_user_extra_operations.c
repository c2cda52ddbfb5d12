/* The box of tests/openfoam/box in Code_Saturne: SnowWall's counts and CSV
 * files at the end of each time step (written every swcs_output steps). */
#include "cs_defs.h"
#include "cs_domain.h"
#include "cs_prototypes.h"

#include "swcs.h"

BEGIN_C_DECLS

void
cs_user_extra_operations(cs_domain_t *domain)
{
  CS_UNUSED(domain);
  swcs_end_of_step();
}

END_C_DECLS
