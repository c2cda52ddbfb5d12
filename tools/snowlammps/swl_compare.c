/* swl_compare.c - snowlammps: the calibrations on single contacts, the impacts
 * of every case in both codes (and at half the step in both), the tolerances
 * and the tables (summary.md, impacts.csv; doc/kernel.md, "Cross-check against
 * LAMMPS"). */
#include "swl_lammps.h"
#include "swo_err.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *case_name[] = { "hertz", "jkr-elastic", "jkr" };

#define fail(err, errlen, ...) swo_fail(-1, err, errlen, __VA_ARGS__)

/* a growing list of table lines */
typedef struct {
    char **l;
    size_t n, cap;
    int oom;
} lines;

static void add(lines *t, const char *fmt, ...)
{
    if (t->oom) return;
    char buf[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 32;
        char **q = realloc(t->l, cap * sizeof *q);
        if (!q) { t->oom = 1; return; }
        t->l = q;
        t->cap = cap;
    }
    if (!(t->l[t->n] = strdup(buf))) { t->oom = 1; return; }
    t->n++;
}

static void lines_free(lines *t)
{
    for (size_t k = 0; k < t->n; k++) free(t->l[k]);
    free(t->l);
    memset(t, 0, sizeof *t);
}

/* ------------------------------------------------------------ calibration */

static swl_spec spec(double x, double y, double vn, double vt, int jkr, double dcoef)
{
    swl_spec s = { x, y, vn, vt, jkr, dcoef, 0, 0.0, 1.0, 0 };
    return s;
}

/* the COR of LAMMPS's Hertz impact head-on at v with the tsuji input eL */
static int lmp_cor(swl_lammps *L, double eL, int flat, double v, double *cor, char *err, size_t n)
{
    swl_spec s = spec(0.0, 0.0, v, 0.0, 0, eL);
    s.flat = flat;
    swl_lres r;
    if (swl_lammps_one(L, &s, &r, err, n) != 0) return -1;
    *cor = r.v[2] / v;
    return 0;
}

/* LAMMPS's tsuji input restitution coefficient that gives the COR e on the flat
 * base plane (its polynomial alpha(e) does not give e for this dashpot:
 * measured), by the secant method; then the single-asperity COR of both codes. */
static int calibrate(swl_lammps *L, swl_ours *O, double e, const double *speeds, int nspeeds,
                     lines *log, double *eL_out, char *err, size_t n)
{
    const double v = speeds[0];
    double x0 = e, x1 = e - 0.1, c0, c1;
    if (lmp_cor(L, x0, 1, v, &c0, err, n) || lmp_cor(L, x1, 1, v, &c1, err, n)) return -1;
    double f0 = c0 - e, f1 = c1 - e;
    for (int k = 0; k < 20; k++) {
        if (fabs(f1) < 1e-5 || f1 == f0)
            break;
        const double xn = fmin(0.999, fmax(0.05, x1 - f1 * (x1 - x0) / (f1 - f0)));
        x0 = x1;
        x1 = xn;
        f0 = f1;
        if (lmp_cor(L, x1, 1, v, &c1, err, n)) return -1;
        f1 = c1 - e;
    }
    if (fabs(f1) > 1e-4)
        return fail(err, n, "LAMMPS's COR could not be calibrated to %g (input %g gives %g)", e, x1,
                    f1 + e);
    const double eL = x1;
    double c;
    if (lmp_cor(L, e, 1, v, &c, err, n)) return -1;
    add(log, "| LAMMPS tsuji input e = %.3g (its polynomial alpha(e)) gives, flat base plane, %.3g m/s | COR %.5f |",
        e, v, c);
    add(log, "| LAMMPS tsuji input e for COR %.3g (flat base plane, %.3g m/s; secant) | %.6f |", e, v, eL);
    for (int k = 0; k < nspeeds; k++) {
        const double vv = speeds[k];
        swl_ores o;
        if (lmp_cor(L, eL, 1, vv, &c, err, n)) return -1;
        add(log, "| COR on the flat base plane at %.3g m/s: LAMMPS (fix wall/gran) | %.5f |", vv, c);
        if (swl_ours_impact(O, 0, 0, vv, 0, 0, -1, 0, 0, &o, err, n)) return -1;
        add(log, "| COR on the flat base plane at %.3g m/s: snowregime (flat wall) | %.5f |", vv,
            o.v[2] / vv);
        if (lmp_cor(L, eL, 0, vv, &c, err, n)) return -1;
        add(log, "| COR head-on on one asperity (x = y = 0) at %.3g m/s: LAMMPS (pair granular) | %.5f |",
            vv, c);
        if (swl_ours_impact(O, 0, 0, vv, 0, 0, -1, 1, 0, &o, err, n)) return -1;
        add(log, "| COR head-on on one asperity (x = y = 0) at %.3g m/s: snowregime | %.5f |", vv,
            o.v[2] / vv);
    }
    *eL_out = eL;
    return 0;
}

