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

/* The checks of an impact's inputs: SWR_OK, or SWR_EINVAL with the message in r. */
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

/* The warnings of an impact on the flat wall (into r->msg): the dashpot
 * capped, JKR outside its Tabor range, a contact shorter than the Rayleigh time. */
static void impact_warnings(const swr_model *m, const swr_impact *in, swr_result *r, int plastic,
                            int damp_both, double R, double tc)
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

/* The outcome of a flat-wall impact as the steps go: open (undecided), bounce or stick. */
typedef enum { OPEN, BOUNCE, STICK } flat_outcome;

/* A flat-wall impact in scaled units: the constants set up once (flat_setup,
 * plastic_setup) and the state the velocity-Verlet steps advance (flat_step). */
typedef struct {
    /* units and constants of the impact */
    double mass, gam, T, V, L, u0, sE, Rs, Is, Gs, kd, pk, xic, mu, alpha, E0;
    int plastic, damp_both, tangential, stride, shortcut;
    swr_normal nrm;
    swr_plastic pl;
    double dstar, h_el, h_yield, h_unload, h_min, t_bound;
    /* the step, the separation and the energies of the decision */
    double h, h2, dsep, usep, eref, e_dec;
    /* state */
    double t, delta, u, x, fne, fd, fn, vt, w, ft, mr;
    swr_tangential tan;
    swr_rolling rol;
    const swr_normal *act;                           /* curve the tangential laws use */
    double wd, err, dmax, em, phi_old;
    flat_outcome outcome;
    int separated, moving_out;
    long n;
    double t_end, vt_out;
} flat_impact;

/* The physical quantities of the impact (SI) and its warnings; the scaled
 * units, the contact law and the step of the integration into s. */
static void flat_setup(flat_impact *s, const swr_model *m, const swr_impact *in, swr_result *r,
                       const swr_trace *trace)
{
    const swr_params *p = &m->p;
    memset(s, 0, sizeof *s);
    /* --- physical quantities of this impact (SI) --- */
    const double R = swr_wall_rstar(&m->wall, 0.5 * in->d);
    s->mass = p->rho * (4.0 / 3.0) * M_PI * R * R * R;
    s->gam = m->adhesive ? p->gamma : 0.0;
    const double Uc_si = m->adhesive ? swp_jkr_separation_energy(s->gam, m->Estar, R) : 0.0;
    const double v_adh = sqrt(2.0 * Uc_si / s->mass);
    const double v_ref = in->vn > v_adh ? in->vn : v_adh;
    const double tc = swp_hertz_contact_time(s->mass, R, m->Estar, v_ref);

    s->plastic = p->cor == SWR_COR_THORNTON_NING;
    r->e_target = swr_damping_target(p, m->Estar, R, s->mass, in->vn);
    s->damp_both = p->dashpot == SWR_DASHPOT_BOTH;
    s->alpha = s->plastic ? 0.0 : swr_damping_alpha_for(p, m->alpha_const, r->e_target);
    impact_warnings(m, in, r, s->plastic, s->damp_both, R, tc);

    /* --- scaled units: mass m, speed v_ref = max(vn, v_adh), time tc ---
     * (the adhesive speed keeps the length unit V tc finite for any vn: with
     * vn itself a JKR contact's radii over vn tc overflow below vn ~ 1e-85) */
    s->T = tc;
    s->V = v_ref;
    s->L = s->V * s->T;
    s->u0 = in->vn / s->V;                           /* impact speed, <= 1 */
    s->sE = s->L * s->T * s->T / s->mass;            /* modulus: F T^2/(m L) per L^2 */
    swr_normal_init(&s->nrm, R / s->L, m->Estar * s->sE, s->gam * s->T * s->T / s->mass);
    s->Rs = R / s->L;
    s->Is = 0.4 * s->Rs * s->Rs;
    s->Gs = m->Gstar * s->sE;
    s->kd = sqrt(2.0 * m->Estar * s->sE * sqrt(s->Rs)); /* c_d = alpha kd delta^(1/4) */
    s->pk = 0.8 * s->alpha * s->kd;                  /* Phi = pk delta^(5/4) */
    s->xic = p->xi_crit / s->L;
    s->mu = p->mu;
    /* step: accuracy steps per contact time, the undamped t_c shortened by
     * the damping's loading-time factor */
    const double g = swr_damping_time_factor(s->alpha);
    s->h = g / p->accuracy;
    s->h2 = 0.5 * s->h;
    s->E0 = 0.5 * s->u0 * s->u0;                     /* kinetic energy at first contact */
    s->dsep = s->nrm.delta_c;                        /* 0 for Hertz */
    s->usep = s->nrm.Uc;                             /* energy needed to separate */
    /* energy scale of the balance check: the largest of the impact energy,
     * the adhesive separation energy (slow impacts) and the kinetic energy
     * the adhesion's pull gives during the contact */
    s->eref = s->E0 > s->nrm.Uc ? s->E0 : s->nrm.Uc;
    /* no tangential motion and no trace: once the remaining normal motion is
     * conservative, finish it in closed form instead of stepping */
    s->tangential = in->vt != 0.0 || in->omega != 0.0;
    s->stride = trace && trace->fn && trace->stride > 0 ? trace->stride : 0;
    s->shortcut = !s->tangential && !s->stride;

    /* bound: SWR_CONTACT_TIMES_MAX undamped contact times t_c */
    s->t_bound = SWR_CONTACT_TIMES_MAX / g;
    s->dstar = 0.0;
    s->h_el = s->h_yield = s->h_unload = s->h_min = s->h;
}

