/* swr_collide.c - one ice sphere hitting a wall: the collision integrator (a
 * rough wall's contacts are integrated by swr_rough.c, entered from here)
 * (see swr_collide.h; the physics and numerics are in doc/kernel.md).
 *
 * Units: the integration runs in units where the particle mass, the
 * reference speed v_ref = max(vn, v_adh) and the Hertz contact time t_c at
 * v_ref are 1 (length unit v_ref t_c), v_adh = sqrt(2 U_c/m) the elastic
 * sticking velocity: the step is 1/accuracy whatever the size or speed, slow
 * impacts, whose dynamics are set by the adhesion, get steps on the adhesive
 * time scale, and the scaled lengths stay finite for any accepted vn (the
 * impact speed is u0 = vn / v_ref <= 1).
 *
 * Scheme: velocity Verlet (kick-drift-kick), symplectic for the conservative
 * contact forces; the dashpot, linear in the velocity, is taken implicitly in
 * the closing half kick, so it stays stable for any damping. The tangential
 * spring and rolling resistance are updated with the slip and rolling
 * increments of the drift.
 *
 * Signs: delta > 0 in compression, u = d delta/dt > 0 approaching, F_n > 0
 * repulsive. Tangential axis along the impact's v_t; omega > 0 makes the
 * contact point slide along +v_t (contact-point velocity v_t + R omega).
 */
#include "swr_collide.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "swp_contact.h"
#include "swp_jkr.h"
#include "swp_cor.h"
#include "swp_time.h"
#include "swr_damping.h"
#include "swr_internal.h"
#include "swr_normal.h"
#include "swr_plastic.h"
#include "swr_rolling.h"
#include "swr_tangential.h"
#include "swr_wall.h"

swr_model *swr_model_alloc(const swr_params *p, char *err, size_t errlen)
{
    if (!p) {
        if (err && errlen)
            snprintf(err, errlen, "no parameters");
        return NULL;
    }
    if (swr_params_validate(p, err, errlen) != 0)
        return NULL;
    if (swr_damping_init() != 0) {
        if (err && errlen)
            snprintf(err, errlen, "damping calibration failed");
        return NULL;
    }
    swr_model *m = calloc(1, sizeof *m);
    if (!m) {
        if (err && errlen)
            snprintf(err, errlen, "out of memory");
        return NULL;
    }
    m->p = *p;
    swr_wall_init(&m->wall, p);
    m->Estar = swp_effective_modulus(p->E, p->nu, p->E_wall, p->nu_wall);
    m->Gstar = swp_effective_shear_modulus(p->E, p->nu, p->E_wall, p->nu_wall);
    m->adhesive = p->adhesion == SWR_ADHESION_JKR && p->gamma > 0.0;
    m->alpha_const = p->cor == SWR_COR_CONSTANT ? swr_damping_alpha_exact(p->cor_value) : 0.0;
    m->e_min = swr_damping_e_min();
    return m;
}

void swr_model_free(swr_model *m)
{
    free(m);
}

const swr_params *swr_model_params(const swr_model *m)
{
    return &m->p;
}

int swr_model_rough(const swr_model *m)
{
    return m->wall.type == SWR_WALL_LATTICE;
}

void swr_model_sample_area(const swr_model *m, double *lx, double *ly)
{
    swr_wall_sample_area(&m->wall, lx, ly);
}

double swr_model_tabor(const swr_model *m, double d, int *jkr_ok)
{
    const double lam = swp_tabor(m->p.gamma, m->Estar, swr_wall_rstar(&m->wall, 0.5 * d), m->p.z0);
    if (jkr_ok)
        *jkr_ok = lam > SWP_TABOR_JKR_MIN;
    return lam;
}

static void append_msg(swr_result *r, const char *text)
{
    const size_t len = strlen(r->msg);
    if (len + 3 >= sizeof r->msg)
        return;
    snprintf(r->msg + len, sizeof r->msg - len, "%s%s", len ? "; " : "", text);
}

