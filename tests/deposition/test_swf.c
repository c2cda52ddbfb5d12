/* test_swf.c - the flux-consistent velocity in a cell (wallmodel/core/swf.h)
 * against closed forms: on parallelepipeds the face fluxes it carries, its
 * divergence, the flows it reproduces, a wall; on a polyhedron of the kind
 * snappyHexMesh makes (a cube with one face split in four, side faces of five
 * points, three in a line) the tetrahedra's balances, their inner faces'
 * continuity, a uniform flow exactly and a strain to first order. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "swf.h"

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* A parallelepiped o + i a + j b + k c (i, j, k in [0, 1]): its face centres and
 * outward area vectors, pair k the faces normal to edge k. */
typedef struct {
    double o[3], edge[3][3];
    double s_hi[3][3];   /* outward area vector of face hi of pair k; lo: minus it */
} box;

static void box_make(box *b, const double o[3], const double a[3], const double bb[3],
                     const double c[3], swf_hex *h)
{
    for (int i = 0; i < 3; i++) {
        b->o[i] = o[i];
        b->edge[0][i] = a[i];
        b->edge[1][i] = bb[i];
        b->edge[2][i] = c[i];
    }
    double bc[3];
    cross(bb, c, bc);
    const double sg = dot(a, bc) > 0 ? 1.0 : -1.0;
    for (int k = 0; k < 3; k++) {
        const double *e1 = b->edge[(k + 1) % 3], *e2 = b->edge[(k + 2) % 3];
        double s[3];
        cross(e1, e2, s);
        for (int i = 0; i < 3; i++) {
            b->s_hi[k][i] = sg * s[i];
            h->c_lo[k][i] = o[i] + 0.5 * (e1[i] + e2[i]);
            h->c_hi[k][i] = h->c_lo[k][i] + b->edge[k][i];
        }
    }
}

/* the point at fractions f of the edges */
static void box_point(const box *b, const double f[3], double x[3])
{
    for (int i = 0; i < 3; i++)
        x[i] = b->o[i] + f[0] * b->edge[0][i] + f[1] * b->edge[1][i] + f[2] * b->edge[2][i];
}

/* the exact fluxes of a velocity linear in x (exact on a plane face: the
 * value at its centre times its area vector) */
typedef void (*field_fn)(const double x[3], double u[3]);
static void box_fluxes(const box *b, swf_hex *h, field_fn f)
{
    for (int k = 0; k < 3; k++) {
        double u[3];
        f(h->c_hi[k], u);
        h->phi_hi[k] = dot(u, b->s_hi[k]);
        f(h->c_lo[k], u);
        h->phi_lo[k] = -dot(u, b->s_hi[k]);
    }
}

static const double O[3] = {0.3, -1.2, 2.0};
static const double A[3] = {0.8, 0.1, 0.0};
static const double B[3] = {0.2, 0.5, 0.05};   /* a sheared, graded cell */
static const double C[3] = {0.0, -0.03, 0.3};

/* strain plus a uniform stream: u_k of the cell's own axes only */
static double ga[3], gb[3], gc[3];   /* the dual basis of A, B, C */
static void strain(const double x[3], double u[3])
{
    /* u = U0 + 2 (xi_a - .5) A - 1.5 (xi_b - .5) B - 0.5 (xi_c - .5) C: each
       component along its own edge linear in its own coordinate, div 0 */
    const double r[3] = {x[0] - O[0], x[1] - O[1], x[2] - O[2]};
    const double xa = dot(ga, r), xb = dot(gb, r), xc = dot(gc, r);
    for (int i = 0; i < 3; i++)
        u[i] = 0.7 * A[i] + 0.4 * B[i] - 0.2 * C[i] + 2.0 * xa * A[i] - 1.5 * xb * B[i] - 0.5 * xc * C[i];
}

