/* swr_rough.c - one ice sphere hitting a rough wall (wall lattice): the 3-D
 * multi-contact integrator (swr_wall.h has the geometry, doc/kernel.md the
 * physics and numerics).
 *
 * The sphere (position C, velocity v, spin w, all 3-D) meets hemispherical
 * asperities of radius r and the base plane between them. Every contact it
 * makes carries the whole contact model of the flat wall, with its own
 * history: the normal law (Hertz or JKR with jump-in and snap-off,
 * swr_normal.h) about its own R* and normal, the COR dashpot set from that
 * contact's own approach speed (swr_damping.h; Thornton's e_p with the yield
 * velocity of a sphere of R* and the particle's mass), the Mindlin spring with
 * its Coulomb limit (the law of swr_tangential.h as a 3-D spring kept in the
 * contact's tangent plane) and the rolling resistance (the law of
 * swr_rolling.h with a 3-D rolling displacement R (w x n)).
 *
 * Outcome, by energy. With E_esc = kinetic energy + sum over the contacts of
 * (U_k - U_c,k) + the energy held by their springs, E_esc never grows: the
 * damping and the sliding only remove energy, a contact that breaks leaves at
 * U_k = U_c,k, and a contact that forms adds -U_c,k (the adhesive hysteresis).
 * A free sphere has E_esc = its kinetic energy >= 0. So E_esc < 0 means the
 * sphere can never leave: it sticks (it may still roll or settle among the
 * asperities). It bounces when no contact holds it, it moves away from the
 * base plane and its lowest point clears the highest asperity top.
 *
 * swr_collide_rough runs in phases: rough_setup (units, contact laws, step,
 * start), rough_fly (free flight to the next touch), rough_step (one step in
 * contact: opening kick, drift, update_contacts with each contact's normal,
 * tangential and rolling laws, closing kick, dashpots, new contacts, energy
 * balance) and rough_outcome. The tangential and rolling laws are the flat
 * wall's (swr_tangential.h, swr_rolling.h) on 3-D springs. Contact detection
 * (the free flight, the search for new contacts, the opening of a contact)
 * is in swr_rough_contacts.c, the shared state in swr_rough.h.
 *
 * Numerics: velocity Verlet in units of the particle mass, the reference
 * speed max(vn, v_adh) and the flat-wall Hertz contact time at that speed (the
 * stiffest single contact); step 1/accuracy, divided by sqrt(n) while n
 * contacts act together (their stiffnesses add). The dashpot impulse over a
 * step is exact, as in swr_collide.c. Between contacts the sphere flies
 * straight: the next touch (or the exit from the asperity layer) is found in
 * closed form, so free flight costs no steps. Bounded by
 * p->rough_hold contact times spent in contact and
 * SWR_ROUGH_FLIGHTS_MAX free flights (swr_internal.h): a sphere still held
 * then (skidding over the asperities with E_esc > 0) counts as a stick, with
 * status SWR_STEP_BOUND.
 */
#include <stddef.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "swp_contact.h"
#include "swp_jkr.h"
#include "swp_time.h"
#include "swr_damping.h"
#include "swr_rolling.h"
#include "swr_rough.h"
#include "swr_spring.h"
#include "swr_tangential.h"

static void add_msg(swr_result *r, const char *text)
{
    const size_t len = strlen(r->msg);
    if (len + 3 >= sizeof r->msg)
        return;
    snprintf(r->msg + len, sizeof r->msg - len, "%s%s", len ? "; " : "", text);
}

/* Energy held by a contact's tangential and rolling springs. */
static double spring_energy(const rc_state *s, const rc_contact *c)
{
    const double a = c->x * c->x;
    double e = swr_spring_energy(swr_tangential_stiffness(s->Gs, a), swr_dot3(c->xi, c->xi));
    /* the rolling spring's k_r at this x (set by the step that set x; a
     * contact opened since has no rolling displacement yet) */
    if (c->nm->Fc > 0.0)
        e += swr_spring_energy(c->kr, swr_dot3(c->xr, c->xr)) * s->invR;
    return e;
}

/* Energies of the current state: kinetic + contact potentials + springs. */
static double state_energy(const rc_state *s, const double v[3], const double w[3],
                           double *esc)
{
    double e = 0.5 * swr_dot3(v, v) + 0.5 * s->Is * swr_dot3(w, w), below = 0.0;
    for (int k = 0; k < s->nc; k++) {
        const rc_contact *c = &s->c[k];
        e += rc_contact_energy(c) + spring_energy(s, c);
        below += c->nm->Uc;
    }
    *esc = e - below;
    return e;
}

