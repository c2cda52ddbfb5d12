/* swt_rebound.c - rebound tables for regime.coeffs (see swt_rebound.h). */
#include "swt_rebound.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void swt_rebound_free(swt_rebound *r)
{
    free(r->d);
    free(r->vn);
    free(r->vt);
    free(r->en);
    free(r->et);
    free(r->have);
    memset(r, 0, sizeof *r);
}

int swt_rebound_init(swt_rebound *r, const swt_map *mp, const double *vt, int nvt, char *err,
                     size_t errlen)
{
    memset(r, 0, sizeof *r);
    if (nvt < 1 || (nvt > 1 && (!vt || vt[0] != 0.0))) {
        snprintf(err, errlen, "rebound table: the tangential speeds must start at 0 (%d given)", nvt);
        return -1;
    }
    const size_t M = (size_t)mp->g.nd, N = (size_t)mp->g.nv, K = (size_t)nvt;
    r->nd = mp->g.nd;
    r->nvn = mp->g.nv;
    r->nvt = nvt;
    r->d = malloc(M * sizeof *r->d);
    r->vn = malloc(N * sizeof *r->vn);
    r->en = calloc(K * M * N, sizeof *r->en);
    r->have = calloc(K, sizeof *r->have);
    if (K > 1) {
        r->vt = malloc(K * sizeof *r->vt);
        r->et = calloc(K * M * N, sizeof *r->et);
    }
    if (!r->d || !r->vn || !r->en || !r->have || (K > 1 && (!r->vt || !r->et))) {
        swt_rebound_free(r);
        snprintf(err, errlen, "rebound table: out of memory (%zu x %zu x %zu)", K, M, N);
        return -1;
    }
    memcpy(r->d, mp->d, M * sizeof *r->d);
    memcpy(r->vn, mp->v, N * sizeof *r->vn);
    if (K > 1)
        memcpy(r->vt, vt, K * sizeof *r->vt);
    return 0;
}

static double clamp01(double e)
{
    return isfinite(e) ? (e < 0.0 ? 0.0 : (e > 1.0 ? 1.0 : e)) : 0.0;
}

int swt_rebound_layer(swt_rebound *r, int k, const swt_map *mp, char *err, size_t errlen)
{
    const int M = r->nd, N = r->nvn;
    if (k < 0 || k >= r->nvt || mp->g.nd != M || mp->g.nv != N) {
        snprintf(err, errlen, "rebound table: layer %d of %d, grid %d x %d against %d x %d", k,
                 r->nvt, mp->g.nd, mp->g.nv, M, N);
        return -1;
    }
    for (int i = 0; i < M; i++)
        for (int j = 0; j < N; j++)
            if (mp->d[i] != r->d[i] || mp->v[j] != r->vn[j]) {
                snprintf(err, errlen, "rebound table: layer %d has another grid (d %g, v_n %g)", k,
                         mp->d[i], mp->v[j]);
                return -1;
            }
    double *en = r->en + (size_t)k * M * N;
    for (size_t q = 0; q < (size_t)M * N; q++)
        en[q] = mp->kept[q] ? 0.0 : clamp01(mp->e_n[q]);
    r->have[k] = 1;
    if (!r->et || k == 0)
        return 0;
    double *et = r->et + (size_t)k * M * N;
    /* e_t at bouncing nodes; kept nodes from the nearest bouncing one along d,
     * else from the nearest column with a bounce, else 1 */
    int any = 0;
    for (size_t q = 0; q < (size_t)M * N; q++) {
        et[q] = mp->kept[q] ? -1.0 : clamp01(mp->e_t[q]);
        any |= !mp->kept[q];
    }
    for (int j = 0; j < N; j++)
        for (int i = 0; i < M; i++) {
            if (et[i * N + j] >= 0.0)
                continue;
            double v = -1.0;
            for (int s = 1; s < M && v < 0.0; s++) {
                if (i + s < M && !mp->kept[(i + s) * N + j])
                    v = et[(i + s) * N + j];
                else if (i - s >= 0 && !mp->kept[(i - s) * N + j])
                    v = et[(i - s) * N + j];
            }
            for (int s = 1; s < N && v < 0.0; s++)
                for (int c = -1; c <= 1 && v < 0.0; c += 2) {
                    const int jj = j + c * s;
                    if (jj < 0 || jj >= N)
                        continue;
                    for (int t = 0; t < M && v < 0.0; t++) {
                        if (i + t < M && !mp->kept[(i + t) * N + jj])
                            v = et[(i + t) * N + jj];
                        else if (i - t >= 0 && !mp->kept[(i - t) * N + jj])
                            v = et[(i - t) * N + jj];
                    }
                }
            et[i * N + j] = any && v >= 0.0 ? v : 1.0;
        }
    /* a guard: no node stays unfilled */
    for (size_t q = 0; q < (size_t)M * N; q++)
        if (et[q] < 0.0)
            et[q] = 1.0;
    if (k == 1)
        memcpy(r->et, et, (size_t)M * N * sizeof *et); /* layer 0 repeats layer 1 */
    return 0;
}

int swt_rebound_complete(const swt_rebound *r)
{
    if (!r->have)
        return 0;
    for (int k = 0; k < r->nvt; k++)
        if (!r->have[k])
            return 0;
    return 1;
}

static void write_list(FILE *fp, const char *key, const double *v, size_t n, size_t per_line)
{
    fprintf(fp, "    %-15s (", key);
    for (size_t i = 0; i < n; i++)
        fprintf(fp, "%s%.6g", i == 0 ? "" : (per_line && i % per_line == 0 ? "\n                     "
                                                                           : " "), v[i]);
    fprintf(fp, ");\n");
}

void swt_rebound_write(FILE *fp, const swt_rebound *r)
{
    const size_t M = (size_t)r->nd, N = (size_t)r->nvn, K = (size_t)r->nvt;
    fprintf(fp, "\n    // Rebound of bouncing impacts from the kernel (the wall model's bounce):\n");
    fprintf(fp, "    // v_n' = e_n v_n%s; %s rows by d, columns by v_n; 0 where the\n",
            K > 1 ? ", v_t' = e_t v_t" : "", K > 1 ? "layers by v_t," : "");
    fprintf(fp, "    // kernel keeps the contact (e_t there: the nearest bounce's).\n");
    write_list(fp, "reboundD", r->d, M, 0);
    write_list(fp, "reboundVn", r->vn, N, 0);
    if (K > 1)
        write_list(fp, "reboundVt", r->vt, K, 0);
    write_list(fp, "reboundEn", r->en, K * M * N, N);
    if (K > 1)
        write_list(fp, "reboundEt", r->et, K * M * N, N);
}
