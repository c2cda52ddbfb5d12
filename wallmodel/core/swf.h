/* swf.h - SnowWall flux-consistent velocity in a cell: the fluid velocity at a
 * point of a cell rebuilt from the volume fluxes through the cell's faces (the
 * lowest-order Raviart-Thomas field, RT0: on a hexahedron from its six faces,
 * on any other cell in the tetrahedra of the host's tracking), for particle
 * tracking that keeps tracers well mixed next to walls (doc/deposition.md,
 * "The tracking next to a wall").
 *
 * Why: a finite-volume solution knows the flux through every face exactly
 * (its continuity holds face by face) but the velocity only at cell centres.
 * The usual interpolation from cell and point values (OpenFOAM's cellPoint)
 * takes the wall's points at zero velocity, so in a cell next to a wall both
 * the tangential and the wall-normal velocity fall linearly to the wall; the
 * tangential flux that continuity needs is not there, the interpolated field
 * converges (its divergence is of the order of the cell's normal velocity over
 * its height) and tracers gather in a thin band at the wall, tenfold on a
 * wall-function mesh where the flow meets the wall. The field rebuilt here has
 *   u(x) = sum_k F_k(xi_k) e_k / |V_E|,
 *   F_k(xi) = (1 - xi) (-phi_lo,k) + xi phi_hi,k    (the flux along +e_k),
 * e_k = c_hi,k - c_lo,k the vector between the centres of the k-th pair of
 * opposite faces, V_E = e_0 . (e_1 x e_2), xi_k in [0, 1] the point's
 * coordinate along e_k (through the dual basis of e_0, e_1, e_2, from the
 * mean of the six face centres), phi the outward volume fluxes. On a
 * parallelepiped it is exact in three ways: its flux through each face is
 * that face's phi (so its normal component is continuous with the
 * neighbour's and zero on a wall, phi = 0 there), its divergence is
 * sum(phi) / V_E everywhere in the cell (zero where the flow's continuity
 * holds), and a velocity linear along its own direction (u_k depending on
 * xi_k alone: strain, stagnation flow) is reproduced; a shear across a cell
 * is seen as its mean (first order). On a cell that is not a parallelepiped
 * the three hold as far as the cell is one; xi is clipped to [0, 1].
 *
 * Pure functions, no state: thread-safe (swf_poly_fluxes allocates its
 * work space and frees it); the stall guard at the end holds its own state. */
#ifndef SWF_H
#define SWF_H

