/* swt_rebound.h - the kernel's rebound of bouncing impacts as tables for
 * regime.coeffs (format: doc/regime-coeffs.md, "Rebound tables").
 *
 * e_n(d, v_n), and with a --vt list e_n and e_t over (v_t, d, v_n), taken
 * from the grid points of the maps (swt_map: e_n, e_t, kept). Where the kernel
 * keeps the contact, e_n is 0 (the kernel's rebound speed there, and the limit
 * at the interface); e_t has no value there and takes the nearest bouncing
 * node's along d in its column (else the nearest column's with a bounce, else
 * 1); the head-on layer of e_t (no tangential motion) repeats layer 1.
 */
#ifndef SWT_REBOUND_H
#define SWT_REBOUND_H

#include <stdio.h>

#include "swt_map.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int nd, nvn, nvt;      /* M diameters, N normal speeds, K tangential speeds (1: head-on) */
    double *d, *vn, *vt;   /* axes (vt NULL when K = 1) */
    double *en, *et;       /* K x M x N, layers by v_t, rows by d; et NULL when K = 1 */
    int *have;             /* per layer: filled */
} swt_rebound;

/* Allocate for the grid of mp and the tangential speeds vt[0..nvt-1] (vt[0] = 0;
 * nvt = 1 and vt NULL: head-on only). 0, or -1 with a message. */
int swt_rebound_init(swt_rebound *r, const swt_map *mp, const double *vt, int nvt, char *err,
                     size_t errlen);
/* Take layer k from map mp (the same grid). 0, or -1 when the grid differs. */
int swt_rebound_layer(swt_rebound *r, int k, const swt_map *mp, char *err, size_t errlen);
/* 1 when every layer is filled. */
int swt_rebound_complete(const swt_rebound *r);
void swt_rebound_free(swt_rebound *r);
/* The keys reboundD, reboundVn, [reboundVt], reboundEn, [reboundEt], inside regime { }. */
void swt_rebound_write(FILE *fp, const swt_rebound *r);

#ifdef __cplusplus
}
#endif
#endif
