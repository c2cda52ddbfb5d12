/* swr_rough_contacts.c - contact detection on the rough wall: the free
 * flight to the next touch in closed form, the search for contacts that form
 * (with a Verlet neighbour list), and the opening of a contact with its
 * normal law and dashpot (swr_rough.c has the integrator, swr_wall.h the
 * lattice). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "swp_contact.h"
#include "swp_cor.h"
#include "swr_damping.h"
#include "swr_rough.h"
#include "swr_spring.h"

/* Horizontal distance from a sphere centre at height z (above the plane of
 * the asperity centres, s->zc) within which an asperity centre (at or below
 * that plane) lies within `reach` of it; < 0: none. */
static double side_reach(double reach, double z)
{
    const double r2 = reach * reach - (z > 0.0 ? z * z : 0.0);
    return r2 > 0.0 ? sqrt(r2) : -1.0;
}

/* Plastic COR of one contact: Thornton's e_p with the yield velocity of a
 * sphere of this R* and the particle's mass (the flat wall's V_y at R* = R),
 * per asperity_yield: an asperity contact (R* < R) takes the contact's
 * (contact), the flat wall's (particle) or none (elastic, e = 1). */
double swr_rough_contact_target(const rc_state *s, double Rc_si, double vi_si)
{
    const swr_params *p = &s->m->p;
    const int asperity = Rc_si < s->R * s->L;
    if (asperity && p->asperity_yield == SWR_YIELD_ELASTIC)
        return 1.0;
    if (p->asperity_yield == SWR_YIELD_CONTACT
        && (p->cor == SWR_COR_THORNTON || p->cor == SWR_COR_THORNTON_ASYMPTOTE)
        && p->cor_pair == SWR_PAIR_WALL && asperity) {
        const double vy = swp_yield_velocity_pp(swp_limiting_pressure(p->sigma_y), s->m->Estar,
                                                Rc_si, s->mass);
        return p->cor == SWR_COR_THORNTON ? swp_cor_thornton(vy / vi_si)
                                          : swp_cor_thornton_pp_asymptote(vy / vi_si);
    }
    return swr_damping_target(p, s->m->Estar, s->R * s->L, s->mass, vi_si);
}

/* Open a contact at its first touch (delta >= 0): JKR jumps in to a_jump. */
int swr_rough_open_contact(rc_state *s, int i, int j, const double *a, const double v[3],
                           double delta, const double n[3])
{
    if (s->nc >= RC_MAX)
        return -1;
    rc_contact *c = &s->c[s->nc++];
    memset(c, 0, sizeof *c);
    c->i = i;
    c->j = j;
    if (a)
        memcpy(c->a, a, sizeof c->a);
    c->nm = i == PLANE_ID ? &s->npl : &s->na;
    c->kd = i == PLANE_ID ? s->kdp : s->kda;
    memcpy(c->n, n, sizeof c->n);
    c->delta = delta;
    c->x = delta > 0.0 ? swr_normal_x(c->nm, delta, 0.0) : c->nm->xj;
    if (c->nm->gamma > 0.0 && c->x < c->nm->xj)
        c->x = c->nm->xj;
    const double un = -swr_dot3(v, n) * s->V; /* approach speed [m/s] */
    const swr_params *p = &s->m->p;
    if (un > 0.0 && p->cor != SWR_COR_ELASTIC) {
        const double e = swr_rough_contact_target(s, c->nm->R * s->L, un);
        c->alpha = e >= 1.0 ? 0.0 /* elastic (asperity_yield elastic) */
                            : swr_damping_alpha_for(p, s->m->alpha_const, e);
    }
    c->phi = swr_dashpot_potential(0.8 * c->alpha * c->kd, delta);
    return 0;
}

/* Closed-form free flight from C with velocity v: the time to the first touch
 * of an asperity or the base plane (*hit_i, *hit_j), or to the exit from the
 * asperity layer (returns the time with *hit_i = INT_MAX). It scans the path in
 * chunks of one spacing of horizontal travel, at most SWR_ROUGH_FLIGHT_CELLS of
 * them: with nothing met there it returns the time to the end of the scan with
 * *hit_i = FLY_ON (the caller flies on and asks again). INFINITY when moving
 * parallel to the wall inside the layer without meeting anything. */
