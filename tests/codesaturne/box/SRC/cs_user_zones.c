/* The box of tests/openfoam/box in Code_Saturne: boundary zones by position
 * (0.1 m cube; wall y = 0, top y = 0.1, sides the rest). */
#include "cs_defs.h"
#include "cs_boundary_zone.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_zones(void)
{
  cs_boundary_zone_define("wall", "y < 1e-6", 0);
  cs_boundary_zone_define("top", "y > 0.099999", 0);
  cs_boundary_zone_define("sides", "x < 1e-6 or x > 0.099999 or z < 1e-6 or z > 0.099999", 0);
}

END_C_DECLS