static swr_status bad_input(swr_result *r, const char *what, double v, const char *range)
{
    r->status = SWR_EINVAL;
    snprintf(r->msg, sizeof r->msg, "%s = %g is invalid%s%s", what, v, range ? ": accepted " : "",
             range ? range : "");
    return SWR_EINVAL;
}

/* Duration of a conservative normal motion with energy E between the contact
 * radii x_lo^2 < x_hi^2 (x_hi may be the turning point), the integral of
 * d delta / |u| = delta'(x) dx / sqrt(2 (E - U(x))). The substitution
 * x = x_lo + (x_hi - x_lo)(1 - s^2) removes the square-root singularity at a
 * turning point, and at the separation point both delta'(x_f) and u vanish
 * linearly; Gauss-Legendre on s in [0, 1]. */
static double travel_time(const swr_normal *n, double E, double x_lo, double x_hi)
{
    static const double gx[8] = { 0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                  0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                  0.9445750230732326, 0.9894009349916499 };
    static const double gw[8] = { 0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                  0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                  0.0622535239386479, 0.0271524594117541 };
    const double w = x_hi - x_lo;
    if (!(w > 0.0))
        return 0.0;
    double sum = 0.0;
    for (int k = 0; k < 16; k++) { /* 16 nodes on [0, 1] from the 16-point rule on [-1, 1] */
        const double s = 0.5 * (1.0 + (k < 8 ? -gx[7 - k] : gx[k - 8]));
        const double x = x_lo + w * (1.0 - s * s);
        const double ke = E - swr_normal_energy(n, x);
        const double dd = 4.0 * x * x * x / n->R - n->C;
        if (ke > 0.0)
            sum += 0.5 * gw[k < 8 ? 7 - k : k - 8] * 2.0 * w * s * dd / sqrt(2.0 * ke);
    }
    return sum;
}

/* Thornton-Ning normal impact in closed form (scaled units, E0 = u0^2/2): the
 * loading ends where the work done equals the impact energy, the unloading
 * is conservative on the flattened curve. Time: elastic JKR travel, the
 * harmonic yield branch (z = delta - delta_y + F_y/k oscillates about 0 at
 * sqrt(k)), and the unloading travel to the separation. Returns the time to
 * the decision (turning point) in *t_turn and to the separation in *t_sep
 * (bounce), and the rebound energy e^2/2 (<= 0: kept). */
static double plastic_closed_form(swr_plastic *pl, double E0, double dstar, double *t_turn,
                                  double *t_sep)
{
    swr_plastic_unload(pl, dstar);
    const swr_normal *el = &pl->el;   /* its jump-in x_j is 0 for Hertz */
    double t;
    if (dstar < pl->dy) {
        t = travel_time(el, E0, el->xj, pl->xstar);
    } else {
        t = pl->Wy > 0.0 ? travel_time(el, E0, el->xj, pl->xy) : 0.0;
        const double w = sqrt(pl->k), z0 = pl->Fy / pl->k;
        const double u2 = 2.0 * (E0 - pl->Wy);
        const double amp = sqrt(z0 * z0 + (u2 > 0.0 ? u2 : 0.0) / pl->k);
        const double c = amp > 0.0 ? z0 / amp : 1.0;
        t += acos(c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c)) / w;
    }
    *t_turn = t;
    const double rebound = E0 - swr_plastic_separation_energy(pl);
    *t_sep = rebound > 0.0 ? t + travel_time(&pl->un, pl->Ustar, pl->un.xf, pl->xstar) : t;
    return rebound;
}

