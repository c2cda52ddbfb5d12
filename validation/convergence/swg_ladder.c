/* swg_ladder.c - time-series means, the discretization error of every level,
 * the total error of a run and the cheapest run under a target
 * (swg_ladder.h, doc/convergence.md). */
#include "swg_ladder.h"
#include "swo_err.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define fail(err, errlen, msg) swo_fail(SWG_EINVAL, err, errlen, "%s", msg)

int swg_series_mean(const double *t, const double *x, size_t n, double t0, double t1, int nbatch,
                    swg_series_stat *out, char *err, size_t errlen)
{
    char m[256];
    if (!t || !x || !out)
        return fail(err, errlen, "swg_series_mean: a NULL argument");
    memset(out, 0, sizeof *out);
    if (!isfinite(t0) || !isfinite(t1) || !(t0 < t1)) {
        snprintf(m, sizeof m, "window: %g .. %g is not an interval (t0 < t1, finite)", t0, t1);
        return fail(err, errlen, m);
    }
    if (nbatch < 2 || nbatch > 1000) {
        snprintf(m, sizeof m, "batches: %d is outside [2, 1000]", nbatch);
        return fail(err, errlen, m);
    }
    size_t lo = n, hi = 0;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1]))) {
            snprintf(m, sizeof m, "sample %zu: time %g does not follow %g (strictly increasing, "
                     "finite)", i + 1, t[i], i ? t[i - 1] : 0.0);
            return fail(err, errlen, m);
        }
        if (!isfinite(x[i]) || fabs(x[i]) > SWG_VALUE_MAX) {
            snprintf(m, sizeof m, "sample %zu (t %g): value %g is not finite or above 1e100",
                     i + 1, t[i], x[i]);
            return fail(err, errlen, m);
        }
        if (t[i] > t0 && t[i] <= t1) {
            if (lo == n)
                lo = i;
            hi = i + 1;
        }
    }
    const size_t k = lo == n ? 0 : hi - lo;
    if (k < 2 * (size_t)nbatch) {
        snprintf(m, sizeof m, "window %g .. %g: %zu samples, fewer than 2 per batch for %d batches",
                 t0, t1, k, nbatch);
        return fail(err, errlen, m);
    }
    /* batch b holds samples [lo + b k / B, lo + (b + 1) k / B) */
    double sum = 0.0, bm[1000];
    for (int b = 0; b < nbatch; b++) {
        const size_t i0 = lo + (size_t)b * k / (size_t)nbatch;
        const size_t i1 = lo + (size_t)(b + 1) * k / (size_t)nbatch;
        double s = 0.0;
        for (size_t i = i0; i < i1; i++)
            s += x[i];
        sum += s;
        bm[b] = s / (double)(i1 - i0);
    }
    const double mean = sum / (double)k;
    double bmean = 0.0;
    for (int b = 0; b < nbatch; b++)
        bmean += bm[b];
    bmean /= nbatch;
    double ss = 0.0;
    for (int b = 0; b < nbatch; b++)
        ss += (bm[b] - bmean) * (bm[b] - bmean);
    out->mean = mean;
    out->se = sqrt(ss / (nbatch - 1) / nbatch);
    out->n = k;
    out->nbatch = nbatch;
    out->first = t[lo];
    out->last = t[hi - 1];
    return 0;
}

