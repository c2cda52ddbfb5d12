/* swe_blocks.h - the rear face's deposit on a grid of blocks as coarse as its
 * statistics need: per block the composed deposit and its sampling error,
 * and the choice of the grid from that error.
 *
 * The face [y0, y1] x [z0, z1] is cut into nb x nb equal blocks: column
 * i = floor(nb u), u = (y - y0) / (y1 - y0) across the face seen from behind,
 * row j = floor(nb v), v = (z1 - z) / (z1 - z0) down it (records on or beyond
 * the outline go to the nearest block); block (i, j) is index j nb + i.
 *
 * A class k of the spray (a per-diameter cloud) brings its records on the
 * face and a scale s_k (the composed deposit's kg per kg of its records:
 * its weight times its rear deposit over its records' mass). Its deposit in
 * block b is D_kb = s_k M_kb / A_b (M_kb the records' mass in the block, A_b
 * the block's area) with the relative variance 1 / n_eff_kb, n_eff the
 * effective sample size over independent origins (swe_stats.h). The block's
 * deposit is D_b = sum_k D_kb, its variance V_b = sum_k D_kb^2 / n_eff_kb, its
 * relative error e_b = sqrt(V_b) / D_b (blocks without a record: no value, no
 * error).
 *
 * The grid: the finest nb (1 .. nmax) whose deposit-weighted rms relative
 * error sqrt(sum_b D_b e_b^2 / sum_b D_b), the error of the block a typical
 * unit of snow lies in, is at most the target; nb = 1 when none is. A block
 * whose error exceeds twice the target holds no feature the statistics can
 * show (drawn without a value; the picture: swe_plot.h). Nothing here prints
 * or exits. */
#ifndef SWE_BLOCKS_H
#define SWE_BLOCKS_H

#include "swe_stats.h"

#include <stddef.h>

/* one class of the spray: its records on the face and their scale */
typedef struct {
    const swe_record *rec;
    size_t n;
    double scale; /* composed kg per kg of the records (>= 0) */
} swe_block_class;

/* one block */
typedef struct {
    double y0, y1, z0, z1; /* its outline */
    double deposit;        /* D_b [kg/m^2 of the composed deposit] */
    double var;            /* V_b */
    double rel;            /* e_b; 0 without a record */
    long records;          /* records in it, every class */
} swe_block;

/* the nb x nb blocks (out[nb * nb]) of the classes; 0, or SWE_EINVAL (empty
   outline, nb < 1, a negative or non-finite scale) or SWE_ENOMEM with a
   message in err */
int swe_blocks(const swe_block_class *c, size_t nc, const double outline[4], int nb,
               swe_block *out, char *err, size_t errlen);

/* the deposit-weighted rms relative error of nb x nb blocks; +inf when no
   block holds a deposit */
double swe_blocks_rms(const swe_block *b, int nb);

/* the grid (see above): the finest nb in 1 .. nmax with swe_blocks_rms <=
   target (1 when none is) in *nb, its rms error in *rms; 0, or an error as
   swe_blocks' (also nmax < 1, target not positive) */
int swe_blocks_grid(const swe_block_class *c, size_t nc, const double outline[4], int nmax,
                    double target, int *nb, double *rms, char *err, size_t errlen);

#endif
