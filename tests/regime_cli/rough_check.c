/* rough_check.c - load a rough wall's regime.coeffs (snowregime map --set
 * wall=lattice) with the wall model's reader and compare its stick
 * probability with the map it came from.
 *
 * Usage: rough_check REGIME.COEFFS MAP.CSV [VT]
 * With VT (a rough map over v_t, snowregime map --set wall=lattice --vt 0,...):
 * the table has a v_t axis, the regime tangential gate is on and every
 * impact has that v_t: MAP.CSV is the map at VT (map-vt<VT>.csv).
 * Checks: the file loads with a probability table of the map's size; at every
 * grid node sww_decide's p_stick equals the map's p_stick column (to its
 * 6-digit rounding); over 4000 uniform u the stick fraction at a node with
 * 0 < p < 1 is p within 4 binomial sigma. Prints one line per failure and a
 * summary; exit 0 all good, 1 otherwise.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sww.h"

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 4) { fprintf(stderr, "usage: rough_check REGIME.COEFFS MAP.CSV [VT]\n"); return 2; }
    const double vt = argc == 4 ? atof(argv[3]) : 0.0;
    sww_model *m = sww_alloc();
    if (!m || sww_regime_load(m, argv[1]) != 0) {
        printf("FAIL: %s does not load: %s\n", argv[1], m ? sww_errmsg(m) : "out of memory");
        return 1;
    }
    size_t nd = 0, nv = 0;
    if (!sww_probability_table(m, &nd, &nv)) {
        printf("FAIL: %s has no probability table\n", argv[1]);
        return 1;
    }
    if (argc == 4) {
        double vmax = 0.0;
        if (sww_probability_vt(m, &vmax) < 2 || !(vt <= vmax)) {
            printf("FAIL: %s has no v_t axis reaching %g m/s\n", argv[1], vt);
            return 1;
        }
        if (sww_set_tangential_regime(m) != SWW_OK) {
            printf("FAIL: the regime gate: %s\n", sww_errmsg(m));
            return 1;
        }
    }
    FILE *f = fopen(argv[2], "r");
    if (!f) { printf("FAIL: cannot read %s\n", argv[2]); return 1; }
    char line[512];
    long nodes = 0, bad = 0;
    double maxdev = 0.0, pmid = -1.0, dmid = 0.0, vmid = 0.0;
    /* the grid's extremes: the csv's 9 digits may round a node just outside
     * the table's span, so nodes on the edge are taken a hair inside */
    double d0 = INFINITY, d1 = 0.0, v0 = INFINITY, v1 = 0.0;
    for (int pass = 0; pass < 2; pass++) {
    rewind(f);
    while (fgets(line, sizeof line, f)) {
        double d, v, e_n, e_t, p, perr;
        int st, kept, status, pts;
        if (sscanf(line, "%lf,%lf,%d,%d,%lf,%lf,%d,%lf,%lf,%d", &d, &v, &st, &kept, &e_n, &e_t,
                   &status, &p, &perr, &pts) != 10)
            continue;
        if (pass == 0) {
            d0 = fmin(d0, d); d1 = fmax(d1, d); v0 = fmin(v0, v); v1 = fmax(v1, v);
            continue;
        }
        const double in_d = d == d0 ? d * (1 + 1e-8) : d == d1 ? d * (1 - 1e-8) : d;
        const double in_v = v == v0 ? v * (1 + 1e-8) : v == v1 ? v * (1 - 1e-8) : v;
        sww_impact in = { in_d, in_v, vt, 0.0, 0.0 };
        sww_outcome o;
        if (sww_decide(m, &in, &o) != SWW_OK) { printf("FAIL: decide at d %g v %g\n", d, v); bad++; continue; }
        const double dev = fabs(o.p_stick - p);
        if (dev > maxdev) maxdev = dev;
        if (dev > 1e-5) { printf("FAIL: d %g v %g: p_stick %g, map %g\n", d, v, o.p_stick, p); bad++; }
        if (p > 0.2 && p < 0.8 && pmid < 0.0) { pmid = p; dmid = in_d; vmid = in_v; }
        nodes++;
    }
    }
    fclose(f);
    if ((size_t)nodes != nd * nv) { printf("FAIL: %ld map nodes, table %zu x %zu\n", nodes, nd, nv); bad++; }
    if (pmid > 0.0) {
        long n = 4000, s = 0;
        for (long k = 0; k < n; k++) {
            sww_impact in = { dmid, vmid, vt, 0.0, (k + 0.5) / n };
            sww_outcome o;
            sww_decide(m, &in, &o);
            s += o.fate == SWW_STICK;
        }
        const double fr = (double)s / n, sig = sqrt(pmid * (1.0 - pmid) / n);
        printf("node d %g v %g: p %g, stick fraction over %ld u %g\n", dmid, vmid, pmid, n, fr);
        if (fabs(fr - pmid) > 4.0 * sig + 1.0 / n) { printf("FAIL: stick fraction %g vs p %g\n", fr, pmid); bad++; }
    }
    printf("nodes %ld, table %zu x %zu, max |p_sww - p_map| %.3g\n", nodes, nd, nv, maxdev);
    sww_free(m);
    return bad ? 1 : 0;
}
