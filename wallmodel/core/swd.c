/* swd.c - near-wall particle dispersion (see swd.h). */
#include "swd.h"
#include "swd_internal.h"
#include "swp_nearwall.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { K_LAYER, K_BLEND, K_CT, K_CMU, K_N };

static const struct {
    const char *name;
    double def, lo, hi;   /* default and accepted range [lo, hi]        */
    int lo_open;          /* 1: lo itself is refused                    */
} keys[K_N] = {
    { "layerYPlus", 100.0, 5.0, 200.0, 0 },
    { "blendYPlus", 150.0, 5.0, 400.0, 1 },
    { "CT", 0.3, 0.0, 2.0, 1 },
    { "Cmu", 0.09, 0.0, 1.0, 0 },
};

#define SWD_MAX_TABLE 4096

struct swd_model {
    double v[K_N];
    double cmu4;   /* Cmu^(1/4) */
    int scale;     /* SWD_USTAR_* */
    /* sublayer closure: nodes ln tau+ and Vs+ (n = 0: off) */
    size_t cl_n;
    double cl_ysub;
    double *cl_lnt, *cl_vs;
    int ready;
    char err[256];
};

static int fail(swd_model *m, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->err, sizeof m->err, fmt, ap);
    va_end(ap);
    return code;
}

/* for swd_load.c: a whole message (it carries the file and line) */
int swd_fail_message(swd_model *m, const char *msg)
{
    return fail(m, SWD_EINVAL, "%s", msg);
}

swd_model *swd_alloc(void)
{
    swd_model *m = calloc(1, sizeof *m);
    if (!m)
        return NULL;
    for (int i = 0; i < K_N; i++)
        m->v[i] = keys[i].def;
    swd_commit(m);
    return m;
}

void swd_free(swd_model *m)
{
    if (m)
        swd_closure_off(m);
    free(m);
}

const char *swd_errmsg(const swd_model *m)
{
    return m ? m->err : "no model";
}

const char *swd_key(size_t i)
{
    return i < K_N ? keys[i].name : NULL;
}

static int key_index(const char *key)
{
    for (int i = 0; key && i < K_N; i++)
        if (!strcmp(key, keys[i].name))
            return i;
    return -1;
}

int swd_set(swd_model *m, const char *key, double v)
{
    const int i = key_index(key);
    if (i < 0)
        return fail(m, SWD_EINVAL,
                    "near-wall dispersion: unknown key '%s' (known: layerYPlus, blendYPlus, CT, Cmu)",
                    key ? key : "(null)");
    /* quiet comparisons: a NaN is refused without a floating-point trap */
    const int low_ok = keys[i].lo_open ? isgreater(v, keys[i].lo) : isgreaterequal(v, keys[i].lo);
    if (!(low_ok && islessequal(v, keys[i].hi)))
        return fail(m, SWD_EINVAL, "near-wall dispersion: %s = %g is outside %s%g, %g]", key, v,
                    keys[i].lo_open ? "(" : "[", keys[i].lo, keys[i].hi);
    m->v[i] = v;
    m->ready = 0;
    m->err[0] = '\0';
    return SWD_OK;
}

double swd_get(const swd_model *m, const char *key)
{
    const int i = key_index(key);
    return i < 0 ? NAN : m->v[i];
}

static const char *const scale_names[] = { "max", "wallShear", "turbulence", "wallCell" };

const char *swd_scale_name(int scale)
{
    return scale >= SWD_USTAR_MAX && scale <= SWD_USTAR_WALLCELL ? scale_names[scale] : NULL;
}

int swd_scale_of(const char *name)
{
    for (int i = SWD_USTAR_MAX; name && i <= SWD_USTAR_WALLCELL; i++)
        if (!strcmp(name, scale_names[i]))
            return i;
    return -1;
}