/* Squared angular frequency of the sphere held by the current contacts, each
 * grown by a travel of the sphere towards it: the sum of their stiffnesses,
 * each the normal one 2 E* a with a^2 grown by R* travel (Hertz: a^2 = R*
 * delta), the tangential Mindlin spring 8 G* a acting on the reduced mass of
 * a rolling sphere (1/m + R^2/I = 3.5) and the rolling spring k_r R / I (at
 * the last step). */
static double held_w2(const rc_state *s, double travel)
{
    double w2 = 0.0;
    for (int k = 0; k < s->nc; k++) {
        const rc_contact *c = &s->c[k];
        const double a2 = c->x * c->x * c->x * c->x;
        w2 += (2.0 * c->nm->Es + 28.0 * s->Gs) * sqrt(a2 + c->nm->R * travel) + 2.5 * c->kr * s->invR;
    }
    return w2;
}

/* The step (contact-adaptive). he resolves the reference contact (the flat
 * wall's Hertz contact at the reference speed, at its largest overlap) with
 * `accuracy` steps per contact time; while a dashpot acts (a contact with
 * damping that is loading, or any contact with `dashpot both`) the base is
 * hd = he times the damping's loading-time factor, so the short damped
 * loading gets as many steps. A step
 *  - resolves the contacts held as finely as the reference one, with their
 *    stiffness at the end of the step (grown by the step's travel u h):
 *    w2(u h) h^2 <= w2_ref base^2, w2 taken at the longest step allowed
 *    (it grows with h, so the step found keeps the bound);
 *  - moves the sphere no farther than a step hd at the start speed v0 does:
 *    h <= hd v0 / u;
 *  - when it may reach a surface not touched yet (u h beyond the smallest gap
 *    left, s->guard - s->moved), is no longer than the fixed step for one
 *    more contact, hd / sqrt(n + 1), unless the gap itself allows more: on a
 *    dense lattice of small asperities a fast sphere meets hundreds at once;
 *  - is at most SWR_ROUGH_STRETCH times the base;
 *  - once the sphere has been in contact SWR_ROUGH_SETTLE contact times and no
 *    contact is stretched into tension (held: the impact is over, it rattles
 *    or rolls among the asperities until it sticks by energy, leaves, or
 *    reaches rough_hold; a neck in tension is a separation under way, slow
 *    near the sticking speed, kept at full resolution), resolves it
 *    SWR_ROUGH_HELD times more coarsely (omega h <= 0.4 at accuracy 60, well
 *    inside Verlet's stability limit of 2).
 * An asperity's contact is softer than the reference one (R* ~ r), and after
 * a plastic loading, in the elastic unloading and in the slow stretching of
 * an adhesive neck (u << v0) the bounds allow far longer steps than hd. */
static double step_size(const rc_state *s, double hd, double he, double v0, const double v[3],
                        double t_in)
{
    int necked = 0; /* a contact stretched into tension: a separation under way */
    for (int k = 0; k < s->nc && !necked; k++)
        necked = s->c[k].delta < 0.0;
    if (t_in > SWR_ROUGH_SETTLE && !necked) {
        /* held: past the impact, rattling or rolling among the asperities */
        hd *= SWR_ROUGH_HELD;
        he *= SWR_ROUGH_HELD;
    }
    double base = he;
    for (int k = 0; k < s->nc && base > hd; k++) {
        const rc_contact *c = &s->c[k];
        if (c->alpha > 0.0 && (s->both || swr_dot3(v, c->n) < 0.0))
            base = hd;
    }
    const double u = sqrt(swr_dot3(v, v));
    double h = SWR_ROUGH_STRETCH * base;
    if (u * h > hd * v0)
        h = hd * v0 / u;
    {
        /* the stiffness grown over the longest step bounds it from above: the
         * step it allows grows the contacts less, so it keeps the bound */
        const double w2 = held_w2(s, u * h);
        if (w2 * h * h > s->w2_ref * base * base)
            h = base * sqrt(s->w2_ref / w2);
    }
    const double gap = s->guard - s->moved;
    if (u * h > gap) {
        const double hf = hd / sqrt(s->nc + 1.0);
        if (h > hf)
            h = gap > u * hf ? gap / u : hf;
    }
    return h;
}

