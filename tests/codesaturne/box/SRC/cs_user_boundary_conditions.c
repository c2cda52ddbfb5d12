/* The box of tests/openfoam/box in Code_Saturne: the flow's boundary types.
 * The Couette flow U_x = 2 y of the OpenFOAM box's frozen field: wall y = 0 at
 * rest, the top y = 0.1 a wall sliding at 0.2 m/s, x = 0 an inlet with the
 * linear profile, x = 0.1 an outlet, z = 0 and z = 0.1 symmetry planes.
 * (The particles' boundary types are set in cs_user_lagr_boundary_conditions.c.) */
#include "cs_defs.h"
#include "bft_mem.h"
#include "cs_field.h"
#include "cs_field_pointer.h"
#include "cs_mesh.h"
#include "cs_mesh_quantities.h"
#include "cs_parameters.h"
#include "cs_prototypes.h"
#include "cs_selector.h"

BEGIN_C_DECLS

void
cs_user_boundary_conditions(int         nvar,
                            int         bc_type[],
                            int         icodcl[],
                            cs_real_t   rcodcl[])
{
  CS_UNUSED(nvar);
  CS_UNUSED(icodcl);
  const cs_lnum_t nbf = cs_glob_mesh->n_b_faces;
  const cs_real_t *cog = cs_glob_mesh_quantities->b_face_cog;
  const int iu = cs_field_get_key_int(CS_F_(vel), cs_field_key_id("variable_id")) - 1;
  for (cs_lnum_t f = 0; f < nbf; f++) {
    const cs_real_t x = cog[3*f], y = cog[3*f + 1], z = cog[3*f + 2];
    if (y < 1e-6)
      bc_type[f] = CS_SMOOTHWALL;
    else if (y > 0.099999) {
      bc_type[f] = CS_SMOOTHWALL;
      rcodcl[iu*nbf + f] = 0.2;
    }
    else if (x < 1e-6) {
      bc_type[f] = CS_INLET;
      rcodcl[iu*nbf + f] = 2.0 * y;
      rcodcl[(iu + 1)*nbf + f] = 0.0;
      rcodcl[(iu + 2)*nbf + f] = 0.0;
    }
    else if (x > 0.099999)
      bc_type[f] = CS_OUTLET;
    else if (z < 1e-6 || z > 0.099999)
      bc_type[f] = CS_SYMMETRY;
  }
}

END_C_DECLS
