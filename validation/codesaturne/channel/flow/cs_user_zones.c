/* The deposition channel in Code_Saturne: the two walls (y = 0, y = 2h = 0.0127 m)
 * are the boundary zone "walls" (the other faces are joined periodically). */
#include "cs_defs.h"
#include "cs_boundary_zone.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_zones(void)
{
  cs_boundary_zone_define("walls", "y < 1e-9 or y > 0.01269999", 0);
}

END_C_DECLS
