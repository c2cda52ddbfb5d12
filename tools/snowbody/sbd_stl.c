/* sbd_stl.c - the ASCII STL writer: each region a solid, the facet normal
 * from the triangle's winding (counter-clockwise seen from outside). */
#include "sbd_stl.h"
#include "swo_err.h"

#include <math.h>

int sbd_stl_write(const sbd_surface *s, FILE *f, char *err, size_t errlen)
{
    for (int r = 0; r < SBD_NREGION; r++) {
        size_t n = 0;
        for (size_t t = 0; t < s->nt; t++) n += s->region[t] == r;
        if (n == 0) continue;
        fprintf(f, "solid %s\n", sbd_region_name(r));
        for (size_t t = 0; t < s->nt; t++) {
            if (s->region[t] != r) continue;
            const double *p0 = s->v[s->t[t][0]], *p1 = s->v[s->t[t][1]], *p2 = s->v[s->t[t][2]];
            double u[3], w[3], nn[3];
            for (int k = 0; k < 3; k++) { u[k] = p1[k] - p0[k]; w[k] = p2[k] - p0[k]; }
            nn[0] = u[1] * w[2] - u[2] * w[1];
            nn[1] = u[2] * w[0] - u[0] * w[2];
            nn[2] = u[0] * w[1] - u[1] * w[0];
            double len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
            if (len > 0) for (int k = 0; k < 3; k++) nn[k] /= len;
            fprintf(f, "  facet normal %.9g %.9g %.9g\n    outer loop\n", nn[0], nn[1], nn[2]);
            for (int k = 0; k < 3; k++) {
                const double *p = s->v[s->t[t][k]];
                fprintf(f, "      vertex %.9g %.9g %.9g\n", p[0], p[1], p[2]);
            }
            fputs("    endloop\n  endfacet\n", f);
        }
        fprintf(f, "endsolid %s\n", sbd_region_name(r));
    }
    if (ferror(f))
        return swo_fail(-1, err, errlen, "writing the STL failed");
    return 0;
}