/* ---- the integration, in phases: set-up, free flight, one step (kicks,
 * drift, contact laws, dashpots, new contacts, energy balance), outcome ---- */

/* The sphere's motion (scaled) and the integration's bookkeeping. */
typedef struct {
    double C[3], v[3], w[3]; /* centre, velocity, spin */
    double v0;               /* start speed */
    double t, t_in;          /* time, time in contact */
    double t_first;          /* first touch (-1 before) */
    double h0, he, h_min;    /* step with and without the damping's factor, the smallest */
    double E0, eref;         /* start energy, energy scale of the balance */
    double esc;              /* the escape energy E_esc of the last balance */
    double w_diss;           /* dashpot, sliding, rolling work and the energy left at breaking */
    double err, dmax;        /* largest energy-balance error, largest overlap */
    long n, flights, contacts;
    int overflow;            /* more than RC_MAX contacts at once */
} rc_run;

/* How a phase ends the loop (RC_GO: step on). */
enum { RC_GO, RC_BOUNCE, RC_STICK, RC_STOP, RC_FLY_ON };

/* Set-up: the units (particle mass, the reference speed max(vn, v_adh), the
 * flat-wall Hertz contact time at it), the contact laws in them, the
 * reference contact of the step, the COR, the step and its bounds, and the
 * start: lowest point on the plane of the highest tops, centre above (x, y). */
static void rough_setup(const swr_model *m, const swr_impact *in, rc_state *s, rc_run *u,
                        swr_result *r)
{
    const swr_params *p = &m->p;
    /* everything but the contact array (64 kB, set contact by contact) */
    memset(s, 0, offsetof(rc_state, c));
    memset(u, 0, sizeof *u);
    s->built = INFINITY; /* no neighbour list yet */
    s->m = m;
    s->w = &m->wall;
    const double R_si = 0.5 * in->d, r_si = m->wall.r;
    const double mass = p->rho * (4.0 / 3.0) * M_PI * R_si * R_si * R_si;
    const double Ra_si = swr_wall_rstar(&m->wall, R_si);
    const double gam = m->adhesive ? p->gamma : 0.0;
    /* adhesive speed scale: the flat contact's separation energy */
    const double Uc_si = m->adhesive ? swp_jkr_separation_energy(gam, m->Estar, R_si) : 0.0;
    const double v_adh = sqrt(2.0 * Uc_si / mass);
    const double V = in->vn > v_adh ? in->vn : v_adh;
    const double T = swp_hertz_contact_time(mass, R_si, m->Estar, V);
    const double L = V * T;
    const double sE = L * T * T / mass;
    s->V = V;
    s->T = T;
    s->L = L;
    s->invL = 1.0 / L;
    s->zc = m->wall.zc / L;
    s->mass = mass;
    s->R = R_si / L;
    s->r = r_si / L;
    s->reach_a = s->R + s->r;
    swr_normal_init(&s->na, Ra_si / L, m->Estar * sE, gam * T * T / mass);
    swr_normal_init(&s->npl, s->R, m->Estar * sE, gam * T * T / mass);
    s->kda = sqrt(2.0 * m->Estar * sE * sqrt(s->na.R));
    s->kdp = sqrt(2.0 * m->Estar * sE * sqrt(s->npl.R));
    s->Is = 0.4 * s->R * s->R;
    s->invIs = 1.0 / s->Is;
    s->invR = 1.0 / s->R;
    s->Gs = m->Gstar * sE;
    s->mu = p->mu;
    s->xic = p->xi_crit / L;
    s->margin = 0.5 * (s->r < s->R ? s->r : s->R);
    {
        /* the reference contact: flat Hertz, mass 1, speed 1, at its largest
         * overlap (1/2 = (8/15) E* sqrt(R) delta^(5/2)) */
        const double Es = m->Estar * sE;
        const double dm = pow(15.0 / (16.0 * Es * sqrt(s->R)), 0.4);
        const double a = sqrt(s->R * dm);
        s->w2_ref = (2.0 * Es + 28.0 * s->Gs) * a;
        if (s->npl.Fc > 0.0) {
            const double ra = a / s->npl.a0;
            s->w2_ref += 2.5 * 4.0 * s->npl.Fc * ra * sqrt(ra) / s->R;
        }
    }

    r->e_target = swr_rough_contact_target(s, Ra_si, in->vn);
    if (m->adhesive) {
        const double lam = swp_tabor(gam, m->Estar, Ra_si, p->z0);
        if (!(lam > SWP_TABOR_JKR_MIN)) {
            char wmsg[96];
            snprintf(wmsg, sizeof wmsg, "Tabor parameter %.3g < %g: JKR outside its range (DMT/Maugis)",
                     lam, SWP_TABOR_JKR_MIN);
            add_msg(r, wmsg);
        }
    }

    /* step: 1/accuracy of the contact time, shortened by the damping's
     * loading-time factor at the impact's own COR, as on the flat wall */
    const double alpha0 = p->cor == SWR_COR_ELASTIC ? 0.0
                                                    : swr_damping_alpha_for(p, m->alpha_const, r->e_target);
    u->h0 = swr_damping_time_factor(alpha0) / p->accuracy;
    u->he = 1.0 / p->accuracy; /* the step without damping */
    s->both = p->dashpot == SWR_DASHPOT_BOTH;
    u->h_min = u->h0;
    /* steps: the time bound at the step of 16 contacts at once (h0/4); more
     * contacts than that reach this bound first */
    r->max_steps = (long)ceil(p->rough_hold * 4.0 / u->h0) + 16;

    u->C[0] = in->x / L;
    u->C[1] = in->y / L;
    u->C[2] = (swr_wall_top(s->w) + R_si) / L;
    u->v[0] = in->vt / V;
    u->v[2] = -in->vn / V;
    /* spin about the axis that makes the contact point slide along +x */
    u->w[1] = -in->omega * T;
    u->v0 = sqrt(swr_dot3(u->v, u->v));
    u->E0 = state_energy(s, u->v, u->w, &u->esc);
    u->eref = u->E0;
    u->t_first = -1.0;
}

