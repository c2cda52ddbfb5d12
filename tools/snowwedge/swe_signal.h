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

/* The power spectral density of a signal of uneven samples, by Welch's method:
 * x(t) over [a, b] interpolated linearly onto even samples dt apart (dt as
 * given, else the median step of the samples inside the window), split into K
 * segments of L samples that overlap by half (L = 2 m / (K + 1), m the even
 * samples), each with its mean removed and a Hann window; the one-sided
 * density at f_j = j / (L dt), j = 0 .. L / 2, averaged over the segments and
 * scaled so that sum_j psd_j df is the segments' mean variance (df = 1 / (L dt)).
 * Its resolution is df: a peak at f is known to +- df / 2. */
typedef struct {
    size_t nf;     /* frequencies: L / 2 + 1 */
    double df;     /* their spacing [Hz] */
    double dt;     /* the even step [s] */
    size_t seglen; /* L */
    int nseg;      /* K */
    double var;    /* sum_j psd_j df */
    double *psd;   /* [nf] */
} swe_spectrum;

/* the spectrum of (t, x) over [a, b] with K >= 1 segments and the even step
   dt (<= 0: the median step inside the window) into *out (out->psd malloc'd:
   swe_spectrum_free); 0, or SWE_EINVAL (fewer than 8 samples in the window,
   b <= a, K < 1, segments of fewer than 8 samples, a non-finite value, times
   not increasing) or SWE_ENOMEM with a message in err */
int swe_spectrum_welch(const double *t, const double *x, size_t n, double a, double b, int nseg,
                       double dt, swe_spectrum *out, char *err, size_t errlen);
void swe_spectrum_free(swe_spectrum *s);

/* the peaks of a spectrum: the largest density above f = 0 (its frequency in
   *fpeak), and the lowest local maximum j >= 1 whose band j-1 .. j+1 holds at
   least the share `share` of the variance (its frequency in *flow; the peak's
   when none does); the variance below fpeak / 2 over the whole in *below */
void swe_spectrum_peaks(const swe_spectrum *s, double share, double *fpeak, double *flow,
                        double *below);

#endif
