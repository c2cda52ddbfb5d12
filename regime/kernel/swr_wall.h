/* swr_wall.h - wall geometry, kept apart from the contact laws.
 *
 * Two sub-models (key `wall`, swr_params.h):
 *
 *  - flat: the plane z = 0, normal +z. Its normal does not depend on where
 *    the sphere touches, which lets swr_collide.c integrate the normal motion
 *    in one dimension; R* = R.
 *
 *  - lattice: a rough wall of hemispherical asperities of the wall material,
 *    radius r (`asperity_r`), centred on the base plane z = 0 (or, with
 *    `asperity_shape sphere`, whole spheres resting on it, centred at z = r)
 *    at the nodes of
 *    a square or hexagonal lattice of spacing s (`lattice`, `asperity_spacing`,
 *    the nearest-neighbour distance). The random variant moves each asperity
 *    by a uniform offset of up to `asperity_jitter` s in x and in y and sinks
 *    it by a uniform depth in [0, `asperity_dz`]; the offsets come from a hash
 *    of (`wall_seed`, i, j), so the wall is one fixed, reproducible surface of
 *    infinite extent. The base plane between the asperities is itself a flat
 *    contact (R* = R). A sphere may touch several asperities at once; each
 *    contact has R* = R r / (R + r) and the normal from the asperity centre to
 *    the sphere centre (swr_rough.c integrates the motion in 3-D).
 *
 * Impact points: the horizontal position of the sphere centre when its lowest
 * point crosses the plane of the highest asperity tops (z = r). A regular
 * lattice is periodic: points sampled over its unit cell cover every impact.
 * A random lattice is not: swr_wall_sample_area gives a block of
 * SWR_WALL_RANDOM_CELLS x SWR_WALL_RANDOM_CELLS cells to sample over instead.
 */
#ifndef SWR_WALL_H
#define SWR_WALL_H

#include "swr_params.h"

typedef enum { SWR_WALL_FLAT = 0, SWR_WALL_LATTICE = 1 } swr_wall_type;

/* cells per side of the sampling block of a random lattice */
#define SWR_WALL_RANDOM_CELLS 16

typedef struct {
    swr_wall_type type;
    int hex;              /* 1 hexagonal, 0 square */
    double r;             /* asperity radius [m] */
    double s;             /* nearest-neighbour spacing [m] */
    double row;           /* row spacing: s (square), s sqrt(3)/2 (hexagonal) */
    double jitter;        /* largest lateral offset / s */
    double dz;            /* largest sinking depth [m] */
    double zc;            /* height of the asperity centres above the base plane
                             before sinking: 0 (hemispheres), r (whole spheres) [m] */
    unsigned long long seed;
} swr_wall;

typedef struct {
    double delta;     /* overlap, > 0 in compression */
    double n[3];      /* unit normal, from the wall into the sphere */
    double Rstar;     /* effective radius of the contact */
} swr_wall_contact;

/* Set the wall from the parameters (wall, lattice, asperity_*, wall_seed). */
void swr_wall_init(swr_wall *w, const swr_params *p);

/* Flat wall: contact of a sphere of radius R centred at pos. */
void swr_wall_contact_at(const swr_wall *w, const double pos[3], double R, swr_wall_contact *c);

/* Effective radius of a first contact of a sphere of radius R: R on a flat
 * wall, R r / (R + r) with an asperity of a lattice. */
double swr_wall_rstar(const swr_wall *w, double R);

/* Centre of asperity (i, j) of a lattice [m]. */
void swr_wall_asperity(const swr_wall *w, int i, int j, double c[3]);

/* Index ranges i0..i1 (for each row j) and j0..j1 holding every asperity
 * whose centre may lie in [xlo, xhi] x [ylo, yhi]; rows of a hexagonal
 * lattice are offset by s/2, so the i range is per row: swr_wall_row_range. */
void swr_wall_rows(const swr_wall *w, double ylo, double yhi, int *j0, int *j1);
void swr_wall_row_range(const swr_wall *w, int j, double xlo, double xhi, int *i0, int *i1);

/* Height of the highest asperity top possible (r, 2r for whole spheres; 0 for a
 * flat wall). */
double swr_wall_top(const swr_wall *w);

/* The rectangle [0, lx) x [0, ly) to sample impact points over: one unit cell
 * of a regular lattice, a block of SWR_WALL_RANDOM_CELLS^2 cells of a random
 * one (0 x 0 for a flat wall). */
void swr_wall_sample_area(const swr_wall *w, double *lx, double *ly);

#endif
