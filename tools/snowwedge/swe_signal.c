/* swe_signal.c - mean, rms and spectral peak of an unevenly sampled signal
 * (swe_signal.h). */
#include "swe_signal.h"

#include "swe_spray.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>

double swe_mean(const double *x, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; i++)
        m += x[i];
    return n ? m / (double)n : 0;
}

double swe_rms(const double *x, size_t n)
{
    if (!n)
        return 0;
    const double m = swe_mean(x, n);
    return sqrt(gsl_stats_tss_m(x, 1, n, m) / (double)n);
}

int swe_peak_frequency(const double *t, const double *x, size_t n, double a, double b, double fmax,
                       double *fpeak, char *err, size_t errlen)
{
    const double w = b - a;
    if (n < 3 || !(w > 0) || !(fmax >= 2 / w)) {
        if (err && errlen)
            snprintf(err, errlen, "no spectrum: %zu samples, window %g s, fmax %g Hz", n, w, fmax);
        return SWE_EINVAL;
    }
    const double m = swe_mean(x, n);
    double best = -1, fb = 0;
    /* the grid as summed, f += df, so that its frequencies are those of the
       earlier tables to the last bit */
    for (double f = 2 / w; f <= fmax; f += 0.25 / w) {
        double re = 0, im = 0;
        for (size_t i = 1; i < n; i++) {
            const double dt = t[i] - t[i - 1], ph = 2 * M_PI * f * t[i];
            re += (x[i] - m) * cos(ph) * dt;
            im += (x[i] - m) * sin(ph) * dt;
        }
        const double p = re * re + im * im;
        if (p > best) {
            best = p;
            fb = f;
        }
    }
    *fpeak = fb;
    return 0;
}