/* The input checks: SWR_OK, or the bad_input status (r->msg says why). */
static swr_status check_impact(const swr_model *m, const swr_impact *in, swr_result *r)
{
    if (!m || !in)
        return bad_input(r, "model or impact", NAN, NULL);
    /* each NaN is refused before it is compared: an ordered comparison of a NaN
     * raises FE_INVALID, which OpenFOAM traps */
    if (isnan(in->d) || !(in->d >= SWR_D_MIN && in->d <= SWR_D_MAX))
        return bad_input(r, "d", in->d, "1e-07 .. 0.1 m");
    if (isnan(in->vn) || !(in->vn > 0.0 && in->vn <= SWR_V_MAX))
        return bad_input(r, "vn", in->vn, "(0, 1000] m/s");
    if (!m->adhesive && in->vn < SWR_V_MIN)
        return bad_input(r, "vn", in->vn, "1e-60 .. 1000 m/s without adhesion (below 1e-60 m/s a "
                                          "Hertz contact's scaled radii overflow)");
    if (isnan(in->vt) || !(in->vt >= 0.0 && in->vt <= SWR_V_MAX))
        return bad_input(r, "vt", in->vt, "0 .. 1000 m/s");
    if (isnan(in->omega) || !(fabs(in->omega) <= SWR_V_MAX / (0.5 * in->d)))
        return bad_input(r, "omega", in->omega, "|omega| <= 1000 m/s / (d/2)");
    if (isnan(in->x) || !(fabs(in->x) <= 1.0))
        return bad_input(r, "x", in->x, "|x| <= 1 m");
    if (isnan(in->y) || !(fabs(in->y) <= 1.0))
        return bad_input(r, "y", in->y, "|y| <= 1 m");
    return SWR_OK;
}

/* The warnings of an impact: dashpot capped, Tabor parameter, Rayleigh time. */
static void impact_warnings(const swr_model *m, const swr_impact *in, swr_result *r, double R,
                            double tc, int plastic, int damp_both)
{
    const swr_params *p = &m->p;
    if (!plastic && r->e_target < (damp_both ? swr_damping_e_min_both() : m->e_min))
        append_msg(r, "plastic COR below the dashpot table: damping capped");
    if (m->adhesive) {
        int ok;
        const double lam = swr_model_tabor(m, in->d, &ok);
        if (!ok) {
            char w[96];
            snprintf(w, sizeof w, "Tabor parameter %.3g < %g: JKR outside its range (DMT/Maugis)",
                     lam, SWP_TABOR_JKR_MIN);
            append_msg(r, w);
        }
    }
    if (tc < swp_rayleigh_time(R, p->rho, swp_shear_modulus(p->E, p->nu), p->nu))
        append_msg(r, "contact shorter than the Rayleigh time: quasi-static contact law doubtful");
}

enum outcome { OPEN, BOUNCE, STICK };

/* The constants of one smooth-wall impact, in scaled units (set once), and
 * the outcome known at first contact. */
typedef struct {
    swr_normal nrm;
    swr_plastic pl;
    double T, V, L, mass, u0, E0;
    double Rs, Is, Gs, kd, pk, xic, mu, alpha;
    double h, dstar, h_el, h_yield, h_unload;
    int plastic, damp_both, tangential, stride, shortcut;
    enum outcome outcome0;
} impact_setup;

/* Thornton-Ning set-up: the turning point, the steps of each branch and the
 * step bound into s, *h_min and *t_bound; returns 1 when the closed form
 * finished the impact (result in r), else 0. */