static void dual_basis(void)
{
    double bc[3], ca[3], ab[3];
    cross(B, C, bc);
    cross(C, A, ca);
    cross(A, B, ab);
    const double v = dot(A, bc);
    for (int i = 0; i < 3; i++) {
        ga[i] = bc[i] / v;
        gb[i] = ca[i] / v;
        gc[i] = ab[i] / v;
    }
}

/* a flow the cell's own axes carry (strain along them, a stagnation flow) is
 * rebuilt exactly from its six fluxes, at any point of the cell */
static void reproduces_strain(void **s)
{
    (void)s;
    dual_basis();
    box b;
    swf_hex h;
    box_make(&b, O, A, B, C, &h);
    box_fluxes(&b, &h, strain);
    assert_true(fabs(swf_hex_divergence(&h)) < 1e-12);
    assert_true(swf_hex_imbalance(&h) < 1e-13);
    for (double f0 = 0; f0 <= 1.0; f0 += 0.25)
        for (double f1 = 0; f1 <= 1.0; f1 += 0.5)
            for (double f2 = 0.1; f2 <= 1.0; f2 += 0.4) {
                const double f[3] = {f0, f1, f2};
                double x[3], u[3], ref[3];
                box_point(&b, f, x);
                strain(x, ref);
                assert_int_equal(swf_hex_velocity(&h, x, u), SWF_OK);
                for (int i = 0; i < 3; i++) assert_true(fabs(u[i] - ref[i]) < 1e-12);
            }
}

/* whatever the fluxes (continuity or not), the field carries each face's
 * flux through it at every point of the face; its divergence, by central
 * differences, is sum(phi) / V; and a face of zero flux (a wall) has no
 * normal velocity on it */
static void carries_the_fluxes(void **s)
{
    (void)s;
    box b;
    swf_hex h;
    box_make(&b, O, A, C, B, &h);   /* a left-handed ordering of the edges */
    const double lo[3] = {0.3, 0.0, -0.2}, hi[3] = {-0.1, 0.45, 0.1};
    for (int k = 0; k < 3; k++) {
        h.phi_lo[k] = lo[k];
        h.phi_hi[k] = hi[k];
    }
    for (int k = 0; k < 3; k++)
        for (double p = 0.1; p < 1.0; p += 0.4)
            for (double q = 0.1; q < 1.0; q += 0.4) {
                double f[3];
                f[k] = 1.0;
                f[(k + 1) % 3] = p;
                f[(k + 2) % 3] = q;
                double x[3], u[3];
                box_point(&b, f, x);
                assert_int_equal(swf_hex_velocity(&h, x, u), SWF_OK);
                assert_true(fabs(dot(u, b.s_hi[k]) - h.phi_hi[k]) < 1e-12);
                f[k] = 0.0;
                box_point(&b, f, x);
                assert_int_equal(swf_hex_velocity(&h, x, u), SWF_OK);
                assert_true(fabs(-dot(u, b.s_hi[k]) - h.phi_lo[k]) < 1e-12);
                if (k == 1) assert_true(fabs(dot(u, b.s_hi[1])) < 1e-12);   /* the wall */
            }
    double vol_bc[3];
    cross(C, B, vol_bc);
    const double vol = fabs(dot(A, vol_bc));
    const double f[3] = {0.4, 0.6, 0.3};
    double x[3], div = 0.0;
    box_point(&b, f, x);
    for (int i = 0; i < 3; i++) {
        const double d = 1e-6;
        double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]}, up[3], um[3];
        xp[i] += d;
        xm[i] -= d;
        assert_int_equal(swf_hex_velocity(&h, xp, up), SWF_OK);
        assert_int_equal(swf_hex_velocity(&h, xm, um), SWF_OK);
        div += (up[i] - um[i]) / (2 * d);
    }
    assert_true(fabs(div - 0.55 / vol) < 1e-6 * 0.55 / vol);
    assert_true(fabs(swf_hex_divergence(&h) - 0.55 / vol) < 1e-12 * 0.55 / vol);
    assert_true(fabs(swf_hex_imbalance(&h) - 0.55 / 1.15) < 1e-14);
}