int swd_set_scale(swd_model *m, int scale)
{
    if (!swd_scale_name(scale))
        return fail(m, SWD_EINVAL,
                    "near-wall dispersion: velocity scale %d is not one of 0 (max), 1 (wallShear), 2 (turbulence), 3 (wallCell)",
                    scale);
    m->scale = scale;
    m->ready = 0;
    return SWD_OK;
}

int swd_get_scale(const swd_model *m)
{
    return m->scale;
}

int swd_commit(swd_model *m)
{
    if (m->cl_n && m->cl_ysub > m->v[K_LAYER])
        return fail(m, SWD_EINVAL,
                    "near-wall dispersion: the closure's sublayerYPlus = %g is above layerYPlus = %g",
                    m->cl_ysub, m->v[K_LAYER]);
    if (!(m->v[K_BLEND] > m->v[K_LAYER]))
        return fail(m, SWD_EINVAL,
                    "near-wall dispersion: blendYPlus = %g must be above layerYPlus = %g",
                    m->v[K_BLEND], m->v[K_LAYER]);
    m->cmu4 = pow(m->v[K_CMU], 0.25);
    m->ready = 1;
    m->err[0] = '\0';
    return SWD_OK;
}

int swd_ready(const swd_model *m)
{
    return m && m->ready;
}

void swd_describe(const swd_model *m, char *buf, size_t n)
{
    if (!n)
        return;
    snprintf(buf, n,
             "continuous random walk: wall-layer statistics (v' Guha 1997, u', w', T_L Kallio & Reeks 1989) up to y+ %g, "
             "isotropic sqrt(2k/3) with T_L = %g k/eps from y+ %g, u* = %s%g^(1/4) k%s^(1/2)%s, "
             "drift d sigma_i / d x_i (well mixed)",
             m->v[K_LAYER], m->v[K_CT], m->v[K_BLEND],
             m->scale == SWD_USTAR_SHEAR ? "u_tau (not "
             : (m->scale == SWD_USTAR_MAX || m->scale == SWD_USTAR_WALLCELL) ? "max(u_tau, " : "",
             m->v[K_CMU], m->scale == SWD_USTAR_WALLCELL ? "_wallcell" : "",
             m->scale == SWD_USTAR_TURBULENCE ? " (not u_tau)" : ")");
}

void swd_wall_frame(const double n_out[3], const double u[3], double es[3], double en[3],
                    double ez[3])
{
    for (int k = 0; k < 3; k++)
        en[k] = -n_out[k];
    const double un = u[0] * en[0] + u[1] * en[1] + u[2] * en[2];
    for (int k = 0; k < 3; k++)
        es[k] = u[k] - un * en[k];
    double se = sqrt(es[0] * es[0] + es[1] * es[1] + es[2] * es[2]);
    const double mu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (!(se >= 1e-15 * (mu + 1e-300)) || !(se >= 1e-300)) {
        /* no flow along the wall: any direction in its plane */
        const double t[3] = { fabs(en[0]) < 0.9 ? 1 : 0, fabs(en[0]) < 0.9 ? 0 : 1, 0 };
        const double tn = t[0] * en[0] + t[1] * en[1] + t[2] * en[2];
        for (int k = 0; k < 3; k++)
            es[k] = t[k] - tn * en[k];
        se = sqrt(es[0] * es[0] + es[1] * es[1] + es[2] * es[2]);
    }
    for (int k = 0; k < 3; k++)
        es[k] /= se;
    ez[0] = es[1] * en[2] - es[2] * en[1];
    ez[1] = es[2] * en[0] - es[0] * en[2];
    ez[2] = es[0] * en[1] - es[1] * en[0];
}

double swd_contact_speed(const swd_stats *st, double nu, double d)
{
    return st->ustar * swp_uplus(0.5 * d * st->ustar / nu);
}

static int finite_nonneg(double x)
{
    return isfinite(x) && x >= 0.0;
}

static int finite_pos(double x)
{
    return isfinite(x) && x > 0.0;
}

/* the isotropic bulk: sigma_i = sqrt(2k/3) in every direction and its
   derivative along i, ds_iso[i] = (dk/dx_i) / (3 sigma) */