static int plastic_setup(const swr_model *m, impact_setup *s, swr_result *r, double sE,
                         double gam, double *h_min, double *t_bound)
{
    const swr_params *p = &m->p;
    const double T = s->T, L = s->L, E0 = s->E0;
    swr_plastic *pl = &s->pl;
    swr_plastic_init(pl, s->Rs, m->Estar * sE, gam * T * T / s->mass,
                     swp_limiting_pressure(p->sigma_y) * sE);
    /* the turning point follows from the energy (closed form). Steps:
     * `accuracy` per time scale of each branch: the elastic loading, the
     * Hertz time (or the yield branch's, if shorter); the yield branch,
     * its half period pi/sqrt(k) (F = F_y + k z is harmonic); unloading,
     * the half period of the flattened contact's stiffness 2 E* a* at
     * the turning point, if shorter than the Hertz time. */
    const double dstar = swr_plastic_turning(pl, E0);
    double xs;
    swr_plastic_load_work(pl, dstar, &xs);
    const double tu = M_PI / sqrt(2.0 * m->Estar * sE * xs * xs);
    const double tp = M_PI / sqrt(pl->k);
    s->dstar = dstar;
    s->h_el = (tp < 1.0 ? tp : 1.0) / p->accuracy;
    s->h_yield = tp / p->accuracy;
    s->h_unload = (tu < 1.0 ? tu : 1.0) / p->accuracy;
    s->h = pl->dy > 0.0 ? s->h_el : s->h_yield;    /* dy = 0: yields from the first touch */
    *h_min = fmin(s->h_el, fmin(s->h_yield, s->h_unload));
    *t_bound = SWR_CONTACT_TIMES_MAX * (1.0 + tu + tp);
    if (!s->shortcut)
        return 0;
    double t_turn, t_sep;
    const double reb = plastic_closed_form(pl, E0, dstar, &t_turn, &t_sep);
    r->status = SWR_OK;
    r->dt = 0.0;
    r->steps = 0;
    r->max_steps = 0;
    r->delta_max = dstar * L;
    r->energy_err = 0.0;
    r->contact_kept = !(reb > 0.0);
    r->stick = r->contact_kept;
    r->e_n = reb > 0.0 ? sqrt(2.0 * reb) / s->u0 : 0.0;
    r->t_contact = (reb > 0.0 ? t_sep : t_turn) * T;
    return 1;
}

/* Physical quantities, warnings, scaled units, step and step bound of a
 * smooth-wall impact into s; returns 1 when the plastic closed form finished
 * it (result in r), else 0. */
