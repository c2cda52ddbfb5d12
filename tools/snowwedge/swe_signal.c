/* swe_signal.c - mean, rms and spectral peak of an unevenly sampled signal
 * (swe_signal.h). */
#include "swe_signal.h"

#include "swe_spray.h"

#include <gsl/gsl_fft_real.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

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

static int sig_fail(char *err, size_t errlen, int code, const char *msg)
{
    if (err && errlen)
        snprintf(err, errlen, "%s", msg);
    return code;
}

void swe_spectrum_free(swe_spectrum *s)
{
    if (s) {
        free(s->psd);
        s->psd = NULL;
    }
}

int swe_spectrum_welch(const double *t, const double *x, size_t n, double a, double b, int nseg,
                       double dt, swe_spectrum *out, char *err, size_t errlen)
{
    *out = (swe_spectrum){0};
    if (!isfinite(a) || !isfinite(b) || b <= a)
        return sig_fail(err, errlen, SWE_EINVAL, "the window is not T0 < T1");
    if (nseg < 1 || nseg > 1000)
        return sig_fail(err, errlen, SWE_EINVAL, "the segments are not 1 .. 1000");
    /* the samples inside the window, checked */
    size_t i0 = n, i1 = 0;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(t[i]) || !isfinite(x[i])) {
            if (err && errlen)
                snprintf(err, errlen, "sample %zu is not finite (t %g, x %g)", i + 1, t[i], x[i]);
            return SWE_EINVAL;
        }
        if (i && t[i] <= t[i - 1]) {
            if (err && errlen)
                snprintf(err, errlen, "the times do not increase at sample %zu (%g after %g)",
                         i + 1, t[i], t[i - 1]);
            return SWE_EINVAL;
        }
        if (t[i] >= a && t[i] <= b) {
            i0 = i < i0 ? i : i0;
            i1 = i;
        }
    }
    if (i0 == n || i1 - i0 + 1 < 8) {
        if (err && errlen)
            snprintf(err, errlen, "fewer than 8 samples in the window %g .. %g s", a, b);
        return SWE_EINVAL;
    }
    if (!(dt > 0)) {
        double *st = malloc((i1 - i0) * sizeof *st);
        if (!st)
            return sig_fail(err, errlen, SWE_ENOMEM, "out of memory");
        for (size_t i = i0 + 1; i <= i1; i++)
            st[i - i0 - 1] = t[i] - t[i - 1];
        gsl_sort(st, 1, i1 - i0);
        dt = gsl_stats_median_from_sorted_data(st, 1, i1 - i0);
        free(st);
    }
    /* the even samples over [t_i0, t_i1] */
    const double ta = t[i0], tb = t[i1];
    const size_t m = (size_t)floor((tb - ta) / dt) + 1;
    const size_t L = 2 * m / (size_t)(nseg + 1);
    if (L < 8) {
        if (err && errlen)
            snprintf(err, errlen, "%d segment(s) of %zu samples: fewer than 8 each", nseg, L);
        return SWE_EINVAL;
    }
    double *y = malloc(m * sizeof *y), *seg = malloc(L * sizeof *seg),
           *psd = calloc(L / 2 + 1, sizeof *psd);
    gsl_fft_real_wavetable *wt = gsl_fft_real_wavetable_alloc(L);
    gsl_fft_real_workspace *ws = gsl_fft_real_workspace_alloc(L);
    if (!y || !seg || !psd || !wt || !ws) {
        free(y), free(seg), free(psd);
        if (wt)
            gsl_fft_real_wavetable_free(wt);
        if (ws)
            gsl_fft_real_workspace_free(ws);
        return sig_fail(err, errlen, SWE_ENOMEM, "out of memory");
    }
    size_t k = i0;
    for (size_t j = 0; j < m; j++) {
        const double tj = ta + (double)j * dt;
        while (k + 1 < i1 && t[k + 1] < tj)
            k++;
        const double u = (tj - t[k]) / (t[k + 1] - t[k]);
        y[j] = x[k] + (u < 0 ? 0 : u > 1 ? 1 : u) * (x[k + 1] - x[k]);
    }
    /* Hann's window and its power */
    double w2 = 0;
    for (size_t j = 0; j < L; j++) {
        const double w = 0.5 - 0.5 * cos(2 * M_PI * (double)j / (double)L);
        w2 += w * w;
    }
    const size_t hop = L / 2;
    int used = 0;
    for (size_t s0 = 0; s0 + L <= m && used < nseg; s0 += hop, used++) {
        double mean = 0;
        for (size_t j = 0; j < L; j++)
            mean += y[s0 + j];
        mean /= (double)L;
        for (size_t j = 0; j < L; j++)
            seg[j] = (y[s0 + j] - mean) * (0.5 - 0.5 * cos(2 * M_PI * (double)j / (double)L));
        gsl_fft_real_transform(seg, 1, L, wt, ws);
        /* halfcomplex: seg[0] the mean, seg[2j-1], seg[2j] the real and imaginary parts */
        for (size_t j = 0; j <= L / 2; j++) {
            double p;
            if (j == 0)
                p = seg[0] * seg[0];
            else if (2 * j == L)
                p = seg[L - 1] * seg[L - 1];
            else
                p = 2 * (seg[2 * j - 1] * seg[2 * j - 1] + seg[2 * j] * seg[2 * j]);
            psd[j] += p * dt / w2; /* one-sided: sum psd df = the segment's variance */
        }
    }
    double var = 0;
    const double df = 1 / ((double)L * dt);
    for (size_t j = 0; j <= L / 2; j++) {
        psd[j] /= used;
        var += psd[j] * df;
    }
    gsl_fft_real_wavetable_free(wt);
    gsl_fft_real_workspace_free(ws);
    free(y);
    free(seg);
    *out = (swe_spectrum){L / 2 + 1, df, dt, L, used, var, psd};
    return 0;
}

void swe_spectrum_peaks(const swe_spectrum *s, double share, double *fpeak, double *flow,
                        double *below)
{
    size_t jp = 1;
    for (size_t j = 1; j < s->nf; j++)
        if (s->psd[j] > s->psd[jp])
            jp = j;
    *fpeak = (double)jp * s->df;
    *flow = *fpeak;
    for (size_t j = 1; j < s->nf; j++) {
        const double l = s->psd[j - 1], r = j + 1 < s->nf ? s->psd[j + 1] : 0;
        if (s->psd[j] < l || s->psd[j] < r)
            continue;
        const double band = (l + s->psd[j] + r) * s->df;
        if (s->var > 0 && band >= share * s->var) {
            *flow = (double)j * s->df;
            break;
        }
    }
    double lo = 0;
    for (size_t j = 1; j < s->nf && (double)j * s->df < *fpeak / 2; j++)
        lo += s->psd[j] * s->df;
    *below = s->var > 0 ? lo / s->var : 0;
}