/* Free flight (no contact held) to the next touch or out of the layer; at a
 * touch the contacts there are opened. RC_GO: in contact, step on; RC_FLY_ON:
 * nothing met in the part of the path scanned, fly on; else the loop ends. */
static int rough_fly(rc_state *s, rc_run *u, swr_result *r)
{
    if (++u->flights > SWR_ROUGH_FLIGHTS_MAX)
        return RC_STOP;
    int hi, hj;
    const double tf = swr_rough_free_flight(s, u->C, u->v, &hi, &hj);
    if (!isfinite(tf)) {
        add_msg(r, "left parallel to the wall inside the asperity layer");
        return RC_BOUNCE;
    }
    for (int q = 0; q < 3; q++)
        u->C[q] += u->v[q] * tf;
    u->t += tf;
    s->built = INFINITY; /* the neighbour list is stale after a flight */
    if (hi == INT_MAX)
        return RC_BOUNCE;
    if (hi == FLY_ON)
        return RC_FLY_ON;
    double nn[3], ah[3];
    if (hi != PLANE_ID)
        rc_asp(s, hi, hj, ah);
    const double *ap = hi == PLANE_ID ? NULL : ah;
    const double dl = rc_geometry(s, ap, u->C, nn);
    if (swr_rough_open_contact(s, hi, hj, ap, u->v, dl > 0.0 ? dl : 0.0, nn) != 0
        || swr_rough_new_contacts(s, u->C, u->v) != 0) {
        u->overflow = 1;
        return RC_STOP;
    }
    u->contacts += s->nc;
    if (u->t_first < 0.0)
        u->t_first = u->t;
    for (int k = 0; k < s->nc; k++)
        if (s->c[k].nm->Uc > u->eref)
            u->eref = s->c[k].nm->Uc;
    for (int k = 0; k < s->nc; k++)
        s->c[k].fne = swr_normal_force(s->c[k].nm, s->c[k].x);
    state_energy(s, u->v, u->w, &u->esc);
    return u->esc < 0.0 ? RC_STICK : RC_GO;
}

/* Adds contact c's force (normal force fn along its normal, its tangential
 * force) and moment (of the tangential force about the centre, the rolling
 * moment) to F and M. */
static void add_contact_force(const rc_state *s, const rc_contact *c, double fn, double F[3],
                              double M[3])
{
    const double arm[3] = { -s->R * c->n[0], -s->R * c->n[1], -s->R * c->n[2] };
    double tq[3];
    swr_cross3(arm, c->ft, tq);
    for (int q = 0; q < 3; q++) {
        F[q] += fn * c->n[q] + c->ft[q];
        M[q] += tq[q] + c->mr[q];
    }
}

