/* coeffs_check.c - load a regime.coeffs written by `snowregime map` with the wall
 * model's own reader (sww_regime_load) and compare its d_crit(v_n) with the
 * interface points of the same map.
 *
 * Usage: coeffs_check REGIME.COEFFS INTERFACE.CSV
 * Checks: the file loads; at every interface point sww_dcrit equals the dfit
 * column (the fit the map wrote) to 1e-6 and the point itself to the file's
 * maxResidual (up to its 6-digit rounding); vnMin/vnMax are the first/last interface speeds.
 * Prints one line per failure; exit 0 all good, 1 otherwise.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sww.h"

int main(int argc, char **argv)
{
    if (argc != 3) { fprintf(stderr, "usage: coeffs_check REGIME.COEFFS INTERFACE.CSV\n"); return 2; }
    sww_model *m = sww_alloc();
    if (!m || sww_regime_load(m, argv[1]) != 0) {
        printf("FAIL: %s does not load: %s\n", argv[1], m ? sww_errmsg(m) : "out of memory");
        return 1;
    }
    /* maxResidual from the file itself */
    double maxres = -1.0;
    FILE *f = fopen(argv[1], "r");
    char line[4096];
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, " maxResidual %lf", &maxres) == 1) break;
    if (f) fclose(f);
    if (!(maxres >= 0.0)) { printf("FAIL: no maxResidual in %s\n", argv[1]); return 1; }
    f = fopen(argv[2], "r");
    if (!f) { printf("FAIL: cannot read %s\n", argv[2]); return 1; }
    int n = 0, bad = 0;
    double vfirst = 0.0, vlast = 0.0;
    while (fgets(line, sizeof line, f)) {
        double vn, dc, dfit, res;
        if (line[0] == '#' || sscanf(line, "%lf,%lf,%lf,%lf", &vn, &dc, &dfit, &res) != 4) continue;
        if (n == 0) vfirst = vn;
        vlast = vn;
        n++;
        double dw = sww_dcrit(m, vn);
        if (!(fabs(dw / dfit - 1.0) <= 1e-6)) {
            printf("FAIL: vn %g: sww_dcrit %.9g != dfit %.9g\n", vn, dw, dfit);
            bad++;
        }
        /* maxResidual is written with 6 digits, the points with 9 */
        if (!(fabs(dw / dc - 1.0) <= maxres * (1.0 + 1e-5) + 1e-8)) {
            printf("FAIL: vn %g: sww_dcrit %.9g vs point %.9g: residual above maxResidual %g\n",
                   vn, dw, dc, maxres);
            bad++;
        }
    }
    fclose(f);
    if (n < 2) { printf("FAIL: only %d interface points in %s\n", n, argv[2]); bad++; }
    if (n >= 2 && (fabs(sww_vn_min(m) / vfirst - 1) > 1e-8 || fabs(sww_vn_max(m) / vlast - 1) > 1e-8)) {
        printf("FAIL: vnMin/vnMax %g %g != interface span %g %g\n", sww_vn_min(m), sww_vn_max(m),
               vfirst, vlast);
        bad++;
    }
    printf("coeffs_check: %d interface points, %d failures\n", n, bad);
    sww_free(m);
    return bad ? 1 : 0;
}
