/* rebound_check.c - the wall model's rebound of a bounce (sww_rebound, from the
 * rebound tables of a regime.coeffs written by `snowregime map`) against the
 * kernel at random off-grid points.
 *
 * usage: rebound_check FILE N SEED [KEY=VALUE]...
 *   the kernel runs with the embedded defaults plus the KEY=VALUE settings (they
 *   must be those the file was made with); d uniform and v_n log-uniform over the
 *   table's span, v_t (with reboundVt) log-uniform over [first non-zero, last]
 *   node. Points where the kernel keeps the contact are skipped. A point counts
 *   as "inside" when the kernel bounces at every node of its table cell too (the
 *   cells that hold the interface, where e_n falls to 0, are reported apart).
 *   Prints max and rms of |e_n(table) - e_n(kernel)| and the same of e_t, inside
 *   and over all bouncing points. Exit 0, or 2 on bad input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_util.h"
#include "sww.h"

static size_t cell(const double *X, int n, double x)
{
    int i = 0;
    while (i < n - 2 && x >= X[i + 1])
        i++;
    return (size_t)i;
}

typedef struct {
    double max, sum2;
    int n;
} stat;

static void add(stat *s, double e)
{
    e = fabs(e);
    s->max = e > s->max ? e : s->max;
    s->sum2 += e * e;
    s->n++;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fputs("usage: rebound_check FILE N SEED [KEY=VALUE]...\n", stderr);
        return 2;
    }
    sww_model *w = sww_alloc();
    if (sww_regime_load(w, argv[1]) != SWW_OK) {
        fprintf(stderr, "rebound_check: %s\n", sww_errmsg(w));
        return 2;
    }
    size_t K;
    if (!sww_rebound_table(w, NULL, NULL, &K)) {
        fprintf(stderr, "rebound_check: %s has no rebound table\n", argv[1]);
        return 2;
    }
    int nd = 0, nv = 0, nt = 0;
    double *D = list_of(argv[1], "reboundD", &nd), *V = list_of(argv[1], "reboundVn", &nv);
    double *T = K > 1 ? list_of(argv[1], "reboundVt", &nt) : NULL;
    if (!D || !V || nd < 2 || nv < 2 || (K > 1 && (!T || nt < 3))) {
        fprintf(stderr, "rebound_check: cannot read the axes of %s (need >= 2 non-zero v_t)\n",
                argv[1]);
        return 2;
    }
    const int n = atoi(argv[2]);
    srand48(atol(argv[3]));
    swr_model *m = kernel_of_args("rebound_check", argc, argv, 4);
    if (!m)
        return 2;
    stat en_in = { 0 }, et_in = { 0 }, en_all = { 0 }, et_all = { 0 };
    double wd = 0, wv = 0, wt = 0, wk = 0, wm = 0;
    int kept = 0;
    for (int q = 0; q < n; q++) {
        const double d = D[0] + (D[nd - 1] - D[0]) * drand48();
        const double vn = V[0] * pow(V[nv - 1] / V[0], drand48());
        const double vt = K > 1 ? T[1] * pow(T[nt - 1] / T[1], drand48()) : 0.0;
        swr_impact in = { .d = d, .vn = vn, .vt = vt };
        swr_result r;
        swr_collide(m, &in, &r, NULL);
        if (r.contact_kept) {
            kept++;
            continue;
        }
        double en, et;
        sww_rebound(w, d, vn, vt, &en, &et);
        /* the cell's nodes: do they all bounce? */
        const size_t i = cell(D, nd, d), j = cell(V, nv, vn);
        const size_t k = K > 1 ? cell(T + 1, nt - 1, vt) + 1 : 0;
        int inside = 1;
        for (int c = 0; c < (K > 1 ? 8 : 4) && inside; c++) {
            swr_impact ci = { .d = D[i + (c & 1)], .vn = V[j + ((c >> 1) & 1)],
                              .vt = K > 1 ? T[k + ((c >> 2) & 1)] : 0.0 };
            swr_result cr;
            swr_collide(m, &ci, &cr, NULL);
            inside = !cr.contact_kept;
        }
        add(&en_all, en - r.e_n);
        if (K > 1)
            add(&et_all, et - r.e_t);
        if (!inside)
            continue;
        add(&en_in, en - r.e_n);
        if (K > 1)
            add(&et_in, et - r.e_t);
        if (fabs(en - r.e_n) >= en_in.max) {
            wd = d, wv = vn, wt = vt, wk = r.e_n, wm = en;
        }
    }
    printf("points %d of %d bounce (%d kept); inside cells whose nodes all bounce: %d\n",
           en_all.n, n, kept, en_in.n);
    printf("inside: |e_n error| max %.4g rms %.4g", en_in.max, en_in.n ? sqrt(en_in.sum2 / en_in.n) : 0.0);
    if (K > 1)
        printf("; |e_t error| max %.4g rms %.4g", et_in.max, et_in.n ? sqrt(et_in.sum2 / et_in.n) : 0.0);
    printf("\nall bouncing: |e_n error| max %.4g rms %.4g", en_all.max,
           en_all.n ? sqrt(en_all.sum2 / en_all.n) : 0.0);
    if (K > 1)
        printf("; |e_t error| max %.4g rms %.4g", et_all.max,
               et_all.n ? sqrt(et_all.sum2 / et_all.n) : 0.0);
    printf("\nworst e_n inside at d %.4g m, vn %.4g m/s, vt %.4g m/s: kernel %.4g, wall model %.4g\n",
           wd, wv, wt, wk, wm);
    free(D);
    free(V);
    free(T);
    swr_model_free(m);
    sww_free(w);
    return 0;
}