/* a shear across the cell is seen as its mean over the cell (first order) */
static void shear(const double x[3], double u[3])
{
    u[0] = 3.0 * x[1];
    u[1] = 0.0;
    u[2] = 0.0;
}
static void shear_is_the_mean(void **s)
{
    (void)s;
    const double o[3] = {0, 1, 0}, a[3] = {1, 0, 0}, bb[3] = {0, 0.2, 0}, c[3] = {0, 0, 1};
    box b;
    swf_hex h;
    box_make(&b, o, a, bb, c, &h);
    box_fluxes(&b, &h, shear);
    for (double f1 = 0; f1 <= 1.0; f1 += 0.25) {
        const double f[3] = {0.3, f1, 0.5};
        double x[3], u[3];
        box_point(&b, f, x);
        assert_int_equal(swf_hex_velocity(&h, x, u), SWF_OK);
        assert_true(fabs(u[0] - 3.3) < 1e-12 && fabs(u[1]) < 1e-12 && fabs(u[2]) < 1e-12);
    }
    /* outside the cell the coordinates are clipped: no extrapolated flux */
    const double far[3] = {5.0, 1.1, 0.5};
    double u[3];
    assert_int_equal(swf_hex_velocity(&h, far, u), SWF_OK);
    assert_true(fabs(u[0] - 3.3) < 1e-12);
}

/* bad input: an error code, the output untouched, never NaN */
static void bad_input(void **s)
{
    (void)s;
    box b;
    swf_hex h;
    box_make(&b, O, A, B, C, &h);
    for (int k = 0; k < 3; k++) h.phi_lo[k] = h.phi_hi[k] = 0.1;
    double u[3] = {7, 7, 7};
    const double nanx[3] = {NAN, 0, 0};
    assert_int_equal(swf_hex_velocity(&h, nanx, u), SWF_EINVAL);
    assert_true(u[0] == 7 && u[1] == 7 && u[2] == 7);
    assert_int_equal(swf_hex_velocity(NULL, O, u), SWF_EINVAL);
    h.phi_hi[2] = INFINITY;
    assert_int_equal(swf_hex_velocity(&h, O, u), SWF_EINVAL);
    assert_true(isnan(swf_hex_divergence(&h)) && isnan(swf_hex_imbalance(&h)));
    h.phi_hi[2] = 0.1;
    /* flat: the third pair's vector in the plane of the other two */
    for (int i = 0; i < 3; i++) {
        h.c_lo[2][i] = 0.0;
        h.c_hi[2][i] = A[i] + B[i];
    }
    assert_int_equal(swf_hex_velocity(&h, O, u), SWF_EDEGENERATE);
    assert_true(isnan(swf_hex_divergence(&h)));
    for (int i = 0; i < 3; i++) h.c_hi[2][i] = h.c_lo[2][i];
    assert_int_equal(swf_hex_velocity(&h, O, u), SWF_EDEGENERATE);
    assert_true(u[0] == 7 && u[1] == 7 && u[2] == 7);
}

/* ---- cells of any shape ---------------------------------------------------- */

/* The split cube: corners of [0,1]^3, the top face (z = 1) split at its edge
 * midpoints and its centre into four quadrilaterals; the four side faces hold
 * the midpoint of their top edge (five points, three in a line). Faces as
 * point-id lists, ordered so that the normal points out; fanned from their
 * first point as OpenFOAM fans a face from its base point. */