/* Adhesion on a single contact, head-on on one asperity (the pair style; fix
 * wall/gran jkr of this LAMMPS does not separate, see doc/kernel.md): the
 * separation overlap and the sticking velocity of both codes against closed forms. */
static int jkr_single(swl_lammps *L, swl_ours *O, const swl_model *m, double eL, lines *log,
                      char *err, size_t n)
{
    const double g = m->gamma, Rs = m->Ra;
    const double af = swl_jkr_af(m, Rs, g);
    double dc, F;
    swl_jkr(m, af, Rs, g, &dc, &F);
    const double dL = swl_lammps_pulloff(m, Rs, g);
    const double Uc = swl_jkr_loss(m, Rs, g, af);
    const double UL = swl_jkr_loss(m, Rs, g, swl_a_at(m, dL, Rs, g));
    const double vs_c = sqrt(2 * Uc / m->mass), vs_L = sqrt(2 * UL / m->mass);
    add(log, "| asperity contact R* [m] | %.4g |", Rs);
    add(log, "| separation overlap: the kernel's delta_c = -3 a_f^2/R* [m] | %.4g |", dc);
    add(log, "| separation overlap: LAMMPS's criterion (pair granular jkr, with E = E*) [m] | %.4g |", dL);
    const double sts[2] = { 1.0, 0.25 };
    for (int k = 0; k < 2; k++) {
        swl_spec s = spec(0, 0, 0.3, 0, 1, 1.0);
        s.dt_factor = sts[k];
        swl_lres r;
        if (swl_lammps_one(L, &s, &r, err, n)) return -1;
        if (r.nsep)
            add(log, "| separation overlap: LAMMPS measured (elastic, 0.3 m/s, dt x %g): last step with a force / first without [m] | %.4g / %.4g |",
                sts[k], r.sep[0], r.sep[1]);
    }
    /* the base plane with JKR (fix wall/gran jkr), elastic, head-on: does it separate? */
    double dcp;
    swl_jkr(m, swl_jkr_af(m, m->R, g), m->R, g, &dcp, &F);
    const double vflat = sqrt(2 * swl_jkr_loss(m, m->R, g, swl_jkr_af(m, m->R, g)) / m->mass);
    const double vs[2] = { 0.35, 0.5 };
    for (int k = 0; k < 2; k++) {
        swl_spec s = spec(0, 0, vs[k], 0, 1, 1.0);
        s.flat = 1;
        s.pjkr = 1;
        swl_lres r;
        char what[400], e2[SWL_ERRLEN];
        if (swl_lammps_one(L, &s, &r, e2, sizeof e2) != 0)
            snprintf(what, sizeof what, "NaN (LAMMPS's result)");
        else if (r.bounce)
            snprintf(what, sizeof what, "left, v_z %.4g m/s", r.v[2]);
        else
            snprintf(what, sizeof what, "still attached after %.3g s, down to overlap %.4g m (the kernel's delta_c: %.4g m)",
                     r.t, r.dmin_f, dcp);
        add(log, "| flat base plane with fix wall/gran jkr, elastic, head-on %.3g m/s (flat V_s %.4g m/s) | %s |",
            vs[k], vflat, what);
    }
    add(log, "| energy lost at separation (closed form): kernel U_c / LAMMPS [J] | %.4g / %.4g (ratio %.3f) |",
        Uc, UL, UL / Uc);
    for (int c = 0; c < 2; c++) {
        const double cor = c == 0 ? 1.0 : -1.0, eLx = c == 0 ? 1.0 : eL;
        double vals[2];
        for (int who = 0; who < 2; who++) {
            double lo = 1e-3, hi = 5.0;
            for (int it = 0; it < 40; it++) {
                const double mid = sqrt(lo * hi);
                int stuck;
                if (who == 0) {
                    swl_ores o;
                    if (swl_ours_impact(O, 0, 0, mid, 0, 1, cor, 1, 0, &o, err, n)) return -1;
                    stuck = o.bounce == 0;
                } else {
                    swl_spec s = spec(0, 0, mid, 0, 1, eLx);
                    swl_lres r;
                    if (swl_lammps_one(L, &s, &r, err, n)) return -1;
                    stuck = r.bounce == 0;
                }
                if (stuck) lo = mid;
                else hi = mid;
                if (hi / lo < 1.002) break;
            }
            vals[who] = sqrt(lo * hi);
        }
        char name[40], extra[200] = "";
        if (c == 0) snprintf(name, sizeof name, "elastic");
        else snprintf(name, sizeof name, "COR %.3g", O->cor);
        if (c == 0)
            snprintf(extra, sizeof extra, " (closed form sqrt(2 U/m): kernel %.4g, LAMMPS %.4g)", vs_c, vs_L);
        add(log, "| sticking velocity on one asperity, %s: snowregime / LAMMPS [m/s] | %.4g / %.4g%s |",
            name, vals[0], vals[1], extra);
    }
    return 0;
}