/* Thornton-Ning: the elastic-plastic contact law, its turning point and the
 * steps and step bound of its branches into s. */
static void plastic_setup(flat_impact *s, const swr_model *m)
{
    const swr_params *p = &m->p;
    swr_plastic_init(&s->pl, s->Rs, m->Estar * s->sE, s->gam * s->T * s->T / s->mass,
                     swp_limiting_pressure(p->sigma_y) * s->sE);
    /* the turning point follows from the energy (closed form). Steps:
     * `accuracy` per time scale of each branch: the elastic loading, the
     * Hertz time (or the yield branch's, if shorter); the yield branch,
     * its half period pi/sqrt(k) (F = F_y + k z is harmonic); unloading,
     * the half period of the flattened contact's stiffness 2 E* a* at
     * the turning point, if shorter than the Hertz time. */
    s->dstar = swr_plastic_turning(&s->pl, s->E0);
    double xs;
    swr_plastic_load_work(&s->pl, s->dstar, &xs);
    const double tu = M_PI / sqrt(2.0 * m->Estar * s->sE * xs * xs);
    const double tp = M_PI / sqrt(s->pl.k);
    s->h_el = (tp < 1.0 ? tp : 1.0) / p->accuracy;
    s->h_yield = tp / p->accuracy;
    s->h_unload = (tu < 1.0 ? tu : 1.0) / p->accuracy;
    s->h = s->pl.dy > 0.0 ? s->h_el : s->h_yield;   /* dy = 0: yields from the first touch */
    s->h2 = 0.5 * s->h;
    s->h_min = fmin(s->h_el, fmin(s->h_yield, s->h_unload));
    s->t_bound = SWR_CONTACT_TIMES_MAX * (1.0 + tu + tp);
}

/* Thornton-Ning without tangential motion and trace: the whole impact in
 * closed form (plastic_closed_form) into r. */
static swr_status plastic_result(flat_impact *s, swr_result *r)
{
    double t_turn, t_sep;
    const double reb = plastic_closed_form(&s->pl, s->E0, s->dstar, &t_turn, &t_sep);
    r->status = SWR_OK;
    r->dt = 0.0;
    r->steps = 0;
    r->max_steps = 0;
    r->delta_max = s->dstar * s->L;
    r->energy_err = 0.0;
    r->contact_kept = !(reb > 0.0);
    r->stick = r->contact_kept;
    r->e_n = reb > 0.0 ? sqrt(2.0 * reb) / s->u0 : 0.0;
    r->t_contact = (reb > 0.0 ? t_sep : t_turn) * s->T;
    return SWR_OK;
}

/* The state at first contact (jump-in for JKR), its trace point and the
 * outcomes known already then. */