static int setup_impact(const swr_model *m, const swr_impact *in, swr_result *r,
                        const swr_trace *trace, impact_setup *s)
{
    const swr_params *p = &m->p;
    /* --- physical quantities of this impact (SI) --- */
    const double R = swr_wall_rstar(&m->wall, 0.5 * in->d);
    const double mass = p->rho * (4.0 / 3.0) * M_PI * R * R * R;
    const double gam = m->adhesive ? p->gamma : 0.0;
    const double Uc_si = m->adhesive ? swp_jkr_separation_energy(gam, m->Estar, R) : 0.0;
    const double v_adh = sqrt(2.0 * Uc_si / mass);
    const double v_ref = in->vn > v_adh ? in->vn : v_adh;
    const double tc = swp_hertz_contact_time(mass, R, m->Estar, v_ref);

    const int plastic = p->cor == SWR_COR_THORNTON_NING;
    r->e_target = swr_damping_target(p, m->Estar, R, mass, in->vn);
    const int damp_both = p->dashpot == SWR_DASHPOT_BOTH;
    const double alpha = plastic ? 0.0 : swr_damping_alpha_for(p, m->alpha_const, r->e_target);
    impact_warnings(m, in, r, R, tc, plastic, damp_both);

    /* --- scaled units: mass m, speed v_ref = max(vn, v_adh), time tc ---
     * (the adhesive speed keeps the length unit V tc finite for any vn: with
     * vn itself a JKR contact's radii over vn tc overflow below vn ~ 1e-85) */
    const double T = tc, V = v_ref, L = V * T;
    const double u0 = in->vn / V;                    /* impact speed, <= 1 */
    const double sE = L * T * T / mass;              /* modulus: F T^2/(m L) per L^2 */
    swr_normal_init(&s->nrm, R / L, m->Estar * sE, gam * T * T / mass);
    const double Rs = R / L;
    s->Rs = Rs;
    s->Is = 0.4 * Rs * Rs;
    s->Gs = m->Gstar * sE;
    const double kd = sqrt(2.0 * m->Estar * sE * sqrt(Rs)); /* c_d = alpha kd delta^(1/4) */
    s->kd = kd;
    s->pk = 0.8 * alpha * kd;                        /* Phi = pk delta^(5/4) */
    s->xic = p->xi_crit / L;
    s->mu = p->mu;
    s->T = T, s->V = V, s->L = L, s->mass = mass, s->u0 = u0, s->alpha = alpha;
    s->plastic = plastic, s->damp_both = damp_both;
    /* step: accuracy steps per contact time, the undamped t_c shortened by
     * the damping's loading-time factor */
    const double g = swr_damping_time_factor(alpha);
    s->h = g / p->accuracy;
    s->E0 = 0.5 * u0 * u0;                           /* kinetic energy at first contact */
    /* no tangential motion and no trace: once the remaining normal motion is
     * conservative, finish it in closed form instead of stepping */
    s->tangential = in->vt != 0.0 || in->omega != 0.0;
    s->stride = trace && trace->fn && trace->stride > 0 ? trace->stride : 0;
    s->shortcut = !s->tangential && !s->stride;
    /* Known at first contact: with E0 <= U_c it can never escape (damping
     * only removes energy); undamped, the energy is conserved. */
    s->outcome0 = OPEN;
    if (plastic)
        ; /* decided on the unloading curve */
    else if (s->E0 <= s->nrm.Uc)
        s->outcome0 = STICK;
    else if (alpha == 0.0)
        s->outcome0 = BOUNCE;

    /* bound: SWR_CONTACT_TIMES_MAX undamped contact times t_c */
    double t_bound = SWR_CONTACT_TIMES_MAX / g;
    double h_min = s->h;
    s->dstar = 0.0, s->h_el = s->h, s->h_yield = s->h, s->h_unload = s->h;
    if (plastic && plastic_setup(m, s, r, sE, gam, &h_min, &t_bound))
        return 1;
    if (!plastic)
        h_min = s->h;
    r->dt = h_min * T;
    r->max_steps = (long)ceil(t_bound / h_min) + 16;
    return 0;
}

/* The state the finish needs when the loop ends. */
typedef struct {
    enum outcome outcome;
    int separated;
    long n;
    double t, t_end, u, x, dmax, e_dec, usep, err, vt, vt_out, w;
    const swr_normal *act;
} loop_end;

/* The finish: status, the closed-form remainder of a bounce, the overlap of
 * a stick decided at first contact, the result fields, the rest prediction. */
