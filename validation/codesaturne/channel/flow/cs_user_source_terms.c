/* The deposition channel in Code_Saturne: the flow is held by the mean pressure
 * gradient dp/dx = rho u_tau^2 / h of Re_tau = u_tau h / nu = 314 (Liu &
 * Agarwal's Reynolds number, validation/deposition.sh), h = 6.35 mm, air. */
#include "cs_defs.h"
#include "cs_domain.h"
#include "cs_field.h"
#include "cs_field_pointer.h"
#include "cs_mesh_quantities.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_source_terms(cs_domain_t *domain, int f_id, cs_real_t *st_exp, cs_real_t *st_imp)
{
  CS_UNUSED(st_imp);
  if (f_id != CS_F_(vel)->id)
    return;
  const double h = 0.00635, nu = 1.5e-5, utau = 314 * nu / h, dpdx = 1.2 * utau * utau / h;
  const cs_real_t *vol = domain->mesh_quantities->cell_vol;
  for (cs_lnum_t c = 0; c < domain->mesh->n_cells; c++)
    st_exp[3*c] += dpdx * vol[c];
}

END_C_DECLS
