/* The deposition channel in Code_Saturne (validation/codesaturne/channel.sh):
 * periodic along the flow (x) and across it (z), the walls at y = 0 and y = 2h. */
#include "cs_defs.h"
#include "cs_join_perio.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_periodicity(void)
{
  const double tx[3] = {0.00635, 0, 0}, tz[3] = {0, 0, 0.00635};
  cs_join_perio_add_translation("x < 1e-9 or x > 0.00634999", 0.1, 0.8, 0, 0, tx);
  cs_join_perio_add_translation("z < 1e-9 or z > 0.00634999", 0.1, 0.8, 0, 0, tz);
}

END_C_DECLS
