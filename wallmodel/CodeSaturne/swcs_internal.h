/* swcs_internal.h - between the two halves of the Code_Saturne binding (swcs.c,
 * swcs_nearwall.c); not for the case's own sources. */
#ifndef SWCS_INTERNAL_H
#define SWCS_INTERNAL_H

#include "cs_defs.h"
#include "cs_lagr_particle.h"

BEGIN_C_DECLS

/* 1 when swcs_zone named the boundary zone "snow" (the set-up is then closed). */
int swcs_is_snow_zone(int zone_id);

/* A particle the near-wall closure brings to boundary face face_id of snow
 * zone zone_id with the impact velocity u_imp: decided by the wall model and
 * booked like a tracked impact. Returns 1 when it sticks (flagged deposited and
 * to be deleted, counted in Code_Saturne's deposit counters), 0 when it bounces
 * or is ripped off (u_out: the core's rebound velocity). */
int swcs_closure_impact(cs_lagr_particle_set_t *particles, cs_lnum_t p_id, cs_lnum_t face_id,
                        int zone_id, const double u_imp[3], double u_out[3]);

/* From swcs_end_of_step: the closure's counts into the listing on an output step. */
void swcs_nearwall_end_of_step(int write);

END_C_DECLS
#endif