static swr_status finish(const swr_impact *in, swr_result *r, const impact_setup *s, loop_end *e)
{
    const swr_normal *nrm = &s->nrm;
    const double T = s->T, V = s->V, L = s->L, u0 = s->u0, E0 = s->E0;
    r->status = SWR_OK;
    if (e->outcome == BOUNCE && !e->separated) {
        if (s->shortcut) {
            /* conservative remainder with energy e_dec, closed form */
            double xs = nrm->xf;              /* separation: a_f, or 0 for Hertz */
            if (e->u > 0.0) {                 /* still loading (undamped run) */
                const double xm = swr_normal_turning_x(nrm, e->e_dec, e->x);
                e->t += travel_time(nrm, e->e_dec, e->x, xm) + travel_time(nrm, e->e_dec, xs, xm);
                const double dm = xm * xm * xm * xm / nrm->R - nrm->C * xm;
                if (dm > e->dmax)
                    e->dmax = dm;
            } else {
                e->t += travel_time(nrm, e->e_dec, xs, e->x);
            }
            e->t_end = e->t;
            e->separated = 1;
        } else {
            r->status = SWR_STEP_BOUND;
        }
    } else if (e->outcome == OPEN) {
        r->status = SWR_STEP_BOUND;
        e->outcome = STICK; /* still in contact: best estimate */
        e->t_end = e->t;
    }
    if (r->status == SWR_STEP_BOUND) {
        append_msg(r, "step bound reached: outcome is the best estimate");
        e->vt_out = e->vt;
    }
    if (e->outcome == STICK && e->n == 0 && !s->plastic) {
        /* decided at first contact: the overlap an undamped approach reaches
         * (an upper bound when damped) */
        const double xm = swr_normal_turning_x(nrm, E0, nrm->xj);
        e->dmax = xm * xm * xm * xm / nrm->R - nrm->C * xm;
    }
    r->steps = e->n;
    r->contact_kept = e->outcome == STICK;
    /* rebound speed from the conserved energy past the decision */
    r->e_n = e->outcome == BOUNCE ? sqrt(2.0 * fmax(e->e_dec - e->usep, 0.0)) / u0 : 0.0;
    r->t_contact = e->t_end * T;
    r->delta_max = e->dmax * L;
    r->energy_err = e->err;
    if (e->outcome == BOUNCE) {
        if (in->vt > 0.0)
            r->e_t = e->vt_out * V / in->vt;
        r->stick = 0;
    } else {
        /* sliding and rolling of the adhered sphere stop under the adhesive
         * resistances; predict when and where (doc/kernel.md) */
        const swr_normal *act = e->act;
        const double fs = s->mu * 2.0 * act->Fc, ml = 4.0 * act->Fc * s->xic;
        double tr = 0.0, sr = 0.0;
        r->stick = s->tangential
                       ? swr_tangential_rest(1.0, s->Rs, s->Is, fs, ml, e->vt, e->w, &tr, &sr)
                       : 1;
        r->t_rest = tr * T;
        r->s_rest = sr * L;
    }
    return r->status;
}

/* Closing kick. The dashpot acts while loading, with its exact impulse over
 * the step (swr_damping.h: the opening kick took h/2 F_d(old), the rest is
 * applied here). Returns u; sets *fd, *phi_old, *wd. */
static inline double closing_kick(double alpha, double kd, double pk, int damp_both, double uh,
                                  double fne, double h2, double delta, double d_old, double u_old,
                                  double fd_old, double *fd, double *phi_old, double *wd)
{
    double u = uh - h2 * fne;
    const double phi = swr_dashpot_potential(pk, delta);
    *fd = 0.0;
    if ((uh > 0.0 || (damp_both && (delta > 0.0 || d_old > 0.0))) && alpha > 0.0) {
        u = swr_dashpot_step(u, phi - *phi_old, h2 * fd_old, u_old, wd);
        if ((u > 0.0 || damp_both) && delta > 0.0)
            *fd = swr_dashpot_force(alpha, kd, delta, u);
    } else if (fd_old != 0.0) {
        u += h2 * fd_old; /* loading ended: undo the opening kick's dashpot part */
    }
    *phi_old = phi;
    return u;
}

/* Tangential and rolling kicks from the slip and rolling increments of the
 * drift: sets *ft, *mr, *vt, *w. */
static inline void tangential_kick(const swr_model *m, double Rs, double Is, double Gs,
                                   double mu, double xic, const swr_normal *act,
                                   swr_tangential *tan, swr_rolling *rol, double h, double h2,
                                   double x, double fn, double vth, double wh, double *ft,
                                   double *mr, double *vt, double *w)
{
    const double a = x * x;
    /* Coulomb limit on the whole contact load: the dashpot stands for
     * the plastic contact pressure while loading */
    *ft = swr_tangential_update(tan, h * (vth + Rs * wh), swr_tangential_stiffness(Gs, a),
                                swr_tangential_limit(mu, fn, act->Fc));
    if (m->adhesive)
        *mr = swr_rolling_update(rol, -h * Rs * wh, swr_rolling_stiffness(act->Fc, a, act->a0),
                                 xic);
    *vt = vth + h2 * *ft;
    *w = wh + h2 * (Rs * *ft + *mr) / Is;
}