static void flat_start(flat_impact *s, const swr_impact *in, const swr_trace *trace)
{
    /* zero from flat_setup: t, delta, fd, the tangential and rolling springs,
     * ft, mr, wd, err, dmax, phi_old, separated, moving_out, t_end, n */
    s->u = s->u0;
    s->x = s->nrm.xj;
    s->fne = swr_normal_force(&s->nrm, s->x);
    s->fn = s->fne;
    s->vt = in->vt / s->V;
    s->w = in->omega * s->T;
    s->act = &s->nrm;
    s->em = s->E0;
    s->e_dec = s->E0;   /* normal energy from the decision on (conserved) */
    s->outcome = OPEN;
    s->vt_out = s->vt;

    if (s->stride)
        trace->fn(trace->ctx, 0.0, 0.0, in->vn, s->fn * s->mass * s->L / (s->T * s->T),
                  s->x * s->x * s->L, in->vt, in->omega);
    /* Known at first contact: with E0 <= U_c it can never escape (damping
     * only removes energy); undamped, the energy is conserved. */
    if (s->plastic)
        ; /* decided on the unloading curve */
    else if (s->E0 <= s->nrm.Uc)
        s->outcome = STICK;
    else if (s->alpha == 0.0)
        s->outcome = BOUNCE;
}

/* Thornton-Ning, turned: unload from the turning point of the energy balance.
 * The normal motion does not depend on the tangential one and is
 * conservative from here, so the outcome is decided now by the exact energy
 * (as in the closed form); the steps go on for the tangential motion (and
 * the trace) of a bounce. */
static void plastic_turned(flat_impact *s)
{
    swr_plastic_unload(&s->pl, s->dstar);
    s->act = &s->pl.un;
    s->x = s->pl.xstar;
    s->dsep = swr_plastic_separation_overlap(&s->pl);
    s->usep = swr_plastic_separation_energy(&s->pl);
    if (s->E0 <= s->usep) {
        s->outcome = STICK;
        s->t_end = s->t - s->h2;
    } else {
        s->outcome = BOUNCE;
        s->e_dec = s->E0;
        s->moving_out = 1;
    }
}

/* The closing kick of the normal motion at the drifted overlap: the contact
 * force and the dashpot (the kick's half-step velocity uh, the step's old
 * overlap, velocity and dashpot force). */
static void normal_kick(flat_impact *s, double uh, double d_old, double u_old, double fd_old)
{
    if (s->plastic) {
        s->fne = swr_plastic_force(&s->pl, s->delta, &s->x);
    } else {
        s->x = swr_normal_x(&s->nrm, s->delta, s->x);
        s->fne = swr_normal_force(&s->nrm, s->x);
    }
    /* closing kick. The dashpot acts while loading, with its exact
     * impulse over the step (swr_damping.h: the opening kick took
     * h/2 F_d(old), the rest is applied here). */
    s->u = uh - s->h2 * s->fne;
    const double phi = swr_dashpot_potential(s->pk, s->delta);
    s->fd = 0.0;
    if ((uh > 0.0 || (s->damp_both && (s->delta > 0.0 || d_old > 0.0))) && s->alpha > 0.0) {
        s->u = swr_dashpot_step(s->u, phi - s->phi_old, s->h2 * fd_old, u_old, &s->wd);
        if ((s->u > 0.0 || s->damp_both) && s->delta > 0.0)
            s->fd = swr_dashpot_force(s->alpha, s->kd, s->delta, s->u);
    } else if (fd_old != 0.0) {
        s->u += s->h2 * fd_old; /* loading ended: undo the opening kick's dashpot part */
    }
    s->phi_old = phi;
    s->fn = s->fne + s->fd;
}

/* The tangential spring and rolling resistance over the drift's slip and
 * rolling increments, and the closing kick of the tangential motion (from
 * the opening kick's half-step velocities vth, wh). */
static void tangential_kick(flat_impact *s, const swr_model *m, double vth, double wh)
{
    const double a = s->x * s->x;
    /* Coulomb limit on the whole contact load: the dashpot stands for
     * the plastic contact pressure while loading */
    s->ft = swr_tangential_update(&s->tan, s->h * (vth + s->Rs * wh),
                                  swr_tangential_stiffness(s->Gs, a),
                                  swr_tangential_limit(s->mu, s->fn, s->act->Fc));
    if (m->adhesive)
        s->mr = swr_rolling_update(&s->rol, -s->h * s->Rs * wh,
                                   swr_rolling_stiffness(s->act->Fc, a, s->act->a0), s->xic);
    s->vt = vth + s->h2 * s->ft;
    s->w = wh + s->h2 * (s->Rs * s->ft + s->mr) / s->Is;
}

/* Hertz, JKR and the dashpot: the outcome once the energy after the step
 * decides it, and back to the undamped step for an elastic remainder. */
