/* sbd_measure.c - the checks of a surface: closedness (every edge shared by
 * exactly two triangles running it in opposite directions), the enclosed
 * volume, the frontal area and the area per region. */
#include "sbd_body.h"
#include "swo_err.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct { size_t lo, hi; int forward; } sbd_edge;

static int cmp_edge(const void *pa, const void *pb)
{
    const sbd_edge *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return a->forward - b->forward;
}

int sbd_measure_surface(const sbd_surface *s, sbd_measure *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (s->nt == 0)
        return swo_fail(-1, err, errlen, "the surface has no triangle");
    sbd_edge *e = malloc(3 * s->nt * sizeof *e);
    if (!e)
        return swo_fail(-1, err, errlen, "out of memory measuring the surface");
    for (size_t t = 0; t < s->nt; t++) {
        for (int k = 0; k < 3; k++) {
            size_t a = s->t[t][k], b = s->t[t][(k + 1) % 3];
            if (a >= s->nv || b >= s->nv) {
                free(e);
                return swo_fail(-1, err, errlen, "triangle %zu names vertex %zu of %zu", t,
                                a >= s->nv ? a : b, s->nv);
            }
            e[3 * t + (size_t)k] = (sbd_edge){ a < b ? a : b, a < b ? b : a, a < b };
        }
        const double *p0 = s->v[s->t[t][0]], *p1 = s->v[s->t[t][1]], *p2 = s->v[s->t[t][2]];
        double u[3], w[3], n[3];
        for (int k = 0; k < 3; k++) { u[k] = p1[k] - p0[k]; w[k] = p2[k] - p0[k]; }
        n[0] = u[1] * w[2] - u[2] * w[1];
        n[1] = u[2] * w[0] - u[0] * w[2];
        n[2] = u[0] * w[1] - u[1] * w[0];   /* twice the area along the normal */
        double vol = (p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0])
                    + p0[2] * (p1[0] * p2[1] - p1[1] * p2[0])) / 6;
        int r = s->region[t];
        m->volume += vol;
        if (r >= 0 && r < SBD_NREGION)
            m->area[r] += sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
        if (r != SBD_STILTS) {
            m->body_volume += vol;
            m->frontal_area += fabs(n[0]) / 4;   /* half of |n_x| dA, dA = |n| / 2 */
        }
    }
    size_t ne = 3 * s->nt;
    qsort(e, ne, sizeof *e, cmp_edge);
    for (size_t i = 0; i < ne;) {
        size_t j = i, fwd = 0;
        while (j < ne && e[j].lo == e[i].lo && e[j].hi == e[i].hi) fwd += (size_t)e[j++].forward;
        size_t n = j - i;
        if (n > 2) m->nonmanifold++;
        else if (n == 1 || fwd != 1) m->open_edges++;
        i = j;
    }
    free(e);
    return 0;
}