/* ------------------------------------------------------------ comparison */

typedef struct {
    int cas;
    double V, th, x, y, vn, vt;
    swl_ores o, o2;
    swl_lres l, l2;
    int halved;
} row;

typedef struct {
    row *r;
    size_t n, cap;
} rows;

static int compare(swl_lammps *L, swl_ours *O, int cas, double eL, const double (*pts)[2],
                   int npts, const double *angles, int nangles, const double *speeds,
                   int nspeeds, int halve, rows *out, char *err, size_t n)
{
    const double cor = cas == SWL_JKR_ELASTIC ? 1.0 : -1.0;
    if (cas == SWL_JKR_ELASTIC) eL = 1.0;
    const int jkr = cas != SWL_HERTZ;
    const size_t add_n = (size_t)nspeeds * (size_t)nangles * (size_t)npts;
    if (out->n + add_n > out->cap) {
        size_t cap = out->n + add_n;
        row *q = realloc(out->r, cap * sizeof *q);
        if (!q) return fail(err, n, "out of memory for %zu impacts", cap);
        out->r = q;
        out->cap = cap;
    }
    swl_spec *specs = malloc((halve ? 2 : 1) * (add_n ? add_n : 1) * sizeof *specs);
    swl_lres *res = malloc((halve ? 2 : 1) * (add_n ? add_n : 1) * sizeof *res);
    if (!specs || !res) {
        free(specs);
        free(res);
        return fail(err, n, "out of memory for %zu impacts", add_n);
    }
    const size_t first = out->n;
    size_t ns = 0;
    int rc = 0;
    for (int iv = 0; iv < nspeeds && rc == 0; iv++)
        for (int ia = 0; ia < nangles && rc == 0; ia++) {
            const double V = speeds[iv], th = angles[ia];
            const double vn = V * cos(th * (M_PI / 180.0));
            double vt = V * sin(th * (M_PI / 180.0));
            if (vt < 1e-12 * V) vt = 0.0;
            for (int k = 0; k < npts && rc == 0; k++) {
                row *w = &out->r[out->n];
                memset(w, 0, sizeof *w);
                w->cas = cas;
                w->V = V;
                w->th = th;
                w->x = pts[k][0];
                w->y = pts[k][1];
                w->vn = vn;
                w->vt = vt;
                rc = swl_ours_impact(O, w->x, w->y, vn, vt, jkr, cor, 1, 0, &w->o, err, n);
                specs[ns++] = spec(w->x, w->y, vn, vt, jkr, eL);
                if (rc == 0 && halve) {
                    w->halved = 1;
                    rc = swl_ours_impact(O, w->x, w->y, vn, vt, jkr, cor, 1, 2 * O->accuracy,
                                         &w->o2, err, n);
                    specs[ns] = spec(w->x, w->y, vn, vt, jkr, eL);
                    specs[ns++].dt_factor = 0.5;
                }
                out->n++;
            }
        }
    if (rc == 0)
        rc = swl_lammps_run(L, specs, ns, res, err, n);
    if (rc == 0) {
        size_t k = 0;
        for (size_t i = first; i < out->n; i++) {
            out->r[i].l = res[k++];
            if (halve) out->r[i].l2 = res[k++];
        }
    }
    free(specs);
    free(res);
    return rc;
}