/* The tangential and rolling laws of contact c (normal c->n, contact radius
 * c->x^2) over a step h at the mid-step velocity vh and spin wh: the
 * sub-models of swr_tangential.h and swr_rolling.h on the contact's 3-D
 * springs. Their work is added to *w_diss. */
static void contact_tangential(const rc_state *s, rc_contact *c, const double vh[3],
                               const double wh[3], double h, double *w_diss)
{
    const double *nn = c->n;
    /* tangential spring: slip of the contact point at mid-step */
    const double arm[3] = { -s->R * nn[0], -s->R * nn[1], -s->R * nn[2] };
    double vc[3];
    swr_cross3(wh, arm, vc);
    for (int q = 0; q < 3; q++)
        vc[q] += vh[q];
    const double vcn = swr_dot3(vc, nn);
    const double a = c->x * c->x;
    double dxi[3]; /* this step's slip increment */
    for (int q = 0; q < 3; q++)
        dxi[q] = h * (vc[q] - vcn * nn[q]);
    *w_diss += swr_tangential_update3(c->xi, dxi, swr_tangential_stiffness(s->Gs, a),
                                      swr_tangential_limit(s->mu, c->fne + c->fd, c->nm->Fc),
                                      c->ft);
    /* rolling resistance (adhesive contacts): v_r = R (w x n) */
    if (c->nm->Fc > 0.0) {
        double vr[3], dxr[3];
        swr_cross3(wh, nn, vr);
        const double vrn = swr_dot3(vr, nn);
        for (int q = 0; q < 3; q++)
            dxr[q] = h * s->R * (vr[q] - vrn * nn[q]);
        c->kr = swr_rolling_stiffness(c->nm->Fc, a, c->nm->a0);
        *w_diss += swr_rolling_update3(c->xr, dxr, c->kr, s->xic, nn, c->mr) * s->invR;
    }
}

/* The contacts at the sphere's new centre C: each breaks (its stored energy
 * and springs lost, the opening kick's dashpot part undone in vh) or takes its
 * new geometry, normal force and tangential and rolling laws; the forces and
 * moments of the closing kick (elastic normal, tangential, rolling) are summed
 * into F, M as each contact's are known. u_start gets each kept contact's
 * approach speed at the step's start (v). */
static void update_contacts(rc_state *s, rc_run *u, double h, double vh[3], const double wh[3],
                            double F[3], double M[3], double *u_start)
{
    const double h2 = 0.5 * h;
    int kk = 0;
    for (int q = 0; q < 3; q++) {
        F[q] = 0.0;
        M[q] = 0.0;
    }
    for (int k = 0; k < s->nc; k++) {
        rc_contact *c = &s->c[k];
        double nn[3];
        const double dl = rc_geometry(s, c->i == PLANE_ID ? NULL : c->a, u->C, nn);
        const int broken = c->nm->gamma > 0.0 ? dl < c->nm->delta_c : dl <= 0.0;
        if (broken) {
            /* the contact's stored energy (U_c for JKR) and its springs are lost */
            u->w_diss += rc_contact_energy(c) + spring_energy(s, c);
            s->guard = 0.0; /* it may touch again: search from the next step */
            if (c->fd != 0.0) /* undo the opening kick's dashpot part */
                for (int q = 0; q < 3; q++)
                    vh[q] -= h2 * c->fd * c->n[q];
            continue;
        }
        u_start[kk] = -swr_dot3(u->v, nn);  /* approach speed at the step's start */
        if (kk != k)
            s->c[kk] = *c;
        c = &s->c[kk++];
        memcpy(c->n, nn, sizeof c->n);
        c->dnew = dl;
        swr_spring_to_plane(c->xi, nn);
        swr_spring_to_plane(c->xr, nn);
        c->x = swr_normal_x(c->nm, dl, c->x);
        c->fne = swr_normal_force(c->nm, c->x);
        contact_tangential(s, c, vh, wh, h, &u->w_diss);
        if (dl > u->dmax)
            u->dmax = dl;
        add_contact_force(s, c, c->fne, F, M);
    }
    s->nc = kk;
}

/* The dashpots over the step, each contact's impulse exact (swr_damping.h:
 * the opening kick took h/2 F_d(old), the rest is applied to the velocity v
 * here; vh: the mid-step velocity, u_start: each contact's approach speed at
 * the step's start). Their work is added to w_diss. */
