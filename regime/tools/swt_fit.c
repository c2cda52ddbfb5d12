/* swt_fit.c - GSL least-squares fit of d_crit(v_n), regime.coeffs writer. */
#include "swt_fit.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>
#include <math.h>
#include <string.h>

#include "swp_contact.h"
#include "swp_cor.h"

double swt_fit_eval(const swt_fit *f, double vn)
{
    double x = log(vn), y = 0.0;
    for (int i = f->degree; i >= 0; i--) y = y * x + f->c[i];
    return y;
}

/* d ln d / d ln v of the fit */
static double fit_slope(const swt_fit *f, double vn)
{
    double x = log(vn), y = 0.0;
    for (int i = f->degree; i >= 1; i--) y = y * x + i * f->c[i];
    return y;
}

static int fit_degree(const swt_interface *it, int deg, swt_fit *f, char *err, size_t errlen)
{
    const int n = it->n;
    gsl_matrix *X = gsl_matrix_alloc((size_t)n, (size_t)deg + 1);
    gsl_vector *y = gsl_vector_alloc((size_t)n);
    gsl_vector *c = gsl_vector_alloc((size_t)deg + 1);
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc((size_t)n, (size_t)deg + 1);
    int rc = -1;
    if (!X || !y || !c || !w) { snprintf(err, errlen, "out of memory"); goto done; }
    for (int k = 0; k < n; k++) {
        double x = log(it->vn[k]), p = 1.0;
        for (int i = 0; i <= deg; i++) { gsl_matrix_set(X, (size_t)k, (size_t)i, p); p *= x; }
        gsl_vector_set(y, (size_t)k, log(it->dcrit[k]));
    }
    /* gsl_multifit_linear's solution exactly (balanced SVD, singular values
     * below GSL_DBL_EPSILON s_0 dropped: what gsl_multifit_linear_tsvd does
     * with lambda < 0 and gsl_multifit_linear_solve with lambda 0), without its
     * covariance matrix: unused here, it divides by n - rank, 0/0 for an exact
     * fit (as many points as coefficients), a NaN that the floating-point traps
     * of the tests and of OpenFOAM catch */
    double rnorm = 0.0, snorm = 0.0;
    int st = gsl_multifit_linear_bsvd(X, w);
    if (st == GSL_SUCCESS)
        st = gsl_multifit_linear_solve(0.0, X, y, c, &rnorm, &snorm, w);
    f->chisq = rnorm * rnorm;
    if (st != GSL_SUCCESS) {
        snprintf(err, errlen, "interface fit of degree %d failed: %s", deg, gsl_strerror(st));
        goto done;
    }
    f->degree = deg;
    for (int i = 0; i <= deg; i++) f->c[i] = gsl_vector_get(c, (size_t)i);
    for (int i = deg + 1; i <= SWT_FIT_MAXDEG; i++) f->c[i] = 0.0;
    double s2 = 0.0, mx = 0.0;
    for (int k = 0; k < n; k++) {
        double r = exp(swt_fit_eval(f, it->vn[k])) / it->dcrit[k] - 1.0;
        s2 += r * r;
        if (fabs(r) > mx) mx = fabs(r);
    }
    f->rms = sqrt(s2 / n);
    f->maxres = mx;
    /* non-increasing over the span: check the derivative on a fine grid */
    f->decreasing = 1;
    for (int k = 0; k <= 200; k++) {
        double v = f->vnmin * pow(f->vnmax / f->vnmin, k / 200.0);
        if (fit_slope(f, v) > 1e-9) { f->decreasing = 0; break; }
    }
    rc = 0;
done:
    gsl_matrix_free(X); gsl_vector_free(y); gsl_vector_free(c);
    if (w) gsl_multifit_linear_free(w);
    return rc;
}

/* log-log slope of the (up to) 4 points at one end: the least-squares slope
 * with gsl_fit_linear's running means, so the same number, but without its
 * parameter variances, which divide by count - 2: 0/0 for two points, a NaN
 * that the floating-point traps catch */
static double end_slope(const swt_interface *it, int from, int count)
{
    double x[4], y[4];
    for (int k = 0; k < count; k++) {
        x[k] = log(it->vn[from + k]);
        y[k] = log(it->dcrit[from + k]);
    }
    double mx = 0.0, my = 0.0, mdx2 = 0.0, mdxdy = 0.0;
    for (int k = 0; k < count; k++) {
        mx += (x[k] - mx) / (k + 1.0);
        my += (y[k] - my) / (k + 1.0);
    }
    for (int k = 0; k < count; k++) {
        const double dx = x[k] - mx, dy = y[k] - my;
        mdx2 += (dx * dx - mdx2) / (k + 1.0);
        mdxdy += (dx * dy - mdxdy) / (k + 1.0);
    }
    return mdxdy / mdx2; /* the interface's v_n are distinct: mdx2 > 0 */
}