/* deviations in units of the impact speed V (bounces only): q[0] v_x, q[1] v_z,
 * q[2] R w_y, and the components out of the plane of incidence: q[3] v_y, q[4]
 * R w_x, q[5] R w_z; `which` 0: snowregime against LAMMPS, 1: snowregime's
 * halving, 2: LAMMPS's */
typedef struct {
    int bounce;
    double v[3], w[3];
} state;

static state st_o(const swl_ores *o)
{
    state s = { o->bounce, { o->v[0], o->v[1], o->v[2] }, { o->w[0], o->wy, o->w[2] } };
    return s;
}

static state st_l(const swl_lres *l)
{
    state s = { l->bounce, { l->v[0], l->v[1], l->v[2] }, { l->w[0], l->w[1], l->w[2] } };
    return s;
}

static int dev(const row *r, int which, double R, double q[6])
{
    const state a = which == 2 ? st_l(&r->l) : st_o(&r->o);
    const state b = which == 0 ? st_l(&r->l) : which == 1 ? st_o(&r->o2) : st_l(&r->l2);
    if (!(a.bounce && b.bounce)) return 0;
    q[0] = fabs(a.v[0] - b.v[0]) / r->V;
    q[1] = fabs(a.v[2] - b.v[2]) / r->V;
    q[2] = fabs(a.w[1] - b.w[1]) * R / r->V;
    q[3] = fabs(a.v[1] - b.v[1]) / r->V;
    q[4] = fabs(a.w[0] - b.w[0]) * R / r->V;
    q[5] = fabs(a.w[2] - b.w[2]) * R / r->V;
    return 1;
}

/* rebound energy per unit mass from v_x, v_z, w_y (what both codes report) */
static double ekin_o(const swl_ores *o, double I)
{
    return 0.5 * (o->v[0] * o->v[0] + o->v[2] * o->v[2]) + 0.5 * I * o->wy * o->wy;
}
static double ekin_l(const swl_lres *l, double I)
{
    return 0.5 * (l->v[0] * l->v[0] + l->v[2] * l->v[2]) + 0.5 * I * l->w[1] * l->w[1];
}

/* `text` as dir/name in the output set (swo_out.h: whole or not at all) */
static int write_file(swo_set *set, const char *name, const char *text, size_t len, char *err,
                      size_t n)
{
    FILE *f = swo_open(set, name, err, n);
    if (!f) return -1;
    if (len && fwrite(text, 1, len, f) != len)
        return fail(err, n, "%s: write error", swo_final(set, name));
    return 0;
}

/* impacts.csv */
static void write_csv(FILE *f, const rows *R)
{
    fprintf(f, "case,V_m_s,angle_deg,x_m,y_m,vn_m_s,vt_m_s,ours_outcome,lmp_outcome,ours_vx,lmp_vx,ours_vz,lmp_vz,"
               "lmp_vy,ours_wy,lmp_wy,lmp_wx,lmp_wz,ours_contacts,lmp_contacts,lmp_plane_contacts,"
               "ours_status,ours_energy_err,ours2_vx,ours2_vz,ours2_wy,lmp2_vx,lmp2_vz,lmp2_wy,"
               "ours_vy,ours_wx,ours_wz,ours2_vy,ours2_wx,ours2_wz,lmp2_vy,lmp2_wx,lmp2_wz\n");
    for (size_t i = 0; i < R->n; i++) {
        const row *r = &R->r[i];
        const swl_ores *o = &r->o;
        const swl_lres *l = &r->l;
        char V[40], th[40], ee[40], e3[40];
        swl_repr(r->V, V, sizeof V);
        swl_repr(r->th, th, sizeof th);
        snprintf(e3, sizeof e3, "%.3g", o->energy_err); /* snowregime collide's precision */
        swl_repr(strtod(e3, NULL), ee, sizeof ee);
        fprintf(f, "%s,%s,%s,%.4g,%.4g,%.6g,%.6g,%s,%s,%.6g,%.6g,%.6g,%.6g,%.4g,%.6g,%.6g,%.4g,%.4g,%ld,%ld,%ld,%s,%s",
                case_name[r->cas], V, th, r->x, r->y, r->vn, r->vt, o->bounce ? "bounce" : "stick",
                l->bounce ? "bounce" : "stick", o->v[0], l->v[0], o->v[2], l->v[2], l->v[1], o->wy,
                l->w[1], l->w[0], l->w[2], o->contacts, l->contacts, l->plane_contacts, o->status, ee);
        if (r->halved)
            fprintf(f, ",%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", r->o2.v[0], r->o2.v[2], r->o2.wy, r->l2.v[0],
                    r->l2.v[2], r->l2.w[1]);
        else
            fprintf(f, ",,,,,,");
        /* out of the plane of incidence (the kernel's v_out, w_out; 0 on a stick) */
        fprintf(f, ",%.6g,%.6g,%.6g", o->v[1], o->w[0], o->w[2]);
        if (r->halved)
            fprintf(f, ",%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", r->o2.v[1], r->o2.w[0], r->o2.w[2], r->l2.v[1],
                    r->l2.w[0], r->l2.w[2]);
        else
            fprintf(f, ",,,,,,");
        fprintf(f, "\n");
    }
}