static void bulk_stats(double s_iso, const double ds_iso[3], double tl_iso, swd_stats *out)
{
    for (int i = 0; i < 3; i++) {
        out->sigma[i] = s_iso;
        out->dsigma[i] = ds_iso[i];
    }
    out->tl = tl_iso;
    out->layer = 0.0;
}

/* the statistics at a place; with slope 0 only sigma, T_L, u*, y+ and the
   layer's weight (the step's midpoint needs sigma alone), dsigma left 0 */
static int stats(const swd_model *m, const swd_local *at, swd_stats *out, int slope)
{
    if (!isfinite(at->y) || !finite_nonneg(at->u_tau) || !finite_pos(at->nu)
        || !finite_nonneg(at->k) || !finite_nonneg(at->eps) || !finite_nonneg(at->k_wall)
        || !isfinite(at->grad_k[0]) || !isfinite(at->grad_k[1]) || !isfinite(at->grad_k[2]))
        return SWD_EINVAL;

    /* the isotropic RANS statistics (bulk) */
    const double s_iso = sqrt(2.0 * at->k / 3.0);
    const double tl_iso = (at->k > 0.0 && at->eps > 0.0) ? m->v[K_CT] * at->k / at->eps : INFINITY;
    double ds_iso[3];
    for (int i = 0; i < 3; i++)
        ds_iso[i] = s_iso > 1e-300 ? at->grad_k[i] / (3.0 * s_iso) : 0.0;

    /* u* and its gradient (only a u* that follows the k at the particle
       changes with the particle's place) */
    const double uk = m->cmu4 * sqrt(at->k);
    double ustar, dus[3] = { 0.0, 0.0, 0.0 };
    int from_k = 0;
    switch (m->scale) {
    case SWD_USTAR_SHEAR: ustar = at->u_tau; break;
    case SWD_USTAR_TURBULENCE: ustar = uk; from_k = 1; break;
    case SWD_USTAR_WALLCELL: ustar = fmax(at->u_tau, m->cmu4 * sqrt(at->k_wall)); break;
    default: ustar = fmax(at->u_tau, uk); from_k = uk > at->u_tau; break;
    }
    if (from_k && at->k > 0.0)
        for (int j = 0; j < 3; j++)
            dus[j] = 0.5 * uk / at->k * at->grad_k[j];
    out->ustar = ustar;
    /* below 1e-30 m/s there is no turbulence to speak of (and T_L = nu / u*^2
       would overflow) */
    if (at->y < 0.0 || !(ustar > 1e-30)) {
        bulk_stats(s_iso, ds_iso, tl_iso, out);
        out->yplus = at->y < 0.0 ? -1.0 : 0.0;
        return SWD_OK;
    }

    const double yl = m->v[K_LAYER], yb = m->v[K_BLEND];
    const double yp = fmin(at->y * ustar / at->nu, 1e300);
    out->yplus = yp;
    double wl, dwl;   /* the layer's weight and its derivative d wl / d y+ */
    if (yp <= yl) {
        wl = 1.0;
        dwl = 0.0;
    } else if (yp >= yb) {
        wl = 0.0;
        dwl = 0.0;
    } else {
        wl = (yb - yp) / (yb - yl);
        dwl = -1.0 / (yb - yl);
    }
    if (wl == 0.0) {
        bulk_stats(s_iso, ds_iso, tl_iso, out);
        return SWD_OK;
    }
    out->layer = wl;

    /* the wall layer in wall units, blended with the bulk:
         sigma_i = wl(y+) u* f_i(y+) + (1 - wl(y+)) sqrt(2k/3),  y+ = y u* / nu,
       and its derivative along x_j by the chain rule through y (j = 1 only),
       u* and k */
    double f[3], df[3] = { 0.0, 0.0, 0.0 };
    swp_rms_plus(yp, f, slope ? df : NULL);
    const double tl_l = swp_tl_plus(yp) * at->nu / (ustar * ustar);
    for (int i = 0; i < 3; i++) {
        out->sigma[i] = wl * ustar * f[i] + (1.0 - wl) * s_iso;
        if (!slope) {
            out->dsigma[i] = 0.0;
            continue;
        }
        const double dyp = ((i == 1 ? ustar : 0.0) + at->y * dus[i]) / at->nu;   /* d y+ / d x_i */
        out->dsigma[i] = (dwl * (ustar * f[i] - s_iso) + wl * ustar * df[i]) * dyp
                         + wl * f[i] * dus[i] + (1.0 - wl) * ds_iso[i];
    }
    out->tl = isinf(tl_iso) ? tl_l : wl * tl_l + (1.0 - wl) * tl_iso;
    return SWD_OK;
}

