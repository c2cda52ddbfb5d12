/* swr_internal.h - the model struct shared by the kernel's files (not installed). */
#ifndef SWR_INTERNAL_H
#define SWR_INTERNAL_H

#include "swr_collide.h"
#include "swr_wall.h"

/* Step bound: this many contact times t_c (swr_collide.c) */
#define SWR_CONTACT_TIMES_MAX 24.0

struct swr_model {
    swr_params p;
    swr_wall wall;
    double Estar;        /* particle-wall E* */
    double Gstar;        /* particle-wall G* (Mindlin) */
    int adhesive;        /* JKR with gamma > 0 */
    double alpha_const;  /* dashpot alpha of a constant COR (root-found) */
    double e_min;        /* smallest COR of the dashpot table */
};

#endif