/* whether one impact r of the group (case c, speed V) is within the tolerances of its case:
 * q, hq the deviations of dev(r, 0, ...), I the moment of inertia per mass and R^2, dUa the
 * separation energy a LAMMPS asperity contact does not lose */
static int within_tolerance(const row *r, int c, double V, const swl_opts *a, const swl_model *m,
                            const double q[6], int hq, double I, double dUa)
{
    const int both = r->o.bounce && r->l.bounce;
    /* contacts: on bounces (a stick is decided by energy in the kernel, which
     * stops counting there, while LAMMPS's sphere rolls on to the time bound) */
    const int same_c_b = r->o.contacts == r->l.contacts || !both;
    /* out of the plane of incidence, in every case: |dv_y| as |dv_x|, R |dw_x|
     * and R |dw_z| as R |dw_y| (doc/kernel.md: measured like the in-plane ones) */
    const int out_ok = !hq || (q[3] <= a->tol_v && q[4] <= a->tol_w && q[5] <= a->tol_w);
    int good;
    if (c == SWL_HERTZ) {
        good = r->o.bounce == r->l.bounce && same_c_b &&
               (!hq || (q[0] <= a->tol_v && q[1] <= a->tol_v && q[2] <= a->tol_w));
    } else if (c == SWL_JKR_ELASTIC) {
        /* the separation criterion accounted for: LAMMPS's rebound energy less
         * n dU is the kernel's (a LAMMPS bounce whose energy less n dU is below
         * tol_e E_in may stick in the kernel: within the difference of the criteria) */
        double e = ekin_l(&r->l, I) * r->l.bounce - ekin_o(&r->o, I) - (double)r->l.contacts * dUa / m->mass;
        e /= 0.5 * V * V;
        good = same_c_b;
        if (both) {
            good = good && fabs(e) <= a->tol_e && q[0] <= a->tol_v && q[2] <= a->tol_w;
        } else if (r->o.bounce != r->l.bounce) {
            /* a kernel stick against a LAMMPS bounce: allowed when LAMMPS's normal
             * rebound energy does not exceed what its n contacts did not lose at
             * separation (capture is decided by the normal motion; the tangential
             * motion of a captured sphere goes on along the wall) */
            const double en = 0.5 * r->l.v[2] * r->l.v[2] - (double)r->l.contacts * dUa / m->mass;
            good = r->l.bounce == 1 && en <= a->tol_e * 0.5 * V * V;
        }
    } else {
        /* JKR with the COR dashpot: LAMMPS's tsuji dashpot acts on the JKR contact
         * radius and in tension too (the kernel's only at delta > 0, on
         * sqrt(R delta)): v_z within tol_vz_jkr V (the single-contact difference),
         * and the outcome may differ when the bouncing one leaves slower than that */
        good = same_c_b;
        if (both) {
            good = good && q[0] <= a->tol_v && q[1] <= a->tol_vz_jkr && q[2] <= a->tol_w;
        } else if (r->o.bounce != r->l.bounce) {
            const double vz = r->o.bounce ? r->o.v[2] : r->l.v[2];
            good = vz <= a->tol_vz_jkr * V;
        }
    }
    return good && out_ok;
}

/* the summary's row of one case, speed and angle, those of R->r[g0]: its impacts marked in
 * done_g, those outside the tolerances appended to bad (nbad of them) */