/* The velocity-Verlet loop from first contact to the decision (and on, for
 * the tangential motion and the trace), then the finish. */
static swr_status integrate(const swr_model *m, const swr_impact *in, swr_result *r,
                            const swr_trace *trace, impact_setup *s)
{
    const swr_params *p = &m->p;
    const swr_normal *const nrm = &s->nrm;
    swr_plastic *const pl = &s->pl;
    const double T = s->T, V = s->V, L = s->L, mass = s->mass, E0 = s->E0;
    const double Rs = s->Rs, Is = s->Is, alpha = s->alpha, dstar = s->dstar;
    const double Gs = s->Gs, kd = s->kd, pk = s->pk, xic = s->xic, mu = s->mu;
    const double h_el = s->h_el, h_yield = s->h_yield, h_unload = s->h_unload;
    const int plastic = s->plastic, damp_both = s->damp_both, tangential = s->tangential;
    const int stride = s->stride, shortcut = s->shortcut;
    double h = s->h, h2 = 0.5 * h;
    double dsep = nrm->delta_c;                      /* 0 for Hertz */
    double usep = nrm->Uc;                           /* energy needed to separate */
    /* energy scale of the balance check: the largest of the impact energy,
     * the adhesive separation energy (slow impacts) and the kinetic energy
     * the adhesion's pull gives during the contact */
    double eref = E0 > nrm->Uc ? E0 : nrm->Uc;

    /* --- state at first contact (jump-in for JKR) --- */
    double t = 0.0, delta = 0.0, u = s->u0;
    double x = nrm->xj;
    double fne = swr_normal_force(nrm, x), fd = 0.0, fn = fne;
    double vt = in->vt / V, w = in->omega * T;
    swr_tangential tan = { 0.0, 0, 0.0 };
    swr_rolling rol = { 0.0, 0, 0.0 };
    const swr_normal *act = nrm;                     /* curve the tangential laws use */
    double ft = 0.0, mr = 0.0;
    double wd = 0.0, err = 0.0, dmax = 0.0, em = E0, phi_old = 0.0;
    double e_dec = E0;   /* normal energy from the decision on (conserved) */
    enum outcome outcome = s->outcome0;
    int separated = 0, moving_out = 0;
    double t_end = 0.0, vt_out = vt;

    if (stride)
        trace->fn(trace->ctx, 0.0, 0.0, in->vn, fn * mass * L / (T * T), x * x * L, in->vt,
                  in->omega);

    long n = 0;
    while (outcome != STICK && !(outcome == BOUNCE && shortcut) && n < r->max_steps) {
        /* kick */
        const double uh = u - h2 * fn;
        const double vth = vt + h2 * ft;
        const double wh = w + h2 * (Rs * ft + mr) / Is;
        const double d_old = delta, u_old = u, fd_old = fd;
        /* drift */
        delta += h * uh;
        n++;
        t += h;
        if (plastic && uh < 0.0 && pl->branch != SWR_PL_UNLOAD) {
            /* turned: unload from the turning point of the energy balance.
             * The normal motion does not depend on the tangential one and is
             * conservative from here, so the outcome is decided now by the
             * exact energy (as in the closed form); the steps go on for the
             * tangential motion (and the trace) of a bounce. */
            swr_plastic_unload(pl, dstar);
            act = &pl->un;
            x = pl->xstar;
            dsep = swr_plastic_separation_overlap(pl);
            usep = swr_plastic_separation_energy(pl);
            if (E0 <= usep) {
                outcome = STICK;
                t_end = t - h2;
            } else {
                outcome = BOUNCE;
                e_dec = E0;
                moving_out = 1;
            }
        }
        if (delta < dsep || (act->gamma == 0.0 && delta <= dsep)) {
            /* the contact breaks during this drift (undamped since u < 0) */
            t_end = t - h + h * (d_old - dsep) / (d_old - delta);
            vt_out = vth;
            separated = 1;
            if (outcome == OPEN)
                e_dec = em < E0 ? em : E0;
            outcome = BOUNCE;
            break;
        }
        if (plastic) {
            fne = swr_plastic_force(pl, delta, &x);
        } else {
            x = swr_normal_x(nrm, delta, x);
            fne = swr_normal_force(nrm, x);
        }
        u = closing_kick(alpha, kd, pk, damp_both, uh, fne, h2, delta, d_old, u_old, fd_old, &fd,
                         &phi_old, &wd);
        fn = fne + fd;
        if (tangential)
            tangential_kick(m, Rs, Is, Gs, mu, xic, act, &tan, &rol, h, h2, x, fn, vth, wh, &ft,
                            &mr, &vt, &w);
        if (delta > dmax)
            dmax = delta;

        em = 0.5 * u * u + (plastic ? swr_plastic_energy(pl, delta, x) : swr_normal_energy(nrm, x));
        if (0.5 * u * u > eref)
            eref = 0.5 * u * u;
        const double e_err = fabs(em + wd - E0) / eref;
        if (e_err > err)
            err = e_err;
        if (stride && n % stride == 0)
            trace->fn(trace->ctx, t * T, delta * L, u * V, fn * mass * L / (T * T), x * x * L,
                      vt * V, w / T);
        if (u < 0.0)
            moving_out = 1;
        if (outcome == BOUNCE && moving_out && u > 0.0) {
            /* Turned back after a bounce decision: only possible within the
             * integration error of E - U_c, right at the threshold. The
             * decision stands (it used the energy); finish in closed form. */
            t_end = t + (plastic ? travel_time(act, e_dec - pl->Wstar + pl->Ustar, act->xf, x)
                                 : travel_time(nrm, e_dec, nrm->xf, x));
            vt_out = vt;
            separated = 1;
            break;
        }
        if (outcome == OPEN && !plastic) {
            if (em <= usep) {
                /* it can never reach delta_c: damping only removes energy */
                outcome = STICK;
                t_end = t;
            } else if (u < 0.0 && !(damp_both && alpha > 0.0 && delta > 0.0)) {
                /* moving out: undamped from here on, and with E > U_c the
                 * energy exceeds U everywhere between here and delta_c (U
                 * falls to its minimum at delta(a0), then rises to U_c), so
                 * it escapes. (At u = 0 an attractive force may still pull
                 * it back in: no decision there.) */
                outcome = BOUNCE;
                e_dec = em < E0 ? em : E0;
                /* the elastic remainder is slower than the damped loading:
                 * back to the undamped step */
                h = 1.0 / p->accuracy;
                h2 = 0.5 * h;
            }
        }
        if (plastic) {
            /* the next step on the branch the contact is on now */
            const double hb = pl->branch == SWR_PL_UNLOAD ? h_unload
                            : pl->branch == SWR_PL_YIELD ? h_yield : h_el;
            if (hb != h) {
                h = hb;
                h2 = 0.5 * h;
            }
        }
    }
    loop_end e = { outcome, separated, n, t, t_end, u, x, dmax, e_dec, usep, err, vt, vt_out, w,
                   act };
    return finish(in, r, s, &e);
}

swr_status swr_collide(const swr_model *m, const swr_impact *in, swr_result *r,
                       const swr_trace *trace)
{
    memset(r, 0, sizeof *r);
    r->e_t = NAN;
    const swr_status bad = check_impact(m, in, r);
    if (bad != SWR_OK)
        return bad;
    r->contacts = 1;
    if (m->wall.type == SWR_WALL_LATTICE)
        return swr_collide_rough(m, in, r, trace);
    impact_setup s;
    if (setup_impact(m, in, r, trace, &s))
        return SWR_OK;
    return integrate(m, in, r, trace, &s);
}