int swg_discretization(const swg_level *l, size_t n, double p_two, const swg_settings *s,
                       swg_disc *d, double *disc, char *err, size_t errlen)
{
    if (!l || !s || !d || !disc)
        return fail(err, errlen, "swg_discretization: a NULL argument");
    if (n < 2) {
        char m[128];
        snprintf(m, sizeof m, "levels: %zu given, at least 2 needed", n);
        return fail(err, errlen, m);
    }
    if (!isfinite(p_two) || !(p_two > 0.0) || p_two > SWG_P_LIMIT) {
        char m[128];
        snprintf(m, sizeof m, "order: %g is outside (0, %g]", p_two, SWG_P_LIMIT);
        return fail(err, errlen, m);
    }
    memset(d, 0, sizeof *d);
    const int rc = n >= 3 ? swg_three_level(l, s, &d->gci, err, errlen)
                          : swg_two_level(l, p_two, s, &d->gci, err, errlen);
    if (rc)
        return rc;
    /* the levels past the finest three must be finest first as well (the first
       three were checked by swg_three_level) */
    for (size_t i = 3; i < n; i++)
        if (!isfinite(l[i].h) || !isfinite(l[i].value) || !(l[i].h > l[i - 1].h) ||
            fabs(l[i].value) > SWG_VALUE_MAX) {
            char m[160];
            snprintf(m, sizeof m, "level %zu: h %g after %g, value %g (h increasing, |value| <= "
                     "1e100)", i + 1, l[i].h, l[i - 1].h, l[i].value);
            return fail(err, errlen, m);
        }
    if (d->gci.has_order) {
        d->kind = SWG_REF_EXTRAPOLATED;
        d->ref = d->gci.phi_ext21;
        d->ref_se = d->gci.se_phi_ext21;
        const double fs = n >= 3 ? s->fs3 : s->fs2;
        d->ref_u = (fs - 1.0) * fabs(l[0].value - d->ref);
        d->ref_a = d->ref_b = d->ref;
        d->u_a = d->u_b = d->ref_u;
        for (size_t i = 0; i < n; i++)
            disc[i] = hypot(l[i].value - d->ref, d->ref_u);
        return 0;
    }
    /* the bound over the two readings; r21 in [SWG_R_MIN, SWG_R_MAX] and p_two in
       (0, SWG_P_LIMIT] make c > 0 and at most 1e40: every number finite */
    d->kind = SWG_REF_BOUND;
    const double c = pow(l[1].h / l[0].h, p_two) - 1.0, e21 = l[1].value - l[0].value;
    d->ref_a = l[0].value;
    d->u_a = fabs(e21);
    d->ref_b = l[0].value - e21 / c;
    d->u_b = fabs(e21 / c);
    /* B when it keeps A's sign and is smaller (an extrapolation through zero makes
       no reference: the error stays relative to the finest value then) */
    const int take_b = d->ref_b * d->ref_a > 0.0 && fabs(d->ref_b) < fabs(d->ref_a);
    d->ref = take_b ? d->ref_b : d->ref_a;
    d->ref_u = take_b ? d->u_b : d->u_a;
    /* B = (1 + 1/c) phi1 - phi2 / c: its sampling error */
    d->ref_se = take_b ? hypot((1.0 + 1.0 / c) * l[0].se, l[1].se / c) : l[0].se;
    for (size_t i = 0; i < n; i++)
        disc[i] = fmax(hypot(l[i].value - d->ref_a, d->u_a), hypot(l[i].value - d->ref_b, d->u_b));
    return 0;
}

const char *swg_ref_kind_name(swg_ref_kind k)
{
    return k == SWG_REF_EXTRAPOLATED ? "extrapolated" : "bound";
}

int swg_total_error(double se, double disc, double ref, double *total, double *rel, int *has_rel,
                    char *err, size_t errlen)
{
    if (!total || !rel || !has_rel)
        return fail(err, errlen, "swg_total_error: a NULL argument");
    /* isfinite first: an ordered comparison with a NaN raises the invalid trap */
    if (!isfinite(se) || !isfinite(disc) || !isfinite(ref) || se < 0.0 || se > SWG_VALUE_MAX ||
        disc < 0.0 || disc > 4 * SWG_VALUE_MAX || fabs(ref) > 4 * SWG_VALUE_MAX) {
        char m[160];
        snprintf(m, sizeof m, "total error: se %g, discretization %g, reference %g (se and the "
                 "discretization error >= 0, all finite)", se, disc, ref);
        return fail(err, errlen, m);
    }
    *total = hypot(se, disc);
    /* the ratio at most 1e300 (compared as a product: no overflow) */
    *has_rel = ref != 0.0 && fabs(ref) >= *total * 1e-300;
    *rel = *has_rel ? *total / fabs(ref) : 0.0;
    return 0;
}

int swg_pick(const double *rel, const int *ok, const double *cost, size_t n, double target,
             size_t *idx)
{
    if (!rel || !ok || !cost || !idx || !isfinite(target) || target < 0.0)
        return -1;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(cost[i]) || cost[i] < 0.0)
            return -1;
    int found = 0;
    for (size_t i = 0; i < n; i++) {
        if (!ok[i] || !isfinite(rel[i]) || rel[i] > target)
            continue;
        if (!found || cost[i] < cost[*idx] || (cost[i] == cost[*idx] && rel[i] < rel[*idx])) {
            *idx = i;
            found = 1;
        }
    }
    return found;
}