int swt_fit_interface(const swt_interface *it, int degree, swt_fit *f, char *err, size_t errlen)
{
    memset(f, 0, sizeof *f);
    f->degree_asked = degree;
    f->npts = it->n;
    if (degree < 1 || degree > SWT_FIT_MAXDEG) {
        snprintf(err, errlen, "--degree: '%d' must be in [1, %d]", degree, SWT_FIT_MAXDEG);
        return -1;
    }
    if (it->n < degree + 1 || it->n < 2) {
        snprintf(err, errlen, "only %d interface points: need at least %d for a degree-%d fit "
                 "(widen --vmin/--vmax or refine the grid)", it->n, degree + 1, degree);
        return -1;
    }
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    f->vnmin = it->vn[0];
    f->vnmax = it->vn[it->n - 1];
    int rc = -1;
    for (int deg = degree; deg >= 1; deg--) {
        if (fit_degree(it, deg, f, err, errlen) != 0) break;
        if (f->decreasing) { rc = 0; break; }
    }
    gsl_set_error_handler(old);
    if (rc != 0) {
        if (!f->decreasing)
            snprintf(err, errlen, "the interface points are not decreasing in v_n: no "
                     "non-increasing fit of degree <= %d exists (see interface.csv)", degree);
        return -1;
    }
    if (f->degree != degree)
        snprintf(f->note, sizeof f->note, "degree %d was not non-increasing over [%g, %g] m/s; "
                 "lowered to %d", degree, f->vnmin, f->vnmax, f->degree);
    int ne = it->n < 4 ? it->n : 4;
    f->slope_lo = end_slope(it, 0, ne);
    f->slope_hi = end_slope(it, it->n - ne, ne);
    /* the contract wants slopes < 0; use the fit's own end slope when the points
     * near an end are flat or noisy */
    if (!(f->slope_lo < 0.0)) f->slope_lo = fmin(fit_slope(f, f->vnmin), -1e-6);
    if (!(f->slope_hi < 0.0)) f->slope_hi = fmin(fit_slope(f, f->vnmax), -1e-6);
    return 0;
}

void swt_coeffs_write(FILE *fp, const swt_fit *f, const swr_params *p, double dmin, double dmax,
                      const char *label)
{
    swt_coeffs_write_ex(fp, f, p, dmin, dmax, label, NULL);
}

static void coeffs_write(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                         double dmax, const char *label, const swt_oblique *ob,
                         const swt_prob *pr, const swt_rebound *rb);

/* the probability table of one rough map (NULL for none) */
static const swt_prob *prob_of(const swt_map *mp, swt_prob *pr)
{
    if (!mp || mp->points <= 0)
        return NULL;
    *pr = (swt_prob){ mp->d, mp->v, NULL, mp->g.nd, mp->g.nv, 0, mp->p, mp->points };
    return pr;
}

void swt_coeffs_write_all(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                          double dmax, const char *label, const swt_oblique *ob,
                          const swt_map *rough, const swt_rebound *rb)
{
    swt_prob pr;
    coeffs_write(fp, f, p, dmin, dmax, label, ob, prob_of(rough, &pr), rb);
}

void swt_coeffs_write_prob(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                           double dmax, const char *label, const swt_prob *pr,
                           const swt_rebound *rb)
{
    coeffs_write(fp, f, p, dmin, dmax, label, NULL, pr, rb);
}

void swt_coeffs_write_ex(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                         double dmax, const char *label, const swt_oblique *ob)
{
    coeffs_write(fp, f, p, dmin, dmax, label, ob, NULL, NULL);
}

void swt_coeffs_write_rough(FILE *fp, const swt_fit *f, const swr_params *p, const swt_map *mp,
                            const char *label)
{
    swt_prob pr;
    coeffs_write(fp, f, p, mp->g.dmin, mp->g.dmax, label, NULL, prob_of(mp, &pr), NULL);
}

static void write_list(FILE *fp, const char *key, const double *x, size_t n)
{
    fprintf(fp, "    %-17s (", key);
    for (size_t k = 0; k < n; k++)
        fprintf(fp, "%s%.10g", k ? " " : "", x[k]);
    fprintf(fp, ");\n");
}

