/* swe_stats.c - rear-face regions, effective sample sizes, composition of
 * classes, halves' z-test (swe_stats.h). */
#include "swe_stats.h"

#include "spo_origin.h"
#include "swe_spray.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

const char *swe_region_name(int r)
{
    static const char *name[SWE_NREGION] = {"left side", "right side", "centre", "edges",
                                            "whole face"};
    return (r >= 0 && r < SWE_NREGION) ? name[r] : "?";
}

double swe_region_area(int r)
{
    static const double area[SWE_NREGION] = {0.25 * 0.8, 0.25 * 0.8, 0.3 * 0.4, 1 - 0.8 * 0.8, 1};
    return (r >= 0 && r < SWE_NREGION) ? area[r] : 0;
}

int swe_region_of(const double o[4], double y, double z)
{
    const double u = (y - o[0]) / (o[1] - o[0]), v = (o[3] - z) / (o[3] - o[2]);
    if (u < 0.1 || u > 0.9 || v < 0.1 || v > 0.9)
        return SWE_EDGES;
    if (u < 0.35)
        return SWE_LEFT;
    if (u > 0.65)
        return SWE_RIGHT;
    if (v >= 0.3 && v <= 0.7)
        return SWE_CENTRE;
    return -1;
}

int swe_rear_stats(const swe_record *rec, size_t n, const double o[4],
                   swe_region_stats out[SWE_NREGION], char *err, size_t errlen)
{
    for (int r = 0; r < SWE_NREGION; r++)
        out[r] = (swe_region_stats){0, 0, 0, 0};
    if (!(o[1] > o[0] && o[3] > o[2])) {
        if (err && errlen)
            snprintf(err, errlen, "the face's outline %g..%g x %g..%g is empty", o[0], o[1], o[2],
                     o[3]);
        return SWE_EINVAL;
    }
    if (n == 0)
        return 0;
    /* a record is in the whole face and in its region, if any: the bins are the regions */
    spo_record *t = malloc(2 * n * sizeof *t);
    if (!t)
        return SWE_ENOMEM;
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        t[m++] = (spo_record){SWE_FACE, 0, rec[i].proc, rec[i].id, rec[i].mass};
        const int r = swe_region_of(o, rec[i].y, rec[i].z);
        if (r >= 0)
            t[m++] = (spo_record){r, 0, rec[i].proc, rec[i].id, rec[i].mass};
    }
    spo_bin b[SWE_NREGION];
    const int rc = spo_origin_bins(t, m, SWE_NREGION, b, err, errlen);
    free(t);
    if (rc)
        return SWE_EINVAL;
    for (int r = 0; r < SWE_NREGION; r++)
        out[r] = (swe_region_stats){b[r].n, b[r].origins, b[r].mass, spo_neff(&b[r])};
    return 0;
}

void swe_compose(const swe_class *c, size_t n, double scale, double sum[SWE_NREGION],
                 double var[SWE_NREGION])
{
    for (int r = 0; r < SWE_NREGION; r++) {
        sum[r] = 0;
        var[r] = 0;
        for (size_t k = 0; k < n; k++) {
            const double m = scale * c[k].w * c[k].mass[r];
            sum[r] += m;
            if (c[k].neff[r] > 0)
                var[r] += m * m / c[k].neff[r];
        }
    }
}

int swe_stands_out(double region, double var, double face, int r)
{
    const double expect = face * swe_region_area(r);
    if (r == SWE_FACE || !(region + face > 0))
        return 0;
    if ((region - expect) * (region - expect) > 4 * (var + 1e-300))
        return region > expect ? 1 : -1;
    return 0;
}

double swe_ztest(double a, double va, double b, double vb, double *p)
{
    const double z = (va + vb > 0) ? (b - a) / sqrt(va + vb) : 0;
    if (p)
        *p = 2 * gsl_cdf_ugaussian_Q(fabs(z));
    return z;
}

double swe_time_for_error(double t, double e, double target)
{
    if (!(target > 0 && t > 0 && e > 0))
        return 0;
    const double r = e / target;
    return t * r * r;
}