static const double P[14][3] = {
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},                  /* 0-3 bottom */
    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},                  /* 4-7 top corners */
    {0.5, 0, 1}, {1, 0.5, 1}, {0.5, 1, 1}, {0, 0.5, 1},          /* 8-11 top edge midpoints */
    {0.5, 0.5, 1}, {0, 0, 0}                                     /* 12 top centre */
};
static const int FACES[][6] = {
    /* n, points (outward, right hand) */
    {4, 0, 3, 2, 1},          /* bottom z = 0, normal -z */
    {4, 4, 8, 12, 11},        /* top, four quadrilaterals, normal +z */
    {4, 8, 5, 9, 12},
    {4, 12, 9, 6, 10},
    {4, 11, 12, 10, 7},
    {5, 0, 1, 5, 8, 4},       /* y = 0, normal -y */
    {5, 1, 2, 6, 9, 5},       /* x = 1, normal +x */
    {5, 2, 3, 7, 10, 6},      /* y = 1, normal +y */
    {5, 3, 0, 4, 11, 7},      /* x = 0, normal -x */
};
#define NFACE (int)(sizeof FACES / sizeof FACES[0])

typedef struct {
    int n;
    double p[3 * 64][3];
    long id[3 * 64];
    double flux[64];
} poly_cell;

/* the flux of the field through the triangle a b c: u at its centroid dotted
   with its area vector (exact for a linear field) */
static double tri_flux(field_fn f, const double a[3], const double b[3], const double c[3])
{
    double e1[3], e2[3], s[3], g[3], u[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = b[i] - a[i];
        e2[i] = c[i] - a[i];
        g[i] = (a[i] + b[i] + c[i]) / 3.0;
    }
    cross(e1, e2, s);
    f(g, u);
    return 0.5 * (u[0] * s[0] + u[1] * s[1] + u[2] * s[2]);
}

static void poly_make(poly_cell *pc, field_fn f)
{
    pc->n = 0;
    for (int k = 0; k < NFACE; k++) {
        const int m = FACES[k][0];
        for (int i = 1; i + 1 < m; i++) {
            const int ids[3] = {FACES[k][1], FACES[k][1 + i], FACES[k][2 + i]};
            for (int j = 0; j < 3; j++) {
                for (int d = 0; d < 3; d++) pc->p[3 * pc->n + j][d] = P[ids[j]][d];
                pc->id[3 * pc->n + j] = ids[j];
            }
            pc->flux[pc->n] = tri_flux(f, P[ids[0]], P[ids[1]], P[ids[2]]);
            pc->n++;
        }
    }
}

static void uniform(const double x[3], double u[3])
{
    (void)x;
    u[0] = 1.0;
    u[1] = -2.0;
    u[2] = 0.5;
}

static void plane_strain(const double x[3], double u[3])
{
    u[0] = 0.3 + (x[0] - 0.5);
    u[1] = -0.2 - (x[1] - 0.5);
    u[2] = 0.1;
}

static void swelling(const double x[3], double u[3])   /* div u = 3 */
{
    u[0] = x[0] - 0.5;
    u[1] = x[1] - 0.5;
    u[2] = x[2] - 0.5;
}

static swf_poly poly_view(const poly_cell *pc, const double centre[3])
{
    swf_poly c;
    c.n = pc->n;
    for (int i = 0; i < 3; i++) c.centre[i] = centre[i];
    c.p = (const double (*)[3])pc->p;
    c.id = pc->id;
    c.flux = pc->flux;
    return c;
}

static void tet_of(const poly_cell *pc, const double centre[3], int t, double v[4][3])
{
    for (int i = 0; i < 3; i++) v[0][i] = centre[i];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) v[1 + j][i] = pc->p[3 * t + j][i];
}

static double tet_volume(double v[4][3])
{
    double e1[3], e2[3], e3[3], s[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = v[1][i] - v[0][i];
        e2[i] = v[2][i] - v[0][i];
        e3[i] = v[3][i] - v[0][i];
    }
    cross(e2, e3, s);
    return (e1[0] * s[0] + e1[1] * s[1] + e1[2] * s[2]) / 6.0;
}

static const double CENTRE[3] = {0.5, 0.5, 0.48};

