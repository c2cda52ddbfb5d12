/* swi_homography.h - plane projective map from 4 point pairs (the 8x8 system,
 * solved with GSL's LU decomposition).
 *
 *   x' = (h0 x + h1 y + h2) / (h6 x + h7 y + 1)
 *   y' = (h3 x + h4 y + h5) / (h6 x + h7 y + 1)      (h8 = 1)
 */
#ifndef SWI_HOMOGRAPHY_H
#define SWI_HOMOGRAPHY_H
#include <stddef.h>

/* H (9 numbers, h8 = 1) mapping src[i] -> dst[i], i = 0..3. Fails (non-zero,
 * message in err) when a coordinate is not finite or the points are degenerate
 * (three collinear, singular system). */
int swi_homography_solve(const double src[4][2], const double dst[4][2], double H[9],
                         char *err, size_t errlen);

/* Apply H to (x, y). Returns non-zero when the point maps to infinity. */
int swi_homography_apply(const double H[9], double x, double y, double *xo, double *yo);

#endif