int swd_stats_at(const swd_model *m, const swd_local *at, swd_stats *out)
{
    if (!swd_ready(m))
        return SWD_ENOTREADY;
    return stats(m, at, out, 1);
}

int swd_advance(const swd_model *m, const swd_local *at, double dt, double tau_p, double w[3],
                const double xi[3], double kick[3], swd_stats *st)
{
    if (!swd_ready(m))
        return SWD_ENOTREADY;
    if (!finite_pos(dt) || !finite_pos(tau_p))
        return SWD_EINVAL;
    for (int i = 0; i < 3; i++)
        if (!isfinite(w[i]) || !isfinite(xi[i]))
            return SWD_EINVAL;
    swd_stats s;
    const int rc = swd_stats_at(m, at, &s);
    if (rc != SWD_OK)
        return rc;

    double wn[3] = { w[0], w[1], w[2] };
    if (isfinite(s.tl) && s.tl > 0.0) {
        const double r = dt / s.tl;
        const double a = exp(-r);
        const double b = sqrt(-expm1(-2.0 * r));   /* sqrt(1 - a^2) */
        const double one_a = -expm1(-r);            /* 1 - a */
        for (int i = 0; i < 3; i++) {
            /* the drift in w units over the step; bounded so that an extreme
               gradient (k -> 0 with a finite dk/dx) cannot throw w to
               infinity: 8 standard deviations is never reached by a
               resolved gradient */
            const double drift = fmax(-8.0, fmin(8.0, one_a * s.tl * s.dsigma[i]));
            wn[i] = a * w[i] + b * xi[i] + (isfinite(drift) ? drift : 0.0);
        }
    }
    for (int i = 0; i < 3; i++)
        w[i] = wn[i];
    if (kick) {
        /* the fluctuation the particle sees over the coming step is sigma at
           the step's midpoint, predicted with the fluid's own displacement
           sigma w dt / 2 (along the wall normal for y, along every direction
           for k): sigma taken at the start instead piles tracers up in the
           buffer layer (20-30 % at steps of 1.2 t+, 50-65 % at 2.4 t+;
           doc/deposition.md). Where the displacement changes neither y nor
           k, the midpoint is the start */
        swd_local mid = *at;
        double dx[3];
        for (int i = 0; i < 3; i++)
            dx[i] = 0.5 * s.sigma[i] * w[i] * dt;
        if (mid.y >= 0.0)
            mid.y = fmax(0.0, mid.y + dx[1]);
        mid.k = fmax(0.0, mid.k + mid.grad_k[0] * dx[0] + mid.grad_k[1] * dx[1] + mid.grad_k[2] * dx[2]);
        swd_stats sm;
        const double *sig = s.sigma;
        if ((mid.y != at->y || mid.k != at->k) && isfinite(mid.y) && isfinite(mid.k)
            && stats(m, &mid, &sm, 0) == SWD_OK)
            sig = sm.sigma;
        /* 1 - exp(-dt/tau_p) without cancellation for dt << tau_p */
        const double f = -expm1(-dt / tau_p);
        for (int i = 0; i < 3; i++)
            kick[i] = sig[i] * w[i] * f;
    }
    if (st)
        *st = s;
    return SWD_OK;
}