#define SWR_ROUGH_FLIGHT_CELLS 4096
double swr_rough_free_flight(const rc_state *s, const double C[3], const double v[3], int *hit_i,
                             int *hit_j)
{
    const double top = swr_wall_top(s->w) / s->L;
    const double zc = C[2];
    double t_exit = INFINITY, t_plane = INFINITY;
    if (v[2] > 0.0)
        t_exit = (top + s->R - zc) / v[2];
    else if (v[2] < 0.0)
        t_plane = (zc - s->R) / -v[2];
    if (t_exit < 0.0)
        t_exit = 0.0;
    if (t_plane < 0.0)
        t_plane = 0.0;
    double t_end = t_exit < t_plane ? t_exit : t_plane;
    *hit_i = v[2] > 0.0 ? INT_MAX : PLANE_ID;
    *hit_j = 0;
    const double vh = hypot(v[0], v[1]);
    const double sp = s->w->s / s->L;
    /* chunks of one spacing of horizontal travel */
    const double tchunk = vh > 0.0 ? sp / vh : t_end;
    double best = t_end;
    double t0 = 0.0;
    for (long k = 0; k < SWR_ROUGH_FLIGHT_CELLS; k++) {
        if (!(t0 < best))
            break;
        double t1 = t0 + tchunk;
        if (!(t1 < best))
            t1 = best;
        if (!isfinite(t1))
            t1 = t0 + (isfinite(tchunk) ? tchunk : 0.0);
        /* lowest centre height over the chunk sets how far sideways it reaches */
        const double rh = side_reach(s->reach_a, fmin(zc + v[2] * t0, zc + v[2] * t1) - s->zc);
        if (rh > 0.0) {
            const double xa = C[0] + v[0] * t0, xb = C[0] + v[0] * t1;
            const double ya = C[1] + v[1] * t0, yb = C[1] + v[1] * t1;
            const double xlo = fmin(xa, xb) - rh, xhi = fmax(xa, xb) + rh;
            const double ylo = fmin(ya, yb) - rh, yhi = fmax(ya, yb) + rh;
            int j0, j1;
            swr_wall_rows(s->w, ylo * s->L, yhi * s->L, &j0, &j1);
            for (int j = j0; j <= j1; j++) {
                int i0, i1;
                swr_wall_row_range(s->w, j, xlo * s->L, xhi * s->L, &i0, &i1);
                for (int i = i0; i <= i1; i++) {
                    if (rc_find(s, i, j) >= 0)
                        continue;
                    double a[3];
                    rc_asp(s, i, j, a);
                    /* |C + v t - a| = reach: a t^2 + 2 b t + c = 0 */
                    const double d[3] = { C[0] - a[0], C[1] - a[1], C[2] - a[2] };
                    const double qa = swr_dot3(v, v), qb = swr_dot3(d, v);
                    const double qc = swr_dot3(d, d) - s->reach_a * s->reach_a;
                    if (qc <= 0.0) {
                        /* already touching (e.g. at the start on a sunken lattice) */
                        if (qb < 0.0 && 0.0 < best) {
                            best = 0.0;
                            *hit_i = i;
                            *hit_j = j;
                        }
                        continue;
                    }
                    const double disc = qb * qb - qa * qc;
                    if (!(qa > 0.0) || disc < 0.0 || qb >= 0.0)
                        continue;
                    const double t = qc / (-qb + sqrt(disc)); /* smaller root, stable form */
                    if (t < best) {
                        best = t;
                        *hit_i = i;
                        *hit_j = j;
                    }
                }
            }
        }
        t0 = t1;
    }
    if (t0 < best) {
        /* the scan ended before the event it found (or none): fly on */
        if (!isfinite(t_end) && !isfinite(best))
            return INFINITY;
        *hit_i = FLY_ON;
        return t0;
    }
    return best;
}

