/* swf.c - the flux-consistent (RT0) velocity in a cell (swf.h): a hexahedron
 * from its six faces, any other cell in the tetrahedra around its centre; the
 * guard against a tracking loop that does not advance. */
#include "swf.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>

#include <math.h>
#include <stdlib.h>

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

/* The pair vectors e_k and V_E = e_0 . (e_1 x e_2); 0 for a degenerate cell. */
static double frame(const swf_hex *h, double e[3][3])
{
    double len = 1.0;
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < 3; i++) e[k][i] = h->c_hi[k][i] - h->c_lo[k][i];
        len *= sqrt(dot(e[k], e[k]));
    }
    double c[3];
    cross(e[1], e[2], c);
    const double v = dot(e[0], c);
    if (!(len > 0) || !(fabs(v) > 1e-9 * len)) return 0.0;
    return v;
}

static int finite_hex(const swf_hex *h)
{
    for (int k = 0; k < 3; k++) {
        if (!isfinite(h->phi_lo[k]) || !isfinite(h->phi_hi[k])) return 0;
        for (int i = 0; i < 3; i++)
            if (!isfinite(h->c_lo[k][i]) || !isfinite(h->c_hi[k][i])) return 0;
    }
    return 1;
}

int swf_hex_velocity(const swf_hex *h, const double x[3], double u[3])
{
    if (!h || !x || !u || !finite_hex(h) || !isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
        return SWF_EINVAL;
    double e[3][3];
    const double v = frame(h, e);
    if (v == 0.0) return SWF_EDEGENERATE;
    /* the origin: the mean of the six face centres (the centre of a
       parallelepiped), so that xi_k = e^k . (x - x0) + 1/2 */
    double x0[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) x0[i] += (h->c_lo[k][i] + h->c_hi[k][i]) / 6.0;
    const double r[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    double out[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        double dual[3];   /* e^k = (e_{k+1} x e_{k+2}) / V_E: e^k . e_j = delta_kj */
        cross(e[(k + 1) % 3], e[(k + 2) % 3], dual);
        double xi = dot(dual, r) / v + 0.5;
        xi = xi < 0.0 ? 0.0 : (xi > 1.0 ? 1.0 : xi);
        const double f = -(1.0 - xi) * h->phi_lo[k] + xi * h->phi_hi[k];
        for (int i = 0; i < 3; i++) out[i] += f * e[k][i] / fabs(v);
    }
    u[0] = out[0];
    u[1] = out[1];
    u[2] = out[2];
    return SWF_OK;
}

double swf_hex_divergence(const swf_hex *h)
{
    double e[3][3];
    if (!h || !finite_hex(h)) return NAN;
    const double v = frame(h, e);
    if (v == 0.0) return NAN;
    double s = 0.0;
    for (int k = 0; k < 3; k++) s += h->phi_lo[k] + h->phi_hi[k];
    return s / fabs(v);
}

double swf_hex_imbalance(const swf_hex *h)
{
    if (!h || !finite_hex(h)) return NAN;
    double s = 0.0, a = 0.0;
    for (int k = 0; k < 3; k++) {
        s += h->phi_lo[k] + h->phi_hi[k];
        a += fabs(h->phi_lo[k]) + fabs(h->phi_hi[k]);
    }
    return a > 0.0 ? fabs(s) / a : 0.0;
}

/* ---- cells of any shape ---------------------------------------------------- */

typedef struct {
    long a, b;   /* the edge's point ids, a < b */
    int t, j;    /* the tetrahedron and the point of its triangle opposite the edge */
} edge_ref;

static int edge_cmp(const void *x, const void *y)
{
    const edge_ref *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return 0;
}

static void sub3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[0] - b[0];
    c[1] = a[1] - b[1];
    c[2] = a[2] - b[2];
}

/* the determinant of a 3 x 3 matrix, rows in m[0..2], m[3..5], m[6..8] */
static double det3(const double m[9])
{
    const double r0[3] = {m[0], m[1], m[2]}, r1[3] = {m[3], m[4], m[5]}, r2[3] = {m[6], m[7], m[8]};
    double c[3];
    cross(r1, r2, c);
    return dot(r0, c);
}

/* the area vector of the triangle x0 x1 x2 (right hand) */
static void area3(const double x0[3], const double x1[3], const double x2[3], double s[3])
{
    double e1[3], e2[3];
    sub3(x1, x0, e1);
    sub3(x2, x0, e2);
    cross(e1, e2, s);
    for (int i = 0; i < 3; i++) s[i] *= 0.5;
}

int swf_poly_fluxes(const swf_poly *c, double *F)
{
    if (!c || !F || !c->p || !c->id || !c->flux || c->n < 4 || c->n > SWF_POLY_MAX)
        return SWF_EINVAL;
    const int n = c->n;
    for (int i = 0; i < 3; i++)
        if (!isfinite(c->centre[i])) return SWF_EINVAL;
    for (int t = 0; t < n; t++) {
        if (!isfinite(c->flux[t])) return SWF_EINVAL;
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                if (!isfinite(c->p[3 * t + j][i])) return SWF_EINVAL;
    }
    const int ne = 3 * n / 2;
    if (3 * n % 2) return SWF_EDEGENERATE;   /* a closed triangulation has 3n/2 edges */
    double *vol = malloc((size_t)n * sizeof *vol);
    edge_ref *er = malloc((size_t)3 * n * sizeof *er);
    double *q = malloc((size_t)ne * sizeof *q), *w = malloc((size_t)ne * sizeof *w);
    int *t1 = malloc((size_t)ne * sizeof *t1), *t2 = malloc((size_t)ne * sizeof *t2);
    double *r = malloc((size_t)n * sizeof *r);
    gsl_matrix *L = n > 1 ? gsl_matrix_calloc((size_t)(n - 1), (size_t)(n - 1)) : NULL;
    int rc = SWF_OK;
    if (!vol || !er || !q || !w || !t1 || !t2 || !r || !L) {
        rc = SWF_EDEGENERATE;   /* out of memory: the host falls back */
        goto done;
    }
    /* volumes, the least-squares mean velocity of the boundary fluxes */
    double vtot = 0.0, qsum = 0.0, A[9] = {0}, b[3] = {0};
    for (int t = 0; t < n; t++) {
        const double *x0 = c->p[3 * t], *x1 = c->p[3 * t + 1], *x2 = c->p[3 * t + 2];
        double a0[3], a1[3], a2[3], s[3];
        sub3(x0, c->centre, a0);
        sub3(x1, c->centre, a1);
        sub3(x2, c->centre, a2);
        cross(a1, a2, s);
        vol[t] = dot(a0, s) / 6.0;
        vtot += vol[t];
        qsum += c->flux[t];
        area3(x0, x1, x2, s);
        const double m = sqrt(dot(s, s));
        if (m > 0.0) {
            for (int i = 0; i < 3; i++) {
                for (int k = 0; k < 3; k++) A[3 * i + k] += s[i] * s[k] / m;
                b[i] += s[i] * c->flux[t] / m;
            }
        }
    }
    if (!(vtot > 0.0)) {
        rc = SWF_EDEGENERATE;
        goto done;
    }
    double uc[3];
    {
        /* A uc = b by Cramer's rule (A is 3 x 3, symmetric, positive for a
           closed cell): the determinant of A with column k replaced by b */
        const double det = det3(A);
        if (!(fabs(det) > 0.0)) {
            rc = SWF_EDEGENERATE;
            goto done;
        }
        for (int k = 0; k < 3; k++) {
            double M[9];
            for (int i = 0; i < 9; i++) M[i] = A[i];
            for (int i = 0; i < 3; i++) M[3 * i + k] = b[i];
            uc[k] = det3(M) / det;
        }
    }
    /* the inner faces: the edges of the boundary, each in two triangles */
    for (int t = 0; t < n; t++)
        for (int j = 0; j < 3; j++) {
            const long u = c->id[3 * t + (j + 1) % 3], v = c->id[3 * t + (j + 2) % 3];
            er[3 * t + j] = (edge_ref){ u < v ? u : v, u < v ? v : u, t, j };
        }
    qsort(er, (size_t)3 * n, sizeof *er, edge_cmp);
    for (int e = 0; e < ne; e++) {
        const edge_ref *x = &er[2 * e], *y = &er[2 * e + 1];
        if (edge_cmp(x, y) != 0 || x->a == x->b || x->t == y->t
            || (2 * e + 2 < 3 * n && edge_cmp(y, &er[2 * e + 2]) == 0)) {
            rc = SWF_EDEGENERATE;   /* not a closed, two-manifold boundary */
            goto done;
        }
        t1[e] = x->t;
        t2[e] = y->t;
        /* the face (c, the edge's points), its area vector out of t1 */
        const double *pa = c->p[3 * x->t + (x->j + 1) % 3], *pb = c->p[3 * x->t + (x->j + 2) % 3];
        double s[3], g[3];
        area3(c->centre, pa, pb, s);
        /* out of t1: away from t1's own vertex opposite this face (its point j) */
        sub3(c->p[3 * x->t + x->j], c->centre, g);
        if (dot(s, g) > 0.0)
            for (int i = 0; i < 3; i++) s[i] = -s[i];
        const double s2 = dot(s, s);
        const double vv = fabs(vol[t1[e]]) + fabs(vol[t2[e]]);
        w[e] = s2 / (vv > 1e-300 ? vv : 1e-300);
        q[e] = dot(uc, s);
    }
    /* the residual of every tetrahedron's balance with the mean velocity's
       inner fluxes: r_t = sum(phi) V_t / V - phi_t - sum_e s_te q_e */
    for (int t = 0; t < n; t++) r[t] = qsum * vol[t] / vtot - c->flux[t];
    for (int e = 0; e < ne; e++) {
        r[t1[e]] -= q[e];
        r[t2[e]] += q[e];
    }
    /* the weighted Laplacian, the last tetrahedron's potential fixed at 0 */
    for (int e = 0; e < ne; e++) {
        const int a = t1[e], bb = t2[e];
        if (a < n - 1) *gsl_matrix_ptr(L, (size_t)a, (size_t)a) += w[e];
        if (bb < n - 1) *gsl_matrix_ptr(L, (size_t)bb, (size_t)bb) += w[e];
        if (a < n - 1 && bb < n - 1) {
            *gsl_matrix_ptr(L, (size_t)a, (size_t)bb) -= w[e];
            *gsl_matrix_ptr(L, (size_t)bb, (size_t)a) -= w[e];
        }
    }
    {
        gsl_error_handler_t *old = gsl_set_error_handler_off();
        gsl_vector_view rv = gsl_vector_view_array(r, (size_t)(n - 1));
        const int st = gsl_linalg_cholesky_decomp1(L);
        const int sv = st == 0 ? gsl_linalg_cholesky_svx(L, &rv.vector) : st;
        gsl_set_error_handler(old);
        if (sv != 0) {
            rc = SWF_EDEGENERATE;   /* the tetrahedra are not connected */
            goto done;
        }
        r[n - 1] = 0.0;   /* r now holds the potentials */
    }
    for (int t = 0; t < n; t++) F[4 * t] = c->flux[t];
    for (int e = 0; e < ne; e++) {
        const double qe = q[e] + w[e] * (r[t1[e]] - r[t2[e]]);
        if (!isfinite(qe)) {
            rc = SWF_EDEGENERATE;
            goto done;
        }
        F[4 * t1[e] + 1 + er[2 * e].j] = qe;
        F[4 * t2[e] + 1 + er[2 * e + 1].j] = -qe;
    }
done:
    free(vol);
    free(er);
    free(q);
    free(w);
    free(t1);
    free(t2);
    free(r);
    if (L) gsl_matrix_free(L);
    return rc;
}

int swf_tet_velocity(const double v[4][3], const double F[4], const double x[3], double u[3])
{
    if (!v || !F || !x || !u) return SWF_EINVAL;
    for (int i = 0; i < 4; i++) {
        if (!isfinite(F[i])) return SWF_EINVAL;
        for (int k = 0; k < 3; k++)
            if (!isfinite(v[i][k])) return SWF_EINVAL;
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(x[k])) return SWF_EINVAL;
    double e1[3], e2[3], e3[3], s[3];
    sub3(v[1], v[0], e1);
    sub3(v[2], v[0], e2);
    sub3(v[3], v[0], e3);
    cross(e2, e3, s);
    const double vol = fabs(dot(e1, s)) / 6.0;
    double lmax = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++) {
            double d[3];
            sub3(v[i], v[j], d);
            const double l = sqrt(dot(d, d));
            if (l > lmax) lmax = l;
        }
    if (!(vol > 1e-12 * lmax * lmax * lmax)) return SWF_EDEGENERATE;
    double out[3] = {0, 0, 0};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) out[k] += F[i] * (x[k] - v[i][k]) / (3.0 * vol);
    u[0] = out[0];
    u[1] = out[1];
    u[2] = out[2];
    return SWF_OK;
}

/* ---- a tracking loop that does not advance --------------------------------- */

void swf_stall_init(swf_stall *g)
{
    if (!g) return;
    g->who = NULL;
    g->start = g->last = 0.0;
    g->calls = 0;
    g->ended = 0;
}

int swf_stall_check(swf_stall *g, const void *who, double step_fraction)
{
    if (!g) return 0;
    const double f = isfinite(step_fraction) ? step_fraction : g->last;
    if (who != g->who || g->calls == 0 || f < g->last) {
        g->who = who;   /* another parcel, or a new step: a new window */
        g->start = f;
        g->calls = 0;
    }
    g->last = f;
    if (++g->calls < SWF_STALL_CALLS) return 0;
    const int stalled = !(f - g->start >= SWF_STALL_ADVANCE);
    g->start = f;
    g->calls = 0;
    if (stalled) {
        g->ended++;
        g->who = NULL;
    }
    return stalled;
}
