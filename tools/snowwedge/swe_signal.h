/* swe_signal.h - a signal sampled at uneven times (the force coefficients of
 * an adaptive-step solver): mean, rms of the fluctuation and the frequency of
 * its largest spectral peak.
 *
 * The spectrum is the transform of the fluctuation x_k - mean on the uneven
 * samples, P(f) = |sum_{k>=2} (x_k - mean) exp(-2 pi i f t_k) (t_k - t_{k-1})|^2,
 * evaluated from f0 = 2 / W (W = t_n - t_1 of the window given, at least two
 * periods in it) in steps of 1 / (4 W) up to fmax: a fast Fourier transform
 * needs even samples, which the solver's steps are not, and a peak between
 * the transform's bins 1 / W apart would be missed. */
#ifndef SWE_SIGNAL_H
#define SWE_SIGNAL_H

#include <stddef.h>

double swe_mean(const double *x, size_t n);
/* sqrt(mean((x - mean)^2)) */
double swe_rms(const double *x, size_t n);
/* the frequency of the largest P(f) over f0 = 2 / W .. fmax, W = b - a the
   window; 0 or SWE_EINVAL (fewer than 3 samples, W <= 0, fmax < f0) */
int swe_peak_frequency(const double *t, const double *x, size_t n, double a, double b, double fmax,
                       double *f, char *err, size_t errlen);

#endif
