/* swr_internal.h - the model struct shared by the kernel's files (not installed). */
#ifndef SWR_INTERNAL_H
#define SWR_INTERNAL_H

#include "swr_collide.h"
#include "swr_wall.h"

/* Step bound: this many contact times t_c (swr_collide.c) */
#define SWR_CONTACT_TIMES_MAX 24.0

/* Rough wall (swr_rough.c): bound on the free flights between contacts of
 * one impact (the time in contact is bounded by the key rough_hold). */
#define SWR_ROUGH_FLIGHTS_MAX 10000L
/* The rough wall's longest step, in steps h0 of the reference contact
 * (swr_rough.c, step_size). */
#ifndef SWR_ROUGH_STRETCH
#define SWR_ROUGH_STRETCH 8.0
#endif
/* After this many contact times in contact a sphere is held (the impact is
 * over) and the step is SWR_ROUGH_HELD times longer (swr_rough.c, step_size):
 * measured on 7 680 impacts and on a sparse lattice, the same outcomes as
 * without (doc/kernel.md). */
#ifndef SWR_ROUGH_SETTLE
#define SWR_ROUGH_SETTLE 4.0
#endif
#ifndef SWR_ROUGH_HELD
#define SWR_ROUGH_HELD 6.0
#endif

struct swr_model {
    swr_params p;
    swr_wall wall;
    double Estar;        /* particle-wall E* */
    double Gstar;        /* particle-wall G* (Mindlin) */
    int adhesive;        /* JKR with gamma > 0 */
    double alpha_const;  /* dashpot alpha of a constant COR (root-found) */
    double e_min;        /* smallest COR of the dashpot table */
};

/* The impact on a rough wall (wall lattice); swr_collide dispatches to it. */
swr_status swr_collide_rough(const swr_model *m, const swr_impact *in, swr_result *r,
                             const swr_trace *trace);

#endif