static void coeffs_write(FILE *fp, const swt_fit *f, const swr_params *p, double dmin,
                         double dmax, const char *label, const swt_oblique *ob,
                         const swt_prob *pr, const swt_rebound *rb)
{
    const double Es = swp_effective_modulus(p->E, p->nu, p->E_wall, p->nu_wall);
    fprintf(fp, "// regime.coeffs - stick/bounce interface of snowregime map (snowwall 0.1)\n");
    if (pr)
        fprintf(fp, "// rough wall: the interface is the p = 0.5 contour of the stick probability%s\n",
                pr->nvt ? " at v_t = 0" : "");
    fprintf(fp, "// format: doc/regime-coeffs.md\n");
    swr_params_print(p, "// material: ", fp);
    fprintf(fp, "regime\n{\n");
    fprintf(fp, "    version         1;\n");
    fprintf(fp, "    label           \"%s\";\n", label);
    fprintf(fp, "\n    // Interface d_crit(v_n): an impact with d > d_crit(v_n) bounces, else sticks.\n");
    fprintf(fp, "    representation  polynomial;\n");
    fprintf(fp, "    basis           log;            // ln(d_crit/1 m) = sum_i c_i (ln(v_n/1 m/s))^i\n");
    fprintf(fp, "    degree          %d;\n", f->degree);
    fprintf(fp, "    coeffs          (");
    for (int i = 0; i <= f->degree; i++) fprintf(fp, "%s%.17g", i ? " " : "", f->c[i]);
    fprintf(fp, ");\n\n");
    fprintf(fp, "    vnMin           %.10g;  // [m/s] span of the interface points\n", f->vnmin);
    fprintf(fp, "    vnMax           %.10g;\n", f->vnmax);
    fprintf(fp, "    dMin            %.10g;  // diameter range of the map [m]\n", dmin);
    fprintf(fp, "    dMax            %.10g;\n", dmax);
    fprintf(fp, "    slopeLow        %.10g;  // d ln d_crit / d ln v_n at vnMin\n", f->slope_lo);
    fprintf(fp, "    slopeHigh       %.10g;  // at vnMax\n", f->slope_hi);
    fprintf(fp, "\n    rmsResidual     %.6g;   // relative residual of d_crit, %d points\n",
            f->rms, f->npts);
    fprintf(fp, "    maxResidual     %.6g;\n\n", f->maxres);
    switch (p->cor) {
    case SWR_COR_ELASTIC:
        fprintf(fp, "    reboundNormal   1;              // cor elastic\n");
        break;
    case SWR_COR_CONSTANT:
        fprintf(fp, "    reboundNormal   %.10g;  // cor constant\n", p->cor_value);
        break;
    default: {
        const double py = swp_limiting_pressure(p->sigma_y);
        double vy;
        if (p->cor_pair == SWR_PAIR_PARTICLE) {
            /* R*^3 / m* = 3 / (4 pi rho): independent of the diameter */
            const double R = 0.5 * (dmin + dmax);
            vy = swp_yield_velocity_pp(py, Es, R, p->rho * 4.0 / 3.0 * M_PI * R * R * R);
        } else {
            vy = swp_yield_velocity_wall(py, Es, p->rho);
        }
        fprintf(fp, "    yieldVelocity   %.10g;  // [m/s] Thornton e_p(V_y / v_n)\n", vy);
    }
    }
    fprintf(fp, "\n    gamma           %.10g;\n", p->gamma);
    fprintf(fp, "    Estar           %.10g;\n", Es);
    fprintf(fp, "    rhoParticle     %.10g;\n", p->rho);
    fprintf(fp, "    mu              %.10g;\n", p->mu);
    if (ob)
        swt_oblique_write(fp, ob);
    if (pr && pr->nvt) {
        /* layers by v_t: the caller's p is [k][i][j] (one map per v_t); the
         * file's order is d, then v_t, then v_n */
        fprintf(fp, "\n    // Stick probability on this rough wall: the fraction of %d impact points\n"
                    "    // that stick, per diameter (rows), tangential speed (then) and normal\n"
                    "    // speed (columns); read at the impact's v_t with the regime tangential\n"
                    "    // gate, at v_t = 0 without; the interface above is the p = 0.5 contour\n"
                    "    // at v_t = 0.\n", pr->points);
        write_list(fp, "probabilityD", pr->d, (size_t)pr->nd);
        write_list(fp, "probabilityVn", pr->v, (size_t)pr->nv);
        write_list(fp, "probabilityVt", pr->vt, (size_t)pr->nvt);
        fprintf(fp, "    %-17s (", "probabilityStick");
        size_t n = 0;
        for (size_t i = 0; i < (size_t)pr->nd; i++)
            for (size_t k = 0; k < (size_t)pr->nvt; k++)
                for (size_t j = 0; j < (size_t)pr->nv; j++)
                    fprintf(fp, "%s%.6g", n++ ? " " : "",
                            (double)pr->p[(k * (size_t)pr->nd + i) * (size_t)pr->nv + j]);
        fprintf(fp, ");\n");
        fprintf(fp, "    %-17s %d;\n", "probabilityPoints", pr->points);
    } else if (pr) {
        fprintf(fp, "\n    // Stick probability on this rough wall: the fraction of %d impact points\n"
                    "    // that stick, per diameter (rows) and normal speed (columns); the\n"
                    "    // interface above is its p = 0.5 contour.\n", pr->points);
        write_list(fp, "probabilityD", pr->d, (size_t)pr->nd);
        write_list(fp, "probabilityVn", pr->v, (size_t)pr->nv);
        fprintf(fp, "    %-17s (", "probabilityStick");
        for (size_t k = 0; k < (size_t)pr->nd * pr->nv; k++)
            fprintf(fp, "%s%.6g", k ? " " : "", (double)pr->p[k]);
        fprintf(fp, ");\n");
        fprintf(fp, "    %-17s %d;\n", "probabilityPoints", pr->points);
    }
    if (rb && swt_rebound_complete(rb))
        swt_rebound_write(fp, rb);
    fprintf(fp, "}\n");
}
