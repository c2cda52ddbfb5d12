/* oblique_check.c - the wall model's d_crit(v_n, v_t) (sww_dcrit_oblique, from
 * a regime.coeffs written by `snowregime map --vt 0,...`) against the kernel
 * at random off-grid (v_n, v_t) points.
 *
 * usage: oblique_check FILE N SEED [KEY=VALUE]...
 *   the kernel runs with the embedded defaults plus the KEY=VALUE settings
 *   (they must be those the file was made with) and the file's obliqueSlide;
 *   v_n log-uniform in the file's [vnMin, vnMax], v_t uniform in the axis
 *   coordinate of the table over (0, last node]. Prints the relative error of
 *   d_crit: max, rms and the worst point. Exit 0, or 2 on bad input. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_util.h"
#include "sww.h"
#include "swt_oblique.h"

static double slide_of(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    double v = -1.0;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, " obliqueSlide %lf", &v) == 1)
            break;
    if (f)
        fclose(f);
    return v;
}

static double vt_last(const char *path)
{
    int n = 0;
    double *v = list_of(path, "obliqueVt", &n);
    const double last = v && n > 0 ? v[n - 1] : -1.0;
    free(v);
    return last;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fputs("usage: oblique_check FILE N SEED [KEY=VALUE]...\n", stderr);
        return 2;
    }
    sww_model *w = sww_alloc();
    if (sww_regime_load(w, argv[1]) != SWW_OK) {
        fprintf(stderr, "oblique_check: %s\n", sww_errmsg(w));
        return 2;
    }
    size_t nvt, nvn;
    if (!sww_oblique_table(w, &nvt, &nvn)) {
        fprintf(stderr, "oblique_check: %s has no oblique table\n", argv[1]);
        return 2;
    }
    const int n = atoi(argv[2]);
    srand48(atol(argv[3]));
    swr_model *m = kernel_of_args("oblique_check", argc, argv, 4);
    if (!m)
        return 2;
    swt_vcrit_opts o;
    swt_vcrit_opts_default(&o);
    o.full_stick = 1;
    o.max_slide = slide_of(argv[1]);
    o.rtol = 1e-4;
    const double vt_max = vt_last(argv[1]);
    if (!(o.max_slide >= 0.0) || !(vt_max > 0.0)) {
        fprintf(stderr, "oblique_check: no obliqueSlide / obliqueVt in %s\n", argv[1]);
        return 2;
    }
    const double lo = sww_vn_min(w), hi = sww_vn_max(w);
    double worst = 0.0, sum2 = 0.0, wv = 0.0, wt = 0.0, wk = 0.0, wm = 0.0;
    int used = 0;
    for (int k = 0; k < n; k++) {
        const double vn = lo * pow(hi / lo, drand48());
        const double vt = vt_max * pow(drand48(), 2.0);
        swt_vcrit_result r;
        if (swt_dcrit(m, vn, vt, &o, 1e-7, 0.1, &r) != SWT_VCRIT_FOUND)
            continue;
        const double dm = sww_dcrit_oblique(w, vn, vt);
        const double e = fabs(dm / r.vcrit - 1.0);
        sum2 += e * e;
        used++;
        if (e > worst) {
            worst = e;
            wv = vn;
            wt = vt;
            wk = r.vcrit;
            wm = dm;
        }
    }
    printf("points %d of %d, relative error of d_crit: max %.4g, rms %.4g; worst at vn %.4g m/s, "
           "vt %.4g m/s: kernel %.4g m, wall model %.4g m\n", used, n, worst,
           used ? sqrt(sum2 / used) : 0.0, wv, wt, wk, wm);
    swr_model_free(m);
    sww_free(w);
    return 0;
}
