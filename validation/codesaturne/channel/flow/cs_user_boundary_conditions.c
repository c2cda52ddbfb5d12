/* The deposition channel in Code_Saturne: every boundary face left after the
 * periodic joining is a smooth wall (Code_Saturne's wall function). */
#include "cs_defs.h"
#include "cs_mesh.h"
#include "cs_parameters.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_boundary_conditions(int nvar, int bc_type[], int icodcl[], cs_real_t rcodcl[])
{
  CS_UNUSED(nvar);
  CS_UNUSED(icodcl);
  CS_UNUSED(rcodcl);
  for (cs_lnum_t f = 0; f < cs_glob_mesh->n_b_faces; f++)
    bc_type[f] = CS_SMOOTHWALL;
}

END_C_DECLS