static void polyhedron_balances(void **s)
{
    (void)s;
    static poly_cell pc;
    double F[4 * 64];
    field_fn fields[] = {uniform, plane_strain, swelling};
    for (int k = 0; k < 3; k++) {
        poly_make(&pc, fields[k]);
        assert_int_equal(pc.n, 22);   /* 2 + 4 x 2 + 4 x 3 triangles */
        const swf_poly c = poly_view(&pc, CENTRE);
        assert_int_equal(swf_poly_fluxes(&c, F), SWF_OK);
        double total = 0.0;
        for (int t = 0; t < pc.n; t++) total += pc.flux[t];
        for (int t = 0; t < pc.n; t++) {
            double v[4][3];
            tet_of(&pc, CENTRE, t, v);
            const double out = F[4 * t] + F[4 * t + 1] + F[4 * t + 2] + F[4 * t + 3];
            /* every tetrahedron has the cell's divergence (the cube's volume is 1) */
            assert_float_equal(out, total * tet_volume(v), 1e-12);
            assert_float_equal(F[4 * t], pc.flux[t], 0.0);
        }
        /* every inner face: what leaves one tetrahedron enters the other */
        for (int t = 0; t < pc.n; t++)
            for (int j = 0; j < 3; j++) {
                const long a = pc.id[3 * t + (j + 1) % 3], b = pc.id[3 * t + (j + 2) % 3];
                int found = 0;
                for (int u = 0; u < pc.n && !found; u++)
                    for (int i = 0; i < 3 && !found; i++) {
                        const long x = pc.id[3 * u + (i + 1) % 3], y = pc.id[3 * u + (i + 2) % 3];
                        if (u != t && ((x == a && y == b) || (x == b && y == a))) {
                            assert_float_equal(F[4 * t + 1 + j], -F[4 * u + 1 + i], 1e-14);
                            found = 1;
                        }
                    }
                assert_true(found);
            }
    }
}

static void polyhedron_velocity(void **s)
{
    (void)s;
    static poly_cell pc;
    double F[4 * 64];
    /* a uniform flow: exact in every tetrahedron of non-zero volume */
    poly_make(&pc, uniform);
    swf_poly c = poly_view(&pc, CENTRE);
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_OK);
    int evaluated = 0, flat = 0;
    for (int t = 0; t < pc.n; t++) {
        double v[4][3], x[3], u[3], ue[3];
        tet_of(&pc, CENTRE, t, v);
        for (int i = 0; i < 3; i++) x[i] = 0.1 * v[0][i] + 0.2 * v[1][i] + 0.3 * v[2][i] + 0.4 * v[3][i];
        const int rc = swf_tet_velocity((const double (*)[3])v, &F[4 * t], x, u);
        if (rc == SWF_EDEGENERATE) {
            flat++;
            continue;
        }
        assert_int_equal(rc, SWF_OK);
        uniform(x, ue);
        for (int i = 0; i < 3; i++) assert_float_equal(u[i], ue[i], 1e-12);
        evaluated++;
    }
    assert_int_equal(flat, 0);   /* the fans from the first points have no flat triangle */
    assert_int_equal(evaluated, pc.n);
    /* a strain: first order, within the velocity change across the cell */
    poly_make(&pc, plane_strain);
    c = poly_view(&pc, CENTRE);
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_OK);
    double worst = 0.0;
    for (int t = 0; t < pc.n; t++) {
        double v[4][3], x[3], u[3], ue[3];
        tet_of(&pc, CENTRE, t, v);
        for (int i = 0; i < 3; i++) x[i] = 0.25 * (v[0][i] + v[1][i] + v[2][i] + v[3][i]);
        if (swf_tet_velocity((const double (*)[3])v, &F[4 * t], x, u) != SWF_OK) continue;
        plane_strain(x, ue);
        for (int i = 0; i < 3; i++) worst = fmax(worst, fabs(u[i] - ue[i]));
    }
    printf("polyhedron, plane strain: largest error at the tetrahedra's centroids %.3f "
           "(the velocity changes by 1 across the cell)\n", worst);
    assert_true(worst < 0.5);
}