static void dashpots(rc_state *s, rc_run *u, double h, const double vh[3], const double *u_start)
{
    const double h2 = 0.5 * h;
    const int both = s->m->p.dashpot == SWR_DASHPOT_BOTH;
    double *v = u->v;
    double wd_step = 0.0;
    for (int k = 0; k < s->nc; k++) {
        rc_contact *c = &s->c[k];
        const double dl = c->dnew;
        const double phi = swr_dashpot_potential(0.8 * c->alpha * c->kd, dl);
        const double uh = -swr_dot3(vh, c->n);   /* approach speed at mid-step */
        const double fd_old = c->fd;
        c->fd = 0.0;
        if (c->alpha > 0.0 && (uh > 0.0 || (both && (dl > 0.0 || c->delta > 0.0)))) {
            const double ue = -swr_dot3(v, c->n);
            const double un = swr_dashpot_step(ue, phi - c->phi, h2 * fd_old, u_start[k], &wd_step);
            for (int q = 0; q < 3; q++)
                v[q] += (ue - un) * c->n[q];
            if ((un > 0.0 || both) && dl > 0.0)
                c->fd = swr_dashpot_force(c->alpha, c->kd, dl, un);
        } else if (fd_old != 0.0) {
            /* loading ended: undo the opening kick's dashpot part */
            for (int q = 0; q < 3; q++)
                v[q] -= h2 * fd_old * c->n[q];
        }
        c->phi = phi;
        c->delta = dl;
    }
    u->w_diss += wd_step;
}

/* One step of velocity Verlet in contact: the step size, the opening half
 * kick with the last step's forces, the drift, the contacts at the new
 * position with their laws, the closing half kick, the dashpots, the contacts
 * that form, and the energy balance. RC_GO, RC_STICK (E_esc < 0 while held)
 * or RC_STOP (too many contacts). */
static int rough_step(rc_state *s, rc_run *u, const swr_params *p, const swr_trace *trace,
                      int stride)
{
    double *C = u->C, *v = u->v, *w = u->w;
    const double h = p->rough_step == SWR_ROUGH_STEP_FIXED
                         ? u->h0 / sqrt((double)s->nc)
                         : step_size(s, u->h0, u->he, u->v0, v, u->t_in);
    const double h2 = 0.5 * h;
    if (h < u->h_min)
        u->h_min = h;
    /* --- opening half kick with the forces of the last step --- */
    double F[3] = { 0.0, 0.0, 0.0 }, M[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < s->nc; k++)
        add_contact_force(s, &s->c[k], s->c[k].fne + s->c[k].fd, F, M);
    double vh[3], wh[3];
    for (int q = 0; q < 3; q++) {
        vh[q] = v[q] + h2 * F[q];
        wh[q] = w[q] + h2 * M[q] * s->invIs;
    }
    /* --- drift --- */
    for (int q = 0; q < 3; q++)
        C[q] += h * vh[q];
    u->t += h;
    u->t_in += h;
    u->n++;
    /* --- contacts at the new position: breaking, then the laws --- */
    double u_start[RC_MAX];
    update_contacts(s, u, h, vh, wh, F, M, u_start);
    /* --- closing half kick with the new elastic and tangential forces --- */
    for (int q = 0; q < 3; q++) {
        v[q] = vh[q] + h2 * F[q];
        w[q] = wh[q] + h2 * M[q] * s->invIs;
    }
    dashpots(s, u, h, vh, u_start);
    /* --- contacts that form now (searched once the sphere may have
     * closed the smallest gap seen at the last search) --- */
    const int before = s->nc;
    const double step_len = h * sqrt(swr_dot3(vh, vh));
    s->moved += step_len;
    s->built += step_len;
    if (s->moved >= s->guard && swr_rough_new_contacts(s, C, v) != 0) {
        u->overflow = 1;
        return RC_STOP;
    }
    for (int k = before; k < s->nc; k++)
        s->c[k].fne = swr_normal_force(s->c[k].nm, s->c[k].x);
    u->contacts += s->nc - before;
    /* --- energy balance and the decision --- */
    const double e = state_energy(s, v, w, &u->esc);
    const double ke = 0.5 * swr_dot3(v, v) + 0.5 * s->Is * swr_dot3(w, w);
    if (ke > u->eref)
        u->eref = ke;
    for (int k = before; k < s->nc; k++)
        if (s->c[k].nm->Uc > u->eref)
            u->eref = s->c[k].nm->Uc;
    const double e_err = fabs(e + u->w_diss - u->E0) / u->eref;
    if (e_err > u->err)
        u->err = e_err;
    if (stride && u->n % stride == 0) {
        double fz = 0.0, amax = 0.0, dm = 0.0;
        for (int k = 0; k < s->nc; k++) {
            fz += (s->c[k].fne + s->c[k].fd) * s->c[k].n[2] + s->c[k].ft[2];
            amax = fmax(amax, s->c[k].x * s->c[k].x);
            dm = fmax(dm, s->c[k].delta);
        }
        const double T = s->T, L = s->L, V = s->V;
        trace->fn(trace->ctx, u->t * T, dm * L, -v[2] * V, fz * s->mass * L / (T * T), amax * L,
                  v[0] * V, -w[1] / T);
    }
    return s->nc > 0 && u->esc < 0.0 ? RC_STICK : RC_GO;
}