static void summary_group(const rows *R, size_t g0, const swl_opts *a, const swl_model *m, double I, double dUa,
                          char *done_g, lines *summ, size_t *bad, size_t *nbad)
{
    const int c = R->r[g0].cas;
    const double V = R->r[g0].V, th = R->r[g0].th;
    long ng = 0, same_o = 0, same_c = 0, nb = 0, same_cb = 0, nbo = 0, nbl = 0, ok = 0;
    double mx[6] = { 0, 0, 0, 0, 0, 0 }, hal[2][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 } }, ens = 0.0;
    int any_hal = 0, nens = 0;
    for (size_t i = g0; i < R->n; i++) {
        const row *r = &R->r[i];
        if (done_g[i] || r->cas != c || r->V != V || r->th != th) continue;
        done_g[i] = 1;
        ng++;
        const int both = r->o.bounce && r->l.bounce;
        same_o += r->o.bounce == r->l.bounce;
        same_c += r->o.contacts == r->l.contacts;
        nb += both;
        same_cb += both && r->o.contacts == r->l.contacts;
        nbo += r->o.bounce;
        nbl += r->l.bounce;
        double q[6];
        const int hq = dev(r, 0, m->R, q);
        if (hq)
            for (int k = 0; k < 6; k++) mx[k] = fmax(mx[k], q[k]);
        if (r->halved) {
            any_hal = 1;
            for (int w = 0; w < 2; w++) {
                double h[6];
                if (dev(r, 1 + w, m->R, h)) {
                    hal[w][0] = fmax(hal[w][0], fmax(h[0], h[1]));
                    hal[w][1] = fmax(hal[w][1], h[2]);
                    hal[w][2] = fmax(hal[w][2], h[3]);
                    hal[w][3] = fmax(hal[w][3], fmax(h[4], h[5]));
                }
            }
        }
        /* the separation criterion accounted for: a LAMMPS contact breaks with dU less lost */
        if (c == SWL_JKR_ELASTIC && both) {
            const double e = fabs(ekin_l(&r->l, I) - ekin_o(&r->o, I) - (double)r->l.contacts * dUa / m->mass) /
                (0.5 * V * V);
            ens = nens ? fmax(ens, e) : e;
            nens++;
        }
        const int good = within_tolerance(r, c, V, a, m, q, hq, I, dUa);
        ok += good;
        if (!good)
            bad[(*nbad)++] = i;
    }
    char h0[64] = "-", h1[64] = "-", h2[64] = "-", h3[64] = "-", en[32] = "-";
    if (any_hal) {
        snprintf(h0, sizeof h0, "%.2g, %.2g", hal[0][0], hal[0][1]);
        snprintf(h1, sizeof h1, "%.2g, %.2g", hal[1][0], hal[1][1]);
        snprintf(h2, sizeof h2, "%.2g, %.2g", hal[0][2], hal[0][3]);
        snprintf(h3, sizeof h3, "%.2g, %.2g", hal[1][2], hal[1][3]);
    }
    if (nens) snprintf(en, sizeof en, "%.2g", ens);
    add(summ, "| %s | %g | %g | %ld | %ld / %ld | %ld | %ld / %ld of %ld | %.2g | %.2g | %.2g | %s | %s | %s | %.2g | %.2g | %.2g | %s | %s | %ld of %ld |",
        case_name[c], V, th, ng, nbo, nbl, same_o, same_c, same_cb, nb, mx[0], mx[1], mx[2], h0,
        h1, en, mx[3], mx[4], mx[5], h2, h3, ok, ng);
}

/* summary.md's text: the setting and the tolerances, the calibration's and the summary's
 * tables, the runs' cost and the count outside the tolerances */