static void polyhedron_refusals(void **s)
{
    (void)s;
    static poly_cell pc;
    double F[4 * 64];
    poly_make(&pc, uniform);
    swf_poly c = poly_view(&pc, CENTRE);
    /* an open boundary: one triangle left out */
    c.n = pc.n - 1;
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_EDEGENERATE);
    /* two triangles left out: an even count, still open */
    c.n = pc.n - 2;
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_EDEGENERATE);
    c = poly_view(&pc, CENTRE);
    c.n = 3;
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_EINVAL);
    c = poly_view(&pc, CENTRE);
    pc.flux[3] = NAN;
    assert_int_equal(swf_poly_fluxes(&c, F), SWF_EINVAL);
    assert_int_equal(swf_poly_fluxes(NULL, F), SWF_EINVAL);
    const double v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};   /* flat */
    const double q[4] = {0, 0, 0, 0}, x[3] = {0.2, 0.2, 0};
    double u[3];
    assert_int_equal(swf_tet_velocity(v, q, x, u), SWF_EDEGENERATE);
    const double xn[3] = {NAN, 0, 0};
    const double v2[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    assert_int_equal(swf_tet_velocity(v2, q, xn, u), SWF_EINVAL);
}

/* The stall guard: a parcel that does not advance has its step ended at the
 * window's last call; one that moves, even through a thousand faces in a
 * step, never; another parcel or a new step starts a new window. */
static void stall_guard(void **s)
{
    (void)s;
    swf_stall g;
    swf_stall_init(&g);
    int a, b;   /* two parcels: only their addresses are used */

    /* stuck at one fraction: ended at exactly the SWF_STALL_CALLS-th call */
    long n = 0;
    while (!swf_stall_check(&g, &a, 0.25)) {
        n++;
        assert_true(n < 10 * SWF_STALL_CALLS);
    }
    assert_int_equal(n + 1, SWF_STALL_CALLS);
    assert_int_equal(g.ended, 1);

    /* creeping by 1e-7 a call (Zeno): ended as well */
    double f = 0.3;
    n = 0;
    while (!swf_stall_check(&g, &a, f)) {
        f += 1e-7;
        n++;
        assert_true(n < 10 * SWF_STALL_CALLS);
    }
    assert_int_equal(n + 1, SWF_STALL_CALLS);
    assert_int_equal(g.ended, 2);

    /* a parcel crossing 5 000 faces in one step (2e-4 of the step each):
       two windows of 0.2, never stopped; then its next step (the fraction
       back at 0) starts afresh */
    swf_stall_init(&g);
    for (int step = 0; step < 2; step++)
        for (int i = 0; i < 5000; i++)
            assert_int_equal(swf_stall_check(&g, &b, i * 2e-4), 0);
    assert_int_equal(g.ended, 0);

    /* a stuck parcel whose window is broken by another parcel starts anew */
    swf_stall_init(&g);
    for (int i = 0; i < SWF_STALL_CALLS - 1; i++) assert_int_equal(swf_stall_check(&g, &a, 0.5), 0);
    assert_int_equal(swf_stall_check(&g, &b, 0.5), 0);
    for (int i = 0; i < SWF_STALL_CALLS - 1; i++) assert_int_equal(swf_stall_check(&g, &a, 0.5), 0);
    assert_int_equal(swf_stall_check(&g, &a, 0.5), 1);

    /* a non-finite fraction is no advance; NULL guard is a no-op */
    swf_stall_init(&g);
    int hit = 0;
    for (int i = 0; i < SWF_STALL_CALLS; i++) hit |= swf_stall_check(&g, &a, NAN);
    assert_int_equal(hit, 1);
    assert_int_equal(swf_stall_check(NULL, &a, 0.1), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reproduces_strain),
        cmocka_unit_test(carries_the_fluxes),
        cmocka_unit_test(shear_is_the_mean),
        cmocka_unit_test(bad_input),
        cmocka_unit_test(polyhedron_balances),
        cmocka_unit_test(polyhedron_velocity),
        cmocka_unit_test(polyhedron_refusals),
        cmocka_unit_test(stall_guard),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
