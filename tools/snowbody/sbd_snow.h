/* sbd_snow.h - the snow on a body from the wall model's stick records.
 *
 * snowWallInteraction's stickRecords write one line per stick (time, position,
 * origProc, origId, nParticle, d, rho) into
 * postProcessing/lagrangian/<cloud>/snowWallSticks/<time>/<patch>.post. From
 * them, over a counting window [t0, t1]:
 *
 *   - the deposited mass and its sampling variance. The independent draws are
 *     the injected parcels: the copies that parcel splitting makes of one
 *     parcel share its (origProc, origId) and their sticks are correlated, so
 *     the sticks are grouped by origin and the variance of the window's mass
 *     is the sum over origins of the square of each origin's mass (the
 *     compound-Poisson variance of rare arrivals: every origin reaches the
 *     wall or not, independently; the sums: tools/snowpost/spo_origin.h);
 *   - the same in the window's two halves (a statistically steady deposit
 *     gives halves that agree within their errors: z = (M2 - M1) / sqrt(V1 +
 *     V2));
 *   - the cumulative mass at any time of the window (the deposit against
 *     time);
 *   - a map of the mass per area on a rectangle of a face (bins in two
 *     coordinates of the position).
 *
 * The resolution ladder (sbd_ladder): one row per mesh level measured with
 * the same snow, the quantities' values and sampling errors and the run time;
 * the mesh error of a level is the relative change to the next finer level
 * (the finest level takes the change from the one below), and the total error
 * the root sum of squares of the sampling and mesh errors.
 *
 * Lifecycle: sbd_sticks_read appends one file's sticks to a growing array
 * (sbd_sticks_free frees it); the statistics are pure functions. Errors are
 * returned with a message; nothing prints or exits. */
#ifndef SBD_SNOW_H
#define SBD_SNOW_H

#include <stddef.h>

typedef struct {
    double t;          /* time of the stick [s] */
    double x[3];       /* position [m] */
    long proc, id;     /* the injected parcel it descends from */
    double mass;       /* nParticle x rho x pi d^3 / 6 [kg] */
} sbd_stick;

typedef struct {
    sbd_stick *s;
    size_t n, cap;
} sbd_sticks;

/* a finite number filling the whole of tok, into *v: 1, else 0 (an
 * overflowing one refused without raising the overflow exception) */
int sbd_number(const char *tok, double *v);

/* append the sticks of one .post file (header line '# Time (position0 ...)'
 * naming the columns; a file with the header only is fine): 0, or -1 with a
 * message naming the file and line (unreadable, a missing column, a value
 * that is not a finite number, a negative mass or diameter) */
int sbd_sticks_read(sbd_sticks *st, const char *path, char *err, size_t errlen);
void sbd_sticks_free(sbd_sticks *st);

typedef struct {
    double mass;          /* in [t0, t1] [kg] */
    double var;           /* its sampling variance [kg^2] */
    double half[2];       /* in [t0, tm] and (tm, t1] */
    double half_var[2];
    size_t sticks;        /* sticks in the window */
    size_t origins;       /* distinct injected parcels among them */
} sbd_window_stat;

/* the statistics of the sticks with t0 < t <= t1 (the halves split at
 * (t0 + t1) / 2); 0, or -1 (t1 <= t0, or no memory) */
int sbd_window(const sbd_stick *s, size_t n, double t0, double t1, sbd_window_stat *out);

/* z of the halves' difference: (M2 - M1) / sqrt(V1 + V2); 0 when both are 0 */
double sbd_halves_z(const sbd_window_stat *w);

/* the map: mass per area [kg/m2] of the sticks in (t0, t1] in ny x nz bins of
 * the rectangle [y0, y1] x [z0, z1] of the coordinates (ia, ib) of x (0, 1
 * or 2), row-major map[j * ny + i] (i along a, j along b); a stick on the
 * rectangle's edge goes to the edge bin, one outside it is counted in
 * *outside. 0, or -1 on bad arguments. */
int sbd_map(const sbd_stick *s, size_t n, double t0, double t1, int ia, int ib, double a0, double a1, int na,
            double b0, double b1, int nb, double *map, size_t *outside);

/* ---- the resolution ladder ------------------------------------------------ */
#define SBD_LADDER_MAX 8
#define SBD_LADDER_Q 2   /* the quantities: 0 the rear face, 1 the sensor */

typedef struct {
    char level[32];
    long cells;
    double seconds;               /* the whole run: mesh, flow and snow [s] */
    double value[SBD_LADDER_Q];   /* [kg/m2] */
    double rel[SBD_LADDER_Q];     /* relative sampling error (1 sigma) */
} sbd_ladder_row;

typedef struct {
    int n;
    sbd_ladder_row row[SBD_LADDER_MAX];   /* coarse to fine (cells ascending) */
} sbd_ladder;

/* read the ladder CSV: '#' comment lines, a header line
 * 'level,cells,seconds,rear_kg_m2,rear_rel,sensor_kg_m2,sensor_rel', then one
 * row per level, cells strictly ascending, values positive and finite, at
 * least two rows: 0, or -1 with a message naming the file and line */
int sbd_ladder_read(const char *path, sbd_ladder *l, char *err, size_t errlen);
/* the row of a level, or -1 */
int sbd_ladder_find(const sbd_ladder *l, const char *level);
/* The errors of every row for quantity q by the one rule of the project's
 * resolution ladders (swg_discretization, validation/convergence/swg_ladder.h,
 * cell size cells^(-1/3), the schemes' order 2): Richardson where the levels
 * resolve a monotone trend, else a bound over the finest value and the
 * extrapolation of the finest pair. All relative to the reference. */
typedef struct {
    double ref;                      /* the reference [kg/m2]                      */
    const char *kind;                /* "extrapolated" or "bound"                  */
    double disc[SBD_LADDER_MAX];     /* per row: discretization error / |ref|      */
    double sampling[SBD_LADDER_MAX]; /* per row: rel value / |ref|                 */
    double total[SBD_LADDER_MAX];    /* per row: sqrt(sampling^2 + disc^2)         */
} sbd_ladder_error;
/* 0, or -1 with a message (a ladder the rule refuses, a reference of 0) */
int sbd_ladder_disc(const sbd_ladder *l, int q, sbd_ladder_error *e, char *err, size_t errlen);

#endif
