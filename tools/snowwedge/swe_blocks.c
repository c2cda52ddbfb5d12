/* swe_blocks.c - the rear face's deposit on a grid of blocks chosen from its
 * sampling error (swe_blocks.h). */
#include "swe_blocks.h"

#include "spo_origin.h"
#include "swe_spray.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* the cell of t in [0, 1) of nb cells, the outside to the nearest */
static int cell_of(double t, int nb)
{
    if (isnan(t) || t <= 0)
        return 0;
    const double c = floor(t * nb);
    return c >= nb ? nb - 1 : (int)c;
}

static int fail(char *err, size_t errlen, int code, const char *what)
{
    if (err && errlen)
        snprintf(err, errlen, "%s", what);
    return code;
}

int swe_blocks(const swe_block_class *c, size_t nc, const double o[4], int nb, swe_block *out,
               char *err, size_t errlen)
{
    if (!(o[1] > o[0] && o[3] > o[2])) {
        if (err && errlen)
            snprintf(err, errlen, "the face's outline %g..%g x %g..%g is empty", o[0], o[1], o[2],
                     o[3]);
        return SWE_EINVAL;
    }
    if (nb < 1 || nb > 4096)
        return fail(err, errlen, SWE_EINVAL, "the blocks across the face are not 1 .. 4096");
    const double dy = (o[1] - o[0]) / nb, dz = (o[3] - o[2]) / nb, area = dy * dz;
    for (int j = 0; j < nb; j++)
        for (int i = 0; i < nb; i++)
            out[j * nb + i] = (swe_block){o[0] + i * dy, o[0] + (i + 1) * dy, o[3] - (j + 1) * dz,
                                          o[3] - j * dz, 0, 0, 0, 0};
    size_t most = 0;
    for (size_t k = 0; k < nc; k++) {
        if (!isfinite(c[k].scale) || c[k].scale < 0) {
            if (err && errlen)
                snprintf(err, errlen, "class %zu: the scale %g is not a finite number >= 0", k + 1,
                         c[k].scale);
            return SWE_EINVAL;
        }
        most = c[k].n > most ? c[k].n : most;
    }
    spo_record *t = most ? malloc(most * sizeof *t) : NULL;
    spo_bin *bin = malloc((size_t)nb * nb * sizeof *bin);
    if ((most && !t) || !bin) {
        free(t);
        free(bin);
        return fail(err, errlen, SWE_ENOMEM, "out of memory");
    }
    for (size_t k = 0; k < nc; k++) {
        /* the class's mass and sum over origins of the origin's mass squared, per block */
        for (size_t i = 0; i < c[k].n; i++) {
            const swe_record *r = &c[k].rec[i];
            const int bi = cell_of((r->y - o[0]) / (o[1] - o[0]), nb),
                      bj = cell_of((o[3] - r->z) / (o[3] - o[2]), nb);
            t[i] = (spo_record){bj * nb + bi, 0, r->proc, r->id, r->mass};
        }
        if (spo_origin_bins(t, c[k].n, nb * nb, bin, err, errlen)) {
            free(t);
            free(bin);
            return SWE_EINVAL;
        }
        /* D_kb = s M / A, its variance D_kb^2 / n_eff = (s / A)^2 sum_a W_a^2 */
        const double f = c[k].scale / area;
        for (int b = 0; b < nb * nb; b++) {
            out[b].deposit += f * bin[b].mass;
            out[b].var += f * f * bin[b].s2;
            out[b].records += bin[b].n;
        }
    }
    for (int b = 0; b < nb * nb; b++)
        out[b].rel = out[b].deposit > 0 ? sqrt(out[b].var) / out[b].deposit : 0;
    free(t);
    free(bin);
    return 0;
}

double swe_blocks_rms(const swe_block *b, int nb)
{
    double w = 0, s = 0;
    for (int i = 0; i < nb * nb; i++)
        if (b[i].deposit > 0) {
            w += b[i].deposit;
            s += b[i].deposit * b[i].rel * b[i].rel;
        }
    return w > 0 ? sqrt(s / w) : INFINITY;
}

int swe_blocks_grid(const swe_block_class *c, size_t nc, const double o[4], int nmax,
                    double target, int *nb, double *rms, char *err, size_t errlen)
{
    if (nmax < 1 || nmax > 4096)
        return fail(err, errlen, SWE_EINVAL, "the finest grid is not 1 .. 4096 blocks across");
    if (!isfinite(target) || target <= 0)
        return fail(err, errlen, SWE_EINVAL, "the target error is not a positive number");
    swe_block *b = malloc((size_t)nmax * nmax * sizeof *b);
    if (!b)
        return fail(err, errlen, SWE_ENOMEM, "out of memory");
    *nb = 1;
    *rms = INFINITY;
    for (int n = 1; n <= nmax; n++) {
        const int rc = swe_blocks(c, nc, o, n, b, err, errlen);
        if (rc) {
            free(b);
            return rc;
        }
        const double e = swe_blocks_rms(b, n);
        if (n == 1 || e <= target) {
            *nb = n;
            *rms = e;
        }
    }
    free(b);
    return 0;
}
