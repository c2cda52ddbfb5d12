/* swi_homography.c - 4-point homography: the 8x8 linear system, GSL LU. */
#include "swi_homography.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdio.h>

int swi_homography_solve(const double src[4][2], const double dst[4][2], double H[9],
                         char *err, size_t errlen)
{
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 2; k++)
            if (!isfinite(src[i][k]) || !isfinite(dst[i][k])) {
                if (err)
                    snprintf(err, errlen, "homography: point %d is not finite", i + 1);
                return 2;
            }
    /* no three points collinear in either set (else the map is degenerate) */
    for (int s = 0; s < 2; s++) {
        const double(*p)[2] = s ? dst : src;
        double scale = 0;
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                double d = hypot(p[i][0] - p[j][0], p[i][1] - p[j][1]);
                if (d > scale) scale = d;
            }
        for (int i = 0; i < 4; i++) {
            int a = (i + 1) % 4, b = (i + 2) % 4;
            double cross = (p[a][0] - p[i][0]) * (p[b][1] - p[i][1]) -
                           (p[a][1] - p[i][1]) * (p[b][0] - p[i][0]);
            if (!(fabs(cross) > 1e-9 * scale * scale)) {
                if (err)
                    snprintf(err, errlen,
                             "homography: %s points %d, %d, %d are collinear (or coincide)",
                             s ? "target" : "source", i + 1, a + 1, b + 1);
                return 2;
            }
        }
    }
    gsl_matrix *A = gsl_matrix_calloc(8, 8);
    gsl_vector *b = gsl_vector_alloc(8), *h = gsl_vector_alloc(8);
    gsl_permutation *perm = gsl_permutation_alloc(8);
    int rc = 0;
    if (!A || !b || !h || !perm) {
        rc = 1;
        if (err) snprintf(err, errlen, "homography: out of memory");
        goto done;
    }
    for (int i = 0; i < 4; i++) {
        double x = src[i][0], y = src[i][1], X = dst[i][0], Y = dst[i][1];
        double r0[8] = {x, y, 1, 0, 0, 0, -x * X, -y * X};
        double r1[8] = {0, 0, 0, x, y, 1, -x * Y, -y * Y};
        for (int k = 0; k < 8; k++) {
            gsl_matrix_set(A, 2 * i, k, r0[k]);
            gsl_matrix_set(A, 2 * i + 1, k, r1[k]);
        }
        gsl_vector_set(b, 2 * i, X);
        gsl_vector_set(b, 2 * i + 1, Y);
    }
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int sign = 0;
    int st = gsl_linalg_LU_decomp(A, perm, &sign);
    double det = st ? 0 : gsl_linalg_LU_det(A, sign);
    if (!st && isfinite(det) && det != 0)
        st = gsl_linalg_LU_solve(A, perm, b, h);
    else
        st = GSL_ESING;
    gsl_set_error_handler(old);
    if (st) {
        rc = 2;
        if (err) snprintf(err, errlen, "homography: singular 8x8 system (%s)", gsl_strerror(st));
        goto done;
    }
    for (int k = 0; k < 8; k++) {
        H[k] = gsl_vector_get(h, (size_t)k);
        if (!isfinite(H[k])) {
            rc = 2;
            if (err) snprintf(err, errlen, "homography: non-finite coefficient h%d", k);
            goto done;
        }
    }
    H[8] = 1;
done:
    gsl_matrix_free(A);
    gsl_vector_free(b);
    gsl_vector_free(h);
    gsl_permutation_free(perm);
    return rc;
}

int swi_homography_apply(const double H[9], double x, double y, double *xo, double *yo)
{
    double w = H[6] * x + H[7] * y + H[8];
    if (!(fabs(w) > 1e-300))
        return 1;
    *xo = (H[0] * x + H[1] * y + H[2]) / w;
    *yo = (H[3] * x + H[4] * y + H[5]) / w;
    return !(isfinite(*xo) && isfinite(*yo));
}