static void elastic_decision(flat_impact *s, const swr_params *p)
{
    if (s->em <= s->usep) {
        /* it can never reach delta_c: damping only removes energy */
        s->outcome = STICK;
        s->t_end = s->t;
    } else if (s->u < 0.0 && !(s->damp_both && s->alpha > 0.0 && s->delta > 0.0)) {
        /* moving out: undamped from here on, and with E > U_c the
         * energy exceeds U everywhere between here and delta_c (U
         * falls to its minimum at delta(a0), then rises to U_c), so
         * it escapes. (At u = 0 an attractive force may still pull
         * it back in: no decision there.) */
        s->outcome = BOUNCE;
        s->e_dec = s->em < s->E0 ? s->em : s->E0;
        /* the elastic remainder is slower than the damped loading:
         * back to the undamped step */
        s->h = 1.0 / p->accuracy;
        s->h2 = 0.5 * s->h;
    }
}

/* One velocity-Verlet step (kick, drift, closing kick), the energy balance,
 * the trace and the decisions: 1 when the contact is over (separated), else 0. */
static int flat_step(flat_impact *s, const swr_model *m, const swr_trace *trace)
{
    /* kick */
    const double uh = s->u - s->h2 * s->fn;
    const double vth = s->vt + s->h2 * s->ft;
    const double wh = s->w + s->h2 * (s->Rs * s->ft + s->mr) / s->Is;
    const double d_old = s->delta, u_old = s->u, fd_old = s->fd;
    /* drift */
    s->delta += s->h * uh;
    s->n++;
    s->t += s->h;
    if (s->plastic && uh < 0.0 && s->pl.branch != SWR_PL_UNLOAD)
        plastic_turned(s);
    if (s->delta < s->dsep || (s->act->gamma == 0.0 && s->delta <= s->dsep)) {
        /* the contact breaks during this drift (undamped since u < 0) */
        s->t_end = s->t - s->h + s->h * (d_old - s->dsep) / (d_old - s->delta);
        s->vt_out = vth;
        s->separated = 1;
        if (s->outcome == OPEN)
            s->e_dec = s->em < s->E0 ? s->em : s->E0;
        s->outcome = BOUNCE;
        return 1;
    }
    normal_kick(s, uh, d_old, u_old, fd_old);
    if (s->tangential)
        tangential_kick(s, m, vth, wh);
    if (s->delta > s->dmax)
        s->dmax = s->delta;

    s->em = 0.5 * s->u * s->u + (s->plastic ? swr_plastic_energy(&s->pl, s->delta, s->x)
                                            : swr_normal_energy(&s->nrm, s->x));
    if (0.5 * s->u * s->u > s->eref)
        s->eref = 0.5 * s->u * s->u;
    const double e_err = fabs(s->em + s->wd - s->E0) / s->eref;
    if (e_err > s->err)
        s->err = e_err;
    if (s->stride && s->n % s->stride == 0)
        trace->fn(trace->ctx, s->t * s->T, s->delta * s->L, s->u * s->V,
                  s->fn * s->mass * s->L / (s->T * s->T), s->x * s->x * s->L, s->vt * s->V,
                  s->w / s->T);
    if (s->u < 0.0)
        s->moving_out = 1;
    if (s->outcome == BOUNCE && s->moving_out && s->u > 0.0) {
        /* Turned back after a bounce decision: only possible within the
         * integration error of E - U_c, right at the threshold. The
         * decision stands (it used the energy); finish in closed form. */
        s->t_end = s->t + (s->plastic ? travel_time(s->act, s->e_dec - s->pl.Wstar + s->pl.Ustar,
                                                    s->act->xf, s->x)
                                      : travel_time(&s->nrm, s->e_dec, s->nrm.xf, s->x));
        s->vt_out = s->vt;
        s->separated = 1;
        return 1;
    }
    if (s->outcome == OPEN && !s->plastic)
        elastic_decision(s, &m->p);
    if (s->plastic) {
        /* the next step on the branch the contact is on now */
        const double hb = s->pl.branch == SWR_PL_UNLOAD ? s->h_unload
                        : s->pl.branch == SWR_PL_YIELD ? s->h_yield : s->h_el;
        if (hb != s->h) {
            s->h = hb;
            s->h2 = 0.5 * s->h;
        }
    }
    return 0;
}