/* ---- the sublayer deposition closure ------------------------------------ */

void swd_closure_off(swd_model *m)
{
    free(m->cl_lnt);
    free(m->cl_vs);
    m->cl_lnt = m->cl_vs = NULL;
    m->cl_n = 0;
    m->cl_ysub = 0.0;
}

int swd_closure_on(const swd_model *m)
{
    return m && m->cl_n > 0;
}

int swd_set_closure(swd_model *m, double sublayer_yplus, const double *tau_plus,
                    const double *vs, size_t n)
{
    if (n < 2 || n > SWD_MAX_TABLE)
        return fail(m, SWD_EINVAL, "near-wall closure: %zu table nodes (2 .. %d)", n,
                    SWD_MAX_TABLE);
    if (!(isgreater(sublayer_yplus, 0.0) && islessequal(sublayer_yplus, m->v[K_LAYER])))
        return fail(m, SWD_EINVAL,
                    "near-wall closure: sublayerYPlus = %g is outside (0, layerYPlus = %g]",
                    sublayer_yplus, m->v[K_LAYER]);
    for (size_t i = 0; i < n; i++) {
        if (!finite_pos(tau_plus[i]))
            return fail(m, SWD_EINVAL, "near-wall closure: tauPlus[%zu] = %g is not finite and > 0",
                        i, tau_plus[i]);
        if (i > 0 && !isgreater(tau_plus[i], tau_plus[i - 1]))
            return fail(m, SWD_EINVAL,
                        "near-wall closure: tauPlus[%zu] = %g does not follow %g (strictly increasing)",
                        i, tau_plus[i], tau_plus[i - 1]);
        if (!finite_nonneg(vs[i]))
            return fail(m, SWD_EINVAL,
                        "near-wall closure: vPlusSublayer[%zu] = %g is not finite and >= 0", i,
                        vs[i]);
    }
    double *lnt = malloc(n * sizeof *lnt), *v = malloc(n * sizeof *v);
    if (!lnt || !v) {
        free(lnt);
        free(v);
        return fail(m, SWD_EINVAL, "near-wall closure: out of memory");
    }
    for (size_t i = 0; i < n; i++) {
        lnt[i] = log(tau_plus[i]);
        v[i] = vs[i];
    }
    swd_closure_off(m);
    m->cl_lnt = lnt;
    m->cl_vs = v;
    m->cl_n = n;
    m->cl_ysub = sublayer_yplus;
    m->ready = 0;
    m->err[0] = '\0';
    return SWD_OK;
}

double swd_closure_vs(const swd_model *m, double tau_plus)
{
    if (isnan(tau_plus))
        return NAN;
    if (!m->cl_n)
        return 0.0;
    if (!(tau_plus > 0.0))
        return m->cl_vs[0];
    const double x = log(tau_plus);
    const size_t n = m->cl_n;
    if (x <= m->cl_lnt[0])
        return m->cl_vs[0];
    if (x >= m->cl_lnt[n - 1])
        return m->cl_vs[n - 1];
    size_t lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        if (m->cl_lnt[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    const double f = (x - m->cl_lnt[lo]) / (m->cl_lnt[hi] - m->cl_lnt[lo]);
    const double a = m->cl_vs[lo], b = m->cl_vs[hi];
    if (a > 0.0 && b > 0.0)
        return exp((1.0 - f) * log(a) + f * log(b));
    return (1.0 - f) * a + f * b;
}

double swd_deposit_rate(const swd_model *m, const swd_stats *st, double nu, double tau_stokes)
{
    if (!m->cl_n || !isgreaterequal(st->yplus, 0.0) || isgreater(st->yplus, m->cl_ysub)
        || !finite_pos(st->ustar) || !finite_pos(nu) || !finite_pos(tau_stokes))
        return 0.0;
    const double u2 = st->ustar * st->ustar;
    const double tplus = tau_stokes * u2 / nu;
    return swd_closure_vs(m, tplus) * u2 / (m->cl_ysub * nu);
}
