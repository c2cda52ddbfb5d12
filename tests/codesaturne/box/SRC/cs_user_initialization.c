/* The box of tests/openfoam/box in Code_Saturne: the flow starts as the
 * Couette profile U_x = 2 y (the OpenFOAM box's frozen field). */
#include "cs_defs.h"
#include "cs_domain.h"
#include "cs_field.h"
#include "cs_field_pointer.h"
#include "cs_mesh.h"
#include "cs_mesh_quantities.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_initialization(cs_domain_t *domain)
{
  const cs_lnum_t n = domain->mesh->n_cells;
  const cs_real_t *xc = domain->mesh_quantities->cell_cen;
  cs_real_t *u = CS_F_(vel)->val;
  for (cs_lnum_t c = 0; c < n; c++) {
    u[3*c] = 2.0 * xc[3*c + 1];
    u[3*c + 1] = 0.0;
    u[3*c + 2] = 0.0;
  }
}

END_C_DECLS
