/* The deposition channel in Code_Saturne: SnowWall's counts at the end of each step. */
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
