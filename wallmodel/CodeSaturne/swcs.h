/* swcs.h - SnowWall in Code_Saturne 6.0: the C core (sww.h) called from the
 * Lagrangian module's user boundary hook (doc/codesaturne.md).
 *
 * The case's user sources (SRC/) call, UDF style:
 *
 *   cs_user_lagr_boundary_conditions(bc_type):    (set-up; the calls after the
 *       swcs_regime("regime.coeffs");              first one are ignored)
 *       swcs_zone(bc_type, "wall", "snow");        snow: a wall zone the core decides
 *       swcs_zone(bc_type, "top", "escape");       escape: removed and counted
 *       swcs_tangential_gate(0.5, 5e-5, 0);        (optional, as sww.h)
 *       swcs_shear_gate_adhesion(0.01);            (optional)
 *       swcs_output(10);                           CSV every 10 steps and at the end
 *   cs_lagr_user_boundary_interaction(...same arguments...):
 *       swcs_boundary_interaction(...the same arguments...);
 *   cs_user_parameters(domain):                    (optional)
 *       swcs_deposit_field();                      the deposit as a boundary field
 *   cs_user_extra_operations(domain):
 *       swcs_end_of_step();                        listing lines and CSV files
 *
 * swcs_zone sets the zone's Lagrangian type to CS_LAGR_BC_USER. A zone left out
 * keeps the type the case gives it (Code_Saturne's own treatment: "none").
 * Every bad input stops the run through bft_error with one message naming the
 * input and its value: a regime file that does not load, an unknown zone name,
 * a snow zone whose faces are not walls (CS_SMOOTHWALL / CS_ROUGHWALL), an
 * unknown type word, a zone given twice, a gate value out of range, and an
 * impact on a CS_LAGR_BC_USER zone that swcs_zone did not name.
 */
#ifndef SWCS_H
#define SWCS_H

#include "cs_defs.h"
#include "cs_lagr_particle.h"
#include "cs_lagr_tracking.h"

BEGIN_C_DECLS

void swcs_regime(const char *path);
void swcs_zone(const int bc_type[], const char *zone, const char *type);
void swcs_tangential_gate(double vt_max, double d_ref, double exponent);
void swcs_shear_gate_adhesion(double roughness);
void swcs_shear_gate_constant(double tau_c);
void swcs_rebound_tangential(double e_t);
/* Counts (listing) and CSV files (snowwall/counts-<step>.csv,
 * snowwall/deposit-<step>.csv in the run folder) every `every` time steps and
 * at the last one; every >= 1 (default 1). */
void swcs_output(int every);
/* Optional, from cs_user_parameters (before the fields are allocated): a
 * boundary-face field SWCS_DEPOSIT_FIELD ("snowwall_deposit") with the deposit
 * [kg/m2] of each face, filled every step by swcs_end_of_step and written with
 * Code_Saturne's boundary post-processing (EnSight, ParaView). */
#define SWCS_DEPOSIT_FIELD "snowwall_deposit"
void swcs_deposit_field(void);
/* One listing line per impact (zone, face, time, point, normal, d, v_n, v_t,
 * tau_w, the random number, the fate) when on != 0 (default off). */
void swcs_verbose(int on);

void swcs_boundary_interaction(cs_lagr_particle_set_t    *particles,
                               cs_lnum_t                  p_id,
                               cs_lnum_t                  face_id,
                               const cs_real_t            face_norm[3],
                               const cs_real_t            c_intersect[3],
                               cs_real_t                  t_intersect,
                               int                        b_zone_id,
                               int                       *event_flag,
                               cs_lagr_tracking_state_t  *tracking_state);

void swcs_end_of_step(void);

/* Wall shear stress [Pa] at boundary face face_id, as the shear gate and the
 * near-wall model read it: |tangential part of the boundary force| / face area
 * when the solver computes "boundary_forces", else rho u*^2 from the wall's
 * "ustar"; the source is chosen at the first call, and a solver with neither
 * field stops the run (bft_error naming both). */
double swcs_wall_shear(cs_lnum_t face_id);

/* ---- the near-wall dispersion model of the C core (swd.h; swcs_nearwall.c) --
 * The turbulence a particle sees near the listed snow walls, from its own wall
 * distance (doc/deposition.md), instead of Code_Saturne's Langevin model, and
 * the sublayer closure's deposits decided by the wall model like impacts:
 *
 *   cs_user_lagr_model():
 *       cs_glob_lagr_time_scheme->idistu = 0;    the mean flow as the velocity seen
 *       swcs_nearwall_model();                   reserves 4 user variables per particle
 *                                                (the first free ones: w and its flag)
 *   cs_user_lagr_boundary_conditions(bc_type):   last: after the swcs_zone calls and
 *                                                the other set-up (it closes the set-up)
 *       swcs_nearwall("walls,floor", "deposition.coeffs");   snow zones, comma-separated;
 *                                                the closure's file ("" or NULL: the walk only)
 *       swcs_nearwall_scale("max");              optional, before: max, wallShear, turbulence
 *   cs_user_lagr_ef(dt_p, taup, ..., fextla):
 *       swcs_nearwall_force(dt_p, taup, fextla); the walk's kick as an external force
 *
 * The flow must have k and epsilon or omega (a RANS model). u_tau of a wall face
 * is read as swcs_wall_shear does. Each particle's wall is the face of the zones
 * nearest to its cell's centre (a grid search once, on each rank among its own
 * faces); y is its distance from that face's plane. Every bad set-up stops the
 * run through bft_error with one message: swcs_nearwall before
 * swcs_nearwall_model, a zone that is not a snow zone or is given twice, a
 * closure file that does not load, Code_Saturne's own dispersion on, no k. At
 * every output step the listing gets the closure's deposits per zone and their
 * expected number. */
void swcs_nearwall_model(void);
void swcs_nearwall(const char *zones, const char *closure);
void swcs_nearwall_scale(const char *name);
void swcs_nearwall_force(cs_real_t dt_p, const cs_real_t taup[], cs_real_3_t fextla[]);

END_C_DECLS
#endif