/* The outcome into r: the status and its message, the rebound (SI units, the
 * impact's frame), the contact time, overlap and energy-balance error. */
static void rough_outcome(const rc_state *s, const rc_run *u, const swr_impact *in, int outcome,
                          swr_result *r)
{
    const double T = s->T, L = s->L, V = s->V;
    r->status = SWR_OK;
    if (u->overflow) {
        r->status = SWR_STEP_BOUND;
        add_msg(r, "more than 256 asperity contacts at once: outcome is the best estimate");
    } else if (outcome == RC_GO) {
        r->status = SWR_STEP_BOUND;
        add_msg(r, s->nc > 0
                       ? "time bound (rough_hold contact times in contact) reached: still held, counted as stick"
                       : "bound on free flights reached: outcome is the best estimate");
    }
    if (outcome == RC_GO)
        outcome = s->nc > 0 ? RC_STICK : RC_BOUNCE;
    r->steps = u->n;
    r->dt = u->h_min * T;
    r->contacts = u->contacts;
    r->contact_kept = r->stick = outcome == RC_STICK;
    r->e_n = outcome == RC_BOUNCE ? fmax(u->v[2], 0.0) * V / in->vn : 0.0;
    if (in->vt > 0.0 && outcome == RC_BOUNCE)
        r->e_t = u->v[0] * V / in->vt;
    if (outcome == RC_BOUNCE)
        for (int q = 0; q < 3; q++) {
            r->v_out[q] = u->v[q] * V;
            r->w_out[q] = u->w[q] / T;
        }
    r->t_contact = u->t_first >= 0.0 ? (u->t - u->t_first) * T : 0.0;
    r->delta_max = u->dmax * L;
    r->energy_err = u->err;
    r->t_rest = r->s_rest = 0.0;
}

swr_status swr_collide_rough(const swr_model *m, const swr_impact *in, swr_result *r,
                             const swr_trace *trace)
{
    const swr_params *p = &m->p;
    if (in->d > SWR_ROUGH_D_OVER_R_MAX * m->wall.r) {
        r->status = SWR_EINVAL;
        snprintf(r->msg, sizeof r->msg,
                 "d = %g m is more than %g asperity radii (asperity_r = %g m): too many contacts "
                 "at once for the rough wall; use the flat wall", in->d, SWR_ROUGH_D_OVER_R_MAX,
                 m->wall.r);
        return SWR_EINVAL;
    }
    rc_state st, *s = &st;
    rc_run u;
    rough_setup(m, in, s, &u, r);
    const int stride = trace && trace->fn && trace->stride > 0 ? trace->stride : 0;
    int outcome = RC_GO;   /* RC_GO: still open */
    while (outcome == RC_GO) {
        if (s->nc == 0) {
            const int ev = rough_fly(s, &u, r);
            if (ev == RC_FLY_ON)
                continue;
            if (ev != RC_GO) {
                if (ev != RC_STOP)
                    outcome = ev;
                break;
            }
        }
        if (u.t_in >= p->rough_hold || u.n >= r->max_steps)
            break;
        const int ev = rough_step(s, &u, p, trace, stride);
        if (ev == RC_STOP)
            break;
        outcome = ev;
    }
    rough_outcome(s, &u, in, outcome, r);
    return r->status;
}