/* One asperity at the sphere centre C: open a contact when it touches
 * (delta >= 0) and is not one yet. Sets *gap to its gap, or -1 when it is a
 * contact (held or just opened: check it at every search, it may break; a
 * breaking contact sets s->guard = 0). -1 past RC_MAX. */
static int check_asperity(rc_state *s, const rc_near *q, const double C[3], const double v[3],
                          double *gap)
{
    *gap = -1.0;
    if (rc_find(s, q->i, q->j) >= 0)
        return 0;
    double n[3];
    const double dl = rc_geometry(s, q->a, C, n);
    if (dl >= 0.0)
        return swr_rough_open_contact(s, q->i, q->j, q->a, v, dl, n);
    *gap = -dl;
    return 0;
}

/* Collect every asperity that touches now (delta >= 0) and is not a contact
 * yet, and the plane; open them. The search also notes the smallest gap to
 * any other surface within s->margin: until the sphere has moved that far no
 * new contact can form, and the next searches are skipped (the caller
 * compares s->moved with s->guard).
 * A neighbour list (Verlet's) keeps the search short: a full scan of the
 * lattice under the sphere lists the asperities within a gap of 2 margin;
 * until the sphere has moved margin since (s->built), an asperity off the list
 * is still more than margin away, so only the listed ones are checked. The
 * caller sets s->built = INFINITY after a free flight (the list is rebuilt);
 * a list longer than RC_NEAR_MAX is not kept (full scans every time).
 * Returns -1 when RC_MAX is exceeded. */
int swr_rough_new_contacts(rc_state *s, const double C[3], const double v[3])
{
    double guard = s->margin;
    if (s->built < s->margin) {
        /* an asperity last seen at gap g cannot touch before the sphere has
         * moved g: it is due again at built + g */
        for (int k = 0; k < s->nnear; k++) {
            rc_near *q = &s->near[k];
            if (q->due <= s->built) {
                double gap;
                if (check_asperity(s, q, C, v, &gap) != 0)
                    return -1;
                q->due = s->built + gap; /* a contact: due at once */
                if (gap < 0.0)
                    continue;
            }
            if (q->due - s->built < guard)
                guard = q->due - s->built;
        }
    } else {
        const double far = s->reach_a + 2.0 * s->margin;
        const double rh = side_reach(far, C[2] - s->zc);
        int kept = 1;
        s->nnear = 0;
        if (rh > 0.0) {
            int j0, j1;
            swr_wall_rows(s->w, (C[1] - rh) * s->L, (C[1] + rh) * s->L, &j0, &j1);
            for (int j = j0; j <= j1; j++) {
                int i0, i1;
                swr_wall_row_range(s->w, j, (C[0] - rh) * s->L, (C[0] + rh) * s->L, &i0, &i1);
                for (int i = i0; i <= i1; i++) {
                    rc_near q = { i, j, { 0.0, 0.0, 0.0 }, 0.0 };
                    rc_asp(s, i, j, q.a);
                    const double d[3] = { C[0] - q.a[0], C[1] - q.a[1], C[2] - q.a[2] };
                    if (swr_dot3(d, d) > far * far)
                        continue;
                    double gap;
                    if (check_asperity(s, &q, C, v, &gap) != 0)
                        return -1;
                    q.due = gap; /* a contact: due at once */
                    if (gap >= 0.0 && gap < guard)
                        guard = gap;
                    if (s->nnear < RC_NEAR_MAX)
                        s->near[s->nnear++] = q;
                    else
                        kept = 0;
                }
            }
        }
        s->built = kept ? 0.0 : INFINITY;
    }
    if (rc_find(s, PLANE_ID, 0) < 0) {
        double n[3];
        const double dl = rc_geometry(s, NULL, C, n);
        if (dl >= 0.0) {
            if (swr_rough_open_contact(s, PLANE_ID, 0, NULL, v, dl, n) != 0)
                return -1;
        } else if (-dl < guard) {
            guard = -dl;
        }
    }
    s->guard = guard;
    s->moved = 0.0;
    return 0;
}