static void write_summary(FILE *sf, const swl_opts *a, const swl_model *m, int npts, const lines *cal,
                          const lines *summ, const swl_ours *O, const swl_lammps *L, double secs, size_t nbad,
                          size_t nrows)
{
    fprintf(sf, "Rough wall, snowregime against LAMMPS: d = %g m ice sphere on the default\n"
                "square lattice (asperity r = %g m, spacing %g m), %d impact points (a %d x %d grid over\n"
                "the unit cell) x angles %s deg x speeds |v| (hertz %s, jkr %s m/s); constant COR %g\n"
                "(dashpot on both branches, LAMMPS tsuji calibrated to it).\n"
                "Tolerances (bounces in both codes): |dv_x|, |dv_y|, |dv_z| <= %g V, R |dw_x|, R |dw_y|, R |dw_z|\n"
                "<= %g V and the same number of contacts; hertz: the same outcome; jkr-elastic: |E_L - E_s - n dU| <= %g E_in\n"
                "instead of dv_z (dU: the separation energy a LAMMPS contact does not lose), a kernel stick\n"
                "against a LAMMPS bounce allowed when its v_z^2/2 - n dU <= %g E_in; jkr: |dv_z| <= %g V, the\n"
                "outcome may differ when the bouncing code leaves with v_z <= %g V.\n\n",
            a->d, m->r, m->sp, npts, a->grid, a->grid, a->angles_s, a->speeds_h_s, a->speeds_j_s, a->cor,
            a->tol_v, a->tol_w, a->tol_e, a->tol_e, a->tol_vz_jkr, a->tol_vz_jkr);
    for (size_t k = 0; k < cal->n; k++) fprintf(sf, "%s\n", cal->l[k]);
    fprintf(sf, "\n");
    for (size_t k = 0; k < summ->n; k++) fprintf(sf, "%s\n", summ->l[k]);
    fprintf(sf, "\n");
    fprintf(sf, "Runs: snowregime %ld impacts in %.1f s, LAMMPS %ld runs in %.1f s; total %.0f s.\n",
            O->runs, O->seconds, L->runs, L->seconds, secs);
    fprintf(sf, "impacts outside the tolerances: %zu of %zu\n", nbad, nrows);
}

/* one line per impact outside the tolerances, after the summary on the report */
static void report_outside(FILE *report, const rows *R, const size_t *bad, size_t nbad)
{
    for (size_t b = 0; b < nbad; b++) {
        const row *r = &R->r[bad[b]];
        fprintf(report, "outside: %s V %g angle %g x %.3g y %.3g: outcome %d/%d contacts %ld/%ld v_x %.4g/%.4g v_z %.4g/%.4g w_y %.4g/%.4g"
                " v_y %.4g/%.4g w_x %.4g/%.4g w_z %.4g/%.4g\n",
                case_name[r->cas], r->V, r->th, r->x, r->y, r->o.bounce, r->l.bounce, r->o.contacts,
                r->l.contacts, r->o.v[0], r->l.v[0], r->o.v[2], r->l.v[2], r->o.wy, r->l.w[1],
                r->o.v[1], r->l.v[1], r->o.w[0], r->l.w[0], r->o.w[2], r->l.w[2]);
    }
}