/* After the steps: the status, a bounce's conservative remainder in closed
 * form, the step bound, and the overlap of a stick decided at first contact. */
static void flat_finish(flat_impact *s, swr_result *r)
{
    r->status = SWR_OK;
    if (s->outcome == BOUNCE && !s->separated) {
        if (s->shortcut) {
            /* conservative remainder with energy e_dec, closed form */
            double xs = s->nrm.xf;            /* separation: a_f, or 0 for Hertz */
            if (s->u > 0.0) {                 /* still loading (undamped run) */
                const double xm = swr_normal_turning_x(&s->nrm, s->e_dec, s->x);
                s->t += travel_time(&s->nrm, s->e_dec, s->x, xm)
                      + travel_time(&s->nrm, s->e_dec, xs, xm);
                const double dm = xm * xm * xm * xm / s->nrm.R - s->nrm.C * xm;
                if (dm > s->dmax)
                    s->dmax = dm;
            } else {
                s->t += travel_time(&s->nrm, s->e_dec, xs, s->x);
            }
            s->t_end = s->t;
            s->separated = 1;
        } else {
            r->status = SWR_STEP_BOUND;
        }
    } else if (s->outcome == OPEN) {
        r->status = SWR_STEP_BOUND;
        s->outcome = STICK; /* still in contact: best estimate */
        s->t_end = s->t;
    }
    if (r->status == SWR_STEP_BOUND) {
        append_msg(r, "step bound reached: outcome is the best estimate");
        s->vt_out = s->vt;
    }
    if (s->outcome == STICK && s->n == 0 && !s->plastic) {
        /* decided at first contact: the overlap an undamped approach reaches
         * (an upper bound when damped) */
        const double xm = swr_normal_turning_x(&s->nrm, s->E0, s->nrm.xj);
        s->dmax = xm * xm * xm * xm / s->nrm.R - s->nrm.C * xm;
    }
}

/* The outcome into r: rebound, contact time, overlap, energy error, and for a
 * kept contact when and where sliding and rolling stop. Returns r->status. */
static swr_status flat_result(const flat_impact *s, const swr_impact *in, swr_result *r)
{
    r->steps = s->n;
    r->contact_kept = s->outcome == STICK;
    /* rebound speed from the conserved energy past the decision */
    r->e_n = s->outcome == BOUNCE ? sqrt(2.0 * fmax(s->e_dec - s->usep, 0.0)) / s->u0 : 0.0;
    r->t_contact = s->t_end * s->T;
    r->delta_max = s->dmax * s->L;
    r->energy_err = s->err;
    if (s->outcome == BOUNCE) {
        if (in->vt > 0.0)
            r->e_t = s->vt_out * s->V / in->vt;
        r->stick = 0;
    } else {
        /* sliding and rolling of the adhered sphere stop under the adhesive
         * resistances; predict when and where (doc/kernel.md) */
        const double fs = s->mu * 2.0 * s->act->Fc, ml = 4.0 * s->act->Fc * s->xic;
        double tr = 0.0, sr = 0.0;
        r->stick = s->tangential ? swr_tangential_rest(1.0, s->Rs, s->Is, fs, ml, s->vt, s->w, &tr, &sr)
                                 : 1;
        r->t_rest = tr * s->T;
        r->s_rest = sr * s->L;
    }
    return r->status;
}

swr_status swr_collide(const swr_model *m, const swr_impact *in, swr_result *r,
                       const swr_trace *trace)
{
    memset(r, 0, sizeof *r);
    r->e_t = NAN;
    const swr_status st = check_impact(m, in, r);
    if (st != SWR_OK)
        return st;
    r->contacts = 1;
    if (m->wall.type == SWR_WALL_LATTICE)
        return swr_collide_rough(m, in, r, trace);

    flat_impact s;
    flat_setup(&s, m, in, r, trace);
    if (s.plastic) {
        plastic_setup(&s, m);
        if (s.shortcut)
            return plastic_result(&s, r);
    }
    if (!s.plastic)
        s.h_min = s.h;
    r->dt = s.h_min * s.T;
    r->max_steps = (long)ceil(s.t_bound / s.h_min) + 16;

    flat_start(&s, in, trace);
    while (s.outcome != STICK && !(s.outcome == BOUNCE && s.shortcut) && s.n < r->max_steps)
        if (flat_step(&s, m, trace))
            break;
    flat_finish(&s, r);
    return flat_result(&s, in, r);
}