#ifdef __cplusplus
extern "C" {
#endif

enum { SWF_OK = 0, SWF_EINVAL = -1, SWF_EDEGENERATE = -2 };

/* One hexahedral cell as three pairs of opposite faces, k = 0, 1, 2. */
typedef struct {
    double c_lo[3][3];  /* centre of face lo of pair k [m]                        */
    double c_hi[3][3];  /* centre of face hi of pair k [m]                        */
    double phi_lo[3];   /* outward volume flux through face lo [m3/s] (0: a wall) */
    double phi_hi[3];   /* outward volume flux through face hi [m3/s]             */
} swf_hex;

/* The velocity u [m/s] at the point x [m] of the cell. SWF_EINVAL for a
 * non-finite input (u untouched), SWF_EDEGENERATE when the three pair vectors
 * are nearly coplanar (|V_E| below 1e-9 of |e_0| |e_1| |e_2|, or a pair's
 * centres coincide): the host falls back to its own interpolation. */
int swf_hex_velocity(const swf_hex *h, const double x[3], double u[3]);

/* The field's divergence sum(phi) / V_E [1/s] (NaN for a degenerate cell),
 * and the relative imbalance |sum(phi)| / sum(|phi|) (0 for a cell without
 * flux): how far the fluxes the host gives keep continuity. */
double swf_hex_divergence(const swf_hex *h);
double swf_hex_imbalance(const swf_hex *h);

/* ---- cells of any shape: the tetrahedra of the host's tracking ------------
 * A cell that is not a hexahedron is split, as OpenFOAM's tracking splits it,
 * into tetrahedra around a centre point c: one per triangle of its boundary
 * (each face fanned into triangles). The flux of each boundary triangle is
 * given (the host's face flux shared out over the face's triangles by their
 * area vectors, the same on both sides of the face); the fluxes through the
 * tetrahedra's inner faces (the triangles from c to every edge) are found so
 * that every tetrahedron has the cell's divergence, sum(phi) / V, and they
 * deviate least from those of the cell's mean velocity U_c (the least-squares
 * velocity of the face fluxes, exact for a uniform flow):
 *   minimise  sum_e (q_e - U_c . S_e)^2 (V_1 + V_2) / |S_e|^2
 *   subject to  the fluxes out of tetrahedron t sum to sum(phi) V_t / V,
 * a weighted graph Laplacian of the tetrahedra, solved by Cholesky (GSL).
 * In each tetrahedron the velocity is then the lowest-order Raviart-Thomas
 * field of its four fluxes F_i (F_i through the face opposite vertex v_i):
 *   u(x) = sum_i F_i (x - v_i) / (3 V_t),
 * whose normal component is constant on each face: continuous from one
 * tetrahedron to the next, from one cell to the next (the neighbour shares the
 * face's flux and triangles) and zero on a wall. A uniform flow is
 * reproduced exactly; otherwise the field is first order, as in the
 * hexahedron. */
#define SWF_POLY_MAX 1024   /* triangles of one cell at most */

typedef struct {
    int n;                    /* boundary triangles = tetrahedra, 4 .. SWF_POLY_MAX  */
    double centre[3];         /* the centre c the tetrahedra share [m]               */
    const double (*p)[3];     /* the triangles' points: p[3 t + j], j = 0, 1, 2, in
                                 the order that makes the triangle's normal point
                                 out of the cell [m]                                */
    const long *id;           /* an identity per point, id[3 t + j] (the host's
                                 point label): equal ids are the same point; every
                                 edge of the closed boundary is in two triangles    */
    const double *flux;       /* outward volume flux through each triangle [m3/s]  */
} swf_poly;

/* The four fluxes of every tetrahedron: F[4 t + 0] through its boundary
 * triangle (opposite c), F[4 t + 1 + j] through the inner face opposite the
 * triangle's point j; outward. F has 4 n values. Returns SWF_OK,
 * SWF_EINVAL (NULL, n out of range, a non-finite value) or SWF_EDEGENERATE
 * (the boundary is not closed with each edge in two triangles, a
 * tetrahedron of (nearly) zero volume, or the tetrahedra are not connected):
 * the host falls back to its own interpolation. */
int swf_poly_fluxes(const swf_poly *c, double *F);

/* The velocity u [m/s] at x [m] in the tetrahedron v[0..3] [m] with the
 * outward fluxes F[i] through the face opposite v[i] [m3/s]. SWF_EINVAL for
 * a non-finite input, SWF_EDEGENERATE for a tetrahedron of (nearly) zero
 * volume (below 1e-12 of its largest edge cubed). */
int swf_tet_velocity(const double v[4][3], const double F[4], const double x[3], double u[3]);

/* ---- a tracking loop that does not advance --------------------------------
 * A host's tracking moves a parcel through its time step in a loop of
 * sub-steps (each to the next face, a wall hit handled between two) that ends
 * when the parcel's step fraction reaches 1. A parcel that a wall sends back
 * without letting it move (a field pointing into the wall over part of a wall
 * face, a normal velocity of rounding size at a corner) would loop for ever.
 * swf_stall_check, called by the host once per sub-step or per wall hit with
 * the parcel's identity and its step fraction, watches windows of
 * SWF_STALL_CALLS consecutive calls of one parcel: a window over which the
 * fraction advanced by less than SWF_STALL_ADVANCE returns 1, and the host
 * ends the parcel's step where it is (its next step starts there). So no step
 * takes more than SWF_STALL_CALLS / SWF_STALL_ADVANCE calls (1e6), and a
 * parcel that moves normally is never stopped (a thousand sub-steps of one
 * parcel in one step would mean a thousand cells crossed). A call of another
 * parcel, or a smaller fraction (a new step), starts a new window. One guard
 * per loop (it holds the last parcel's identity, never dereferenced): not
 * shared between threads. */
#define SWF_STALL_CALLS   1000
#define SWF_STALL_ADVANCE 1e-3

typedef struct {
    const void *who;   /* the parcel of the current window (an identity only) */
    double start;      /* its step fraction at the window's start             */
    double last;       /* its step fraction at the last call                  */
    long calls;        /* calls in the window                                 */
    long ended;        /* steps ended, in all                                 */
} swf_stall;

/* A guard with no window and no step ended. */
void swf_stall_init(swf_stall *g);

/* 1: end the parcel's step now (counted in g->ended); 0: go on. A
 * non-finite fraction is no advance. */
int swf_stall_check(swf_stall *g, const void *who, double step_fraction);

#ifdef __cplusplus
}
#endif
#endif
