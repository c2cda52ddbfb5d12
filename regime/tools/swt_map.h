/* swt_map.h - the stick/bounce regime map over a diameter x normal-speed grid,
 * its interface d_crit(v_n), and a parallel loop helper.
 *
 * Lifecycle: swt_map_alloc(grid) -> swt_map_run(map, model, opts) simulates
 * every grid point with swr_collide (rows split over threads) ->
 * swt_interface_extract() -> swt_map_free().
 */
#ifndef SWT_MAP_H
#define SWT_MAP_H

#include "swr_collide.h"
#include "swt_vcrit.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int nd, nv;            /* grid size (diameters x normal speeds) */
    double dmin, dmax;     /* diameters [m], linearly spaced */
    double vmin, vmax;     /* normal speeds [m/s] */
    int vlog;              /* 1: speeds log-spaced, 0: linear */
} swt_grid;

typedef struct {
    swt_grid g;
    double *d;             /* [nd] */
    double *v;             /* [nv] */
    unsigned char *stick;  /* [nd*nv], index i*nv + j (i: diameter, j: speed): outcome */
    unsigned char *kept;   /* normal contact kept */
    unsigned char *status; /* swr_status of the point (0 ok, 1 step bound) */
    float *e_n, *e_t;      /* rebound CORs (0 when kept; e_t 0 when vt = 0); rough wall:
                              the mean over the bouncing impact points */
    float *p;              /* rough wall: stick fraction over `points` impact points
                              (stick = p >= the options' level); flat: stick as 0 / 1 */
    int points;            /* impact points per grid point (0: flat wall, one impact) */
    long collisions, steps, step_bound;
    long nstick;           /* points that stick */
    double seconds;        /* wall time of swt_map_run */
    char msg[200];         /* first kernel warning */
    struct swt_progress *progress; /* counts the impacts done by swt_map_run and
                              swt_interface_extract (swt_progress.h); NULL: none.
                              Set by the caller; not owned */
} swt_map;

typedef struct {
    int n;                 /* interface points */
    double *vn, *dcrit;    /* [n], vn increasing */
    int cols_all_stick;    /* speed columns where every diameter sticks */
    int cols_all_bounce;   /* ... where every diameter bounces */
    int cols_nonmono;      /* ... with more than one change along d */
    long collisions;       /* kernel calls of the refinement */
} swt_interface;

/* Run fn(ctx, k) for k = 0..n-1 on `threads` threads (k interleaved). */
int swt_parallel_for(int n, int threads, void (*fn)(void *ctx, int k), void *ctx);

/* Check a grid. 0 or -1 with a message naming the option and value. */
int swt_grid_check(const swt_grid *g, char *err, size_t errlen);
swt_map *swt_map_alloc(const swt_grid *g, char *err, size_t errlen);
void swt_map_free(swt_map *mp);
/* Simulate every grid point (outcome as o->full_stick; o->vt / o->tan_angle /
 * o->omega set the tangential motion); on a rough wall the stick fraction
 * over o->points impact points (swt_stick_fraction). 0, or -1 on a kernel error. */
int swt_map_run(swt_map *mp, const swr_model *m, const swt_vcrit_opts *o, int threads,
                char *err, size_t errlen);

/* Interface: in each speed column, the first stick -> bounce change along d,
 * refined by bisection in ln d to relative width o->rtol (refine = 1) or the
 * geometric midpoint of the two grid cells (refine = 0). On a rough wall
 * "sticks" is the stick count at o->level (swt_fraction_sticks), at the grid
 * from mp->p and in the bisection from the same impact points: the
 * p = level contour, for any level without a new map. */
int swt_interface_extract(const swt_map *mp, const swr_model *m, const swt_vcrit_opts *o,
                          int refine, int threads, swt_interface *it, char *err, size_t errlen);
void swt_interface_free(swt_interface *it);

#ifdef __cplusplus
}
#endif
#endif
