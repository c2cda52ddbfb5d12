/* The box of tests/openfoam/box in Code_Saturne: the seven particles of the
 * OpenFOAM box (constant/p1..p7 and kinematicCloudProperties there), and no
 * drag: the OpenFOAM box's parcels feel no force (particleForces {}), so here
 * the relaxation time is made so long (1e6 s) that the 0.1 s run changes
 * their velocity by less than 1e-7 of the fluid's slip. Test set-up, not
 * SnowWall: the binding does not touch the particles' motion. */
#include "cs_defs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bft_printf.h"
#include "cs_lagr.h"
#include "cs_math.h"
#include "cs_lagr_particle.h"
#include "cs_lagr_prototypes.h"
#include "cs_mesh.h"
#include "cs_mesh_quantities.h"
#include "cs_time_step.h"
#include "cs_volume_zone.h"

BEGIN_C_DECLS

static const double _box_x[7][3] = {
  {0.02, 0.07, 0.02}, {0.05, 0.07, 0.02}, {0.08, 0.07, 0.02}, {0.02, 0.02, 0.08},
  {0.05, 0.02, 0.08}, {0.03, 0.02, 0.05}, {0.08, 0.004, 0.08}};
static const double _box_u[7][3] = {
  {0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -2, 0}, {0, -2, 0}, {0.8, -1, 0}, {0, -0.1, 0}};
static const double _box_d[7] = {1e-5, 4e-5, 2e-5, 1e-5, 1.5e-5, 1e-5, 1e-5};

/* Injection places a particle at a random point of its zone (here the cell of
 * its start point), and Code_Saturne 6.0 restores that point after
 * cs_user_lagr_in: so the particles are injected at rest in the first time
 * step and put in the OpenFOAM box's places, in the same cell and so on the
 * same MPI rank, with its velocities, at the end of it. The run starts one step later than the
 * OpenFOAM box (21 steps; every time here is the OpenFOAM one + 5 ms). */
void
cs_user_lagr_in(cs_lagr_particle_set_t         *particles,
                const cs_lagr_injection_set_t  *zis,
                const cs_lnum_t                 particle_range[2],
                const cs_lnum_t                 particle_face_id[],
                const cs_real_t                 visc_length[])
{
  CS_UNUSED(particle_face_id);
  CS_UNUSED(visc_length);
  /* which of the seven: the name of its volume zone, p1 .. p7 */
  const cs_zone_t *z = cs_volume_zone_by_id(zis->zone_id);
  const int i = (z && z->name[0] == 'p') ? atoi(z->name + 1) - 1 : -1;
  if (i < 0 || i >= 7)
    return;
  for (cs_lnum_t p = particle_range[0]; p < particle_range[1]; p++) {
    const double d = _box_d[i];
    cs_real_t *u = cs_lagr_particles_attr(particles, p, CS_LAGR_VELOCITY);
    cs_real_t *us = cs_lagr_particles_attr(particles, p, CS_LAGR_VELOCITY_SEEN);
    for (int k = 0; k < 3; k++)
      u[k] = us[k] = 0;
    cs_lagr_particles_set_real(particles, p, CS_LAGR_DIAMETER, d);
    cs_lagr_particles_set_real(particles, p, CS_LAGR_MASS, 920.0 * cs_math_pi / 6 * d * d * d);
    cs_lagr_particles_set_real(particles, p, CS_LAGR_RANDOM_VALUE, (double)i);
  }
}

void
cs_user_lagr_extra_operations(const cs_real_t  dt[])
{
  CS_UNUSED(dt);
  cs_lagr_particle_set_t *particles = cs_glob_lagr_particle_set;
  if (cs_glob_time_step->nt_cur == cs_glob_time_step->nt_max) {
    /* the particles still in flight, for the test's comparison */
    for (cs_lnum_t p = 0; p < particles->n_particles; p++) {
      const cs_real_t *x = cs_lagr_particles_attr_const(particles, p, CS_LAGR_COORDS);
      const cs_real_t *u = cs_lagr_particles_attr_const(particles, p, CS_LAGR_VELOCITY);
      bft_printf("box particle p%d x %.9g %.9g %.9g U %.9g %.9g %.9g repositioned %d\n",
                 1 + (int)lround(cs_lagr_particles_get_real(particles, p, CS_LAGR_RANDOM_VALUE)),
                 x[0], x[1], x[2], u[0], u[1], u[2],
                 (int)cs_lagr_particles_get_lnum(particles, p, CS_LAGR_TR_REPOSITION));
    }
  }
  if (cs_glob_time_step->nt_cur != 1)
    return;
  const int nt = particles->p_am->n_time_vals;
  const char *e = getenv("SWCS_BOX");
  const int fast = e && strcmp(e, "fast") == 0;
  for (cs_lnum_t p = 0; p < particles->n_particles; p++) {
    const int i = (int)lround(cs_lagr_particles_get_real(particles, p, CS_LAGR_RANDOM_VALUE));
    if (i < 0 || i >= 7)
      continue;
    /* it was injected, at rest, in the cell that holds its point (its zone) */
    const cs_lnum_t best = cs_lagr_particles_get_lnum(particles, p, CS_LAGR_CELL_ID);
    for (int t = 0; t < nt; t++) {
      cs_real_t *x = cs_lagr_particles_attr_n(particles, p, t, CS_LAGR_COORDS);
      cs_real_t *u = cs_lagr_particles_attr_n(particles, p, t, CS_LAGR_VELOCITY);
      cs_real_t *us = cs_lagr_particles_attr_n(particles, p, t, CS_LAGR_VELOCITY_SEEN);
      for (int k = 0; k < 3; k++) {
        x[k] = _box_x[i][k];
        u[k] = us[k] = _box_u[i][k];
      }
      /* SWCS_BOX=fast (test_box.sh): p2 at 8 m/s, so that the step of its
         impact starts one cell above the wall's cells */
      if (i == 1 && fast)
        u[1] = us[1] = -8.0;
      cs_lagr_particles_set_lnum_n(particles, p, t, CS_LAGR_CELL_ID, best);
    }
  }
}

void
cs_user_lagr_rt(cs_lnum_t        id_p,
                cs_real_t        re_p,
                cs_real_t        uvwr,
                cs_real_t        rho_f,
                cs_real_t        rho_p,
                cs_real_t        nu_f,
                cs_real_t        taup[],
                const cs_real_t  dt[])
{
  CS_UNUSED(re_p);
  CS_UNUSED(uvwr);
  CS_UNUSED(rho_f);
  CS_UNUSED(rho_p);
  CS_UNUSED(nu_f);
  CS_UNUSED(dt);
  taup[id_p] = 1e6;
}

END_C_DECLS