int swl_compare_run(const swl_opts *a, FILE *report, char *err, size_t errlen)
{
    const double t_start = swl_now();
    swl_model m;
    if (swl_model_init(&m, a->d, err, errlen) != 0) return -1;
    /* the folder is the output set's (made or checked by the caller); LAMMPS's
     * work files go to a folder of this run's own in it, never one that was there */
    char work[4200];
    snprintf(work, sizeof work, "%s/.work-XXXXXX", a->out);
    if (!mkdtemp(work))
        return fail(err, errlen, "cannot make a work folder in '%s' (%s)", a->out, strerror(errno));
    swl_lammps L = { a->lmp, a->deck, work, &m, a->lmp_steps, 100.0, 0, 0.0, 0 };
    swl_ours O;
    memset(&O, 0, sizeof O);
    O.m = &m;
    O.cor = a->cor;
    O.accuracy = m.accuracy;
    lines cal = { 0 }, summ = { 0 };
    rows R = { 0 };
    char *sbuf = NULL, *cbuf = NULL;
    size_t slen = 0, clen = 0;
    int rc = 0;
    char ver[200];
    double pts[400][2];
    const int npts = a->grid * a->grid;
    for (int i = 0; i < a->grid; i++)
        for (int j = 0; j < a->grid; j++) {
            pts[i * a->grid + j][0] = i * m.sp / a->grid;
            pts[i * a->grid + j][1] = j * m.sp / a->grid;
        }
    if (swl_lammps_version(&L, ver, sizeof ver, err, errlen) != 0) { rc = -1; goto done; }
    add(&cal, "| quantity | value |");
    add(&cal, "|---|---|");
    add(&cal, "| LAMMPS (Debian package lammps) | %s |", ver);
    add(&cal, "| d [m], R* of an asperity contact [m], particle mass [kg] | %.4g, %.4g, %.4g |", a->d,
        m.Ra, m.mass);
    add(&cal, "| E* [Pa], G* [Pa] (LAMMPS: E = 2E* with nu = 0, Mindlin k_t = 8G*) | %.6g, %.6g |", m.Es, m.Gs);
    double eL = 1.0;
    if (calibrate(&L, &O, a->cor, a->speeds_h, a->nspeeds_h, &cal, &eL, err, errlen)) { rc = -1; goto done; }
    int any_jkr = 0;
    for (int c = 0; c < a->ncases; c++) any_jkr |= a->cases[c] != SWL_HERTZ;
    if (any_jkr && !a->no_single && jkr_single(&L, &O, &m, eL, &cal, err, errlen)) { rc = -1; goto done; }
    for (int c = 0; c < a->ncases; c++) {
        const int h = a->cases[c] == SWL_HERTZ;
        if (compare(&L, &O, a->cases[c], eL, (const double (*)[2])pts, npts, a->angles, a->nangles,
                    h ? a->speeds_h : a->speeds_j, h ? a->nspeeds_h : a->nspeeds_j, a->halve, &R, err,
                    errlen)) { rc = -1; goto done; }
    }
    /* per asperity contact: the separation energy the kernel loses and LAMMPS does not */
    const double dUa = swl_jkr_loss(&m, m.Ra, m.gamma, swl_jkr_af(&m, m.Ra, m.gamma)) -
        swl_jkr_loss(&m, m.Ra, m.gamma, swl_a_at(&m, swl_lammps_pulloff(&m, m.Ra, m.gamma), m.Ra, m.gamma));

    /* per-impact table */
    FILE *cf = open_memstream(&cbuf, &clen);
    if (!cf) { rc = fail(err, errlen, "out of memory"); goto done; }
    write_csv(cf, &R);
    if (ferror(cf) | (fclose(cf) != 0)) { rc = fail(err, errlen, "out of memory"); goto done; }

    /* summary per case, speed and angle (in the order met) */
    const double I = 0.4 * m.R * m.R;
    size_t nbad = 0;
    size_t *bad = calloc(R.n ? R.n : 1, sizeof *bad); /* outside, in the order found */
    char *done_g = calloc(R.n ? R.n : 1, 1);
    if (!bad || !done_g) {
        free(bad);
        free(done_g);
        rc = fail(err, errlen, "out of memory");
        goto done;
    }
    add(&summ, "| case | V [m/s] | angle | impacts | bounces (s / L) | same outcome | same contacts (all / bounces) | max dv_x/V | max dv_z/V | max R dw_y/V | "
               "halving: snowregime | halving: LAMMPS | energy: (E_L - E_s - n dU)/E_in | "
               "max dv_y/V | max R dw_x/V | max R dw_z/V | halving v_y, R w_x/z: snowregime | halving v_y, R w_x/z: LAMMPS | within tolerance |");
    add(&summ, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (size_t g0 = 0; g0 < R.n; g0++)
        if (!done_g[g0])
            summary_group(&R, g0, a, &m, I, dUa, done_g, &summ, bad, &nbad);
    free(done_g);

    const double secs = swl_now() - t_start;
    FILE *sf = open_memstream(&sbuf, &slen);
    if (!sf) {
        free(bad);
        rc = fail(err, errlen, "out of memory");
        goto done;
    }
    write_summary(sf, a, &m, npts, &cal, &summ, &O, &L, secs, nbad, R.n);
    if (ferror(sf) | (fclose(sf) != 0) || cal.oom || summ.oom) {
        free(bad);
        rc = fail(err, errlen, "out of memory");
        goto done;
    }
    if (write_file(a->set, "impacts.csv", cbuf, clen, err, errlen) ||
        write_file(a->set, "summary.md", sbuf, slen, err, errlen) ||
        (rmdir(work), swo_commit(a->set, err, errlen) != SWO_OK)) {
        free(bad);
        rc = -1;
        goto done;
    }
    fwrite(sbuf, 1, slen, report);
    report_outside(report, &R, bad, nbad);
    free(bad);
    rc = nbad ? 3 : 0;
done:
    rmdir(work);
    swl_ours_free(&O);
    lines_free(&cal);
    lines_free(&summ);
    free(R.r);
    free(sbuf);
    free(cbuf);
    return rc;
}
