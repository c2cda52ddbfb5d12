/* swcs.c - SnowWall in Code_Saturne 6.0 (swcs.h, doc/codesaturne.md).
 *
 * The glue between the Lagrangian module's user boundary hook and the
 * host-neutral book (swcs_book.h) around the C core (sww.h). No physics: the
 * core decides every impact; this file reads the particle, the face and the
 * wall shear stress from Code_Saturne and writes the result back. */
#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bft_error.h"
#include "bft_mem.h"
#include "bft_printf.h"
#include "cs_boundary_zone.h"
#include "cs_field.h"
#include "cs_lagr.h"
#include "cs_lagr_event.h"
#include "cs_lagr_particle.h"
#include "cs_lagr_tracking.h"
#include "cs_mesh.h"
#include "cs_mesh_quantities.h"
#include "cs_parall.h"
#include "cs_parameters.h"
#include "cs_physical_constants.h"
#include "cs_post.h"
#include "cs_mesh_location.h"
#include "cs_random.h"
#include "cs_time_step.h"

#include "swcs.h"
#include "swcs_book.h"
#include "swcs_internal.h"
#include "sww.h"

BEGIN_C_DECLS

static struct {
    sww_model *model;
    swcs_book *book;
    char regime[1024];
    int frozen;           /* set-up done: later set-up calls are ignored */
    int every;            /* output every N time steps */
    int last_written;     /* time step of the last output */
    int shear_source;     /* 0 not looked up, 1 boundary_forces, 2 ustar */
    int verbose;          /* one listing line per impact */
} _s = {NULL, NULL, "", 0, 1, -1, 0, 0};

static void stop(const char *fmt, const char *a, const char *b)
{
    char msg[1400];
    snprintf(msg, sizeof msg, fmt, a ? a : "", b ? b : "");
    bft_error(__FILE__, __LINE__, 0, "SnowWall: %s\n", msg);
}

static void need_model(const char *caller)
{
    if (!_s.model || !sww_ready(_s.model))
        stop("%s: call swcs_regime(\"regime.coeffs\") first (no regime map loaded)%s",
             caller, NULL);
}

static swcs_book *book(void)
{
    if (!_s.book) {
        const int nz = cs_boundary_zone_n_zones();
        const cs_lnum_t nf = cs_glob_mesh->n_b_faces;
        _s.book = swcs_book_alloc(nz > 0 ? (size_t)nz : 1, nf > 0 ? (size_t)nf : 1);
        if (!_s.book) stop("out of memory for the zone and face book%s%s", NULL, NULL);
    }
    return _s.book;
}

void swcs_regime(const char *path)
{
    if (_s.frozen) return;
    if (!path || !path[0]) stop("swcs_regime: no regime file named%s%s", NULL, NULL);
    if (_s.model && strcmp(_s.regime, path) == 0) return;   /* loaded once */
    if (_s.model) stop("swcs_regime: a second regime file '%s' (the first was '%s')",
                       path, _s.regime);
    _s.model = sww_alloc();
    if (!_s.model) stop("out of memory for the regime map%s%s", NULL, NULL);
    const int rc = sww_regime_load(_s.model, path);
    if (rc != SWW_OK) {
        char msg[1100];
        snprintf(msg, sizeof msg, "regime file '%s' (run folder): %s", path,
                 sww_errmsg(_s.model));
        stop("%s%s", msg, NULL);
    }
    snprintf(_s.regime, sizeof _s.regime, "%s", path);
    char d[512];
    sww_describe(_s.model, d, sizeof d);
    bft_printf("SnowWall: regime map '%s' loaded: %s\n", path, d);
}

static const char *bc_word(int t)
{
    switch (t) {
    case CS_INDEF: return "undefined";
    case CS_INLET: return "inlet";
    case CS_OUTLET: return "outlet";
    case CS_SYMMETRY: return "symmetry";
    case CS_SMOOTHWALL: return "smooth wall";
    case CS_ROUGHWALL: return "rough wall";
    case CS_FREE_INLET: return "free inlet";
    default: return "other";
    }
}

void swcs_zone(const int bc_type[], const char *zone, const char *type)
{
    if (_s.frozen) {
        /* checked at the first call: only keep the Lagrangian type, which a
           case may reset on every call of its boundary conditions */
        const cs_zone_t *z = zone ? cs_boundary_zone_by_name_try(zone) : NULL;
        if (z && swcs_book_zone_type(_s.book, z->id) != SWCS_NONE)
            cs_lagr_get_boundary_conditions()->zone_type[z->id] = CS_LAGR_BC_USER;
        return;
    }
    const cs_zone_t *z = zone ? cs_boundary_zone_by_name_try(zone) : NULL;
    if (!z) {
        char names[800] = "";
        const int nz = cs_boundary_zone_n_zones();
        for (int i = 0; i < nz; ++i) {
            const cs_zone_t *zi = cs_boundary_zone_by_id(i);
            if (strlen(names) + strlen(zi->name) + 3 < sizeof names) {
                if (names[0]) strcat(names, ", ");
                strcat(names, zi->name);
            }
        }
        stop("swcs_zone: no boundary zone named '%s' (the zones: %s)", zone ? zone : "(null)",
             names);
    }
    swcs_book *b = book();
    if (swcs_book_set_zone(b, z->id, z->name, type) != SWW_OK)
        stop("swcs_zone: %s%s", swcs_book_errmsg(b), NULL);
    const swcs_type t = swcs_book_zone_type(b, z->id);
    if (t == SWCS_SNOW && bc_type) {
        for (cs_lnum_t i = 0; i < z->n_elts; ++i) {
            const int bt = bc_type[z->elt_ids[i]];
            if (bt != CS_SMOOTHWALL && bt != CS_ROUGHWALL) {
                char what[200];
                snprintf(what, sizeof what, "its face %ld has the flow boundary type %d (%s)",
                         (long)z->elt_ids[i], bt, bc_word(bt));
                stop("swcs_zone: zone '%s' (type snow) is not a wall: %s; a snow zone needs "
                     "CS_SMOOTHWALL or CS_ROUGHWALL faces", z->name, what);
            }
        }
    }
    cs_lagr_zone_data_t *bcs = cs_lagr_get_boundary_conditions();
    if (t == SWCS_NONE) {
        if (bcs->zone_type[z->id] == CS_LAGR_BC_USER)
            stop("swcs_zone: zone '%s' is type none but its Lagrangian type is CS_LAGR_BC_USER "
                 "(give it a Code_Saturne type such as CS_LAGR_OUTLET)%s", z->name, NULL);
    } else {
        bcs->zone_type[z->id] = CS_LAGR_BC_USER;
    }
    bft_printf("SnowWall: zone %s -> %s\n", z->name, swcs_type_name(t));
}

static void check_gate(int rc, const char *what)
{
    if (rc != SWW_OK) stop("%s: %s", what, sww_errmsg(_s.model));
}

void swcs_tangential_gate(double vt_max, double d_ref, double exponent)
{
    if (_s.frozen) return;
    need_model("swcs_tangential_gate");
    check_gate(sww_set_tangential_gate(_s.model, vt_max, d_ref, exponent), "swcs_tangential_gate");
}

void swcs_shear_gate_adhesion(double roughness)
{
    if (_s.frozen) return;
    need_model("swcs_shear_gate_adhesion");
    check_gate(sww_set_shear_gate_adhesion(_s.model, roughness), "swcs_shear_gate_adhesion");
}

void swcs_shear_gate_constant(double tau_c)
{
    if (_s.frozen) return;
    need_model("swcs_shear_gate_constant");
    check_gate(sww_set_shear_gate_constant(_s.model, tau_c), "swcs_shear_gate_constant");
}

void swcs_rebound_tangential(double e_t)
{
    if (_s.frozen) return;
    need_model("swcs_rebound_tangential");
    check_gate(sww_set_rebound_tangential(_s.model, e_t), "swcs_rebound_tangential");
}

void swcs_output(int every)
{
    if (_s.frozen) return;
    if (every < 1) {
        char v[32];
        snprintf(v, sizeof v, "%d", every);
        stop("swcs_output: every %s is not a whole number >= 1%s", v, NULL);
    }
    _s.every = every;
}

void swcs_verbose(int on)
{
    _s.verbose = on != 0;
}

/* the set-up is complete: check it once, then ignore further set-up calls */
static void freeze(void)
{
    if (_s.frozen) return;
    need_model("SnowWall set-up");
    swcs_book *b = book();
    int n = 0;
    for (size_t i = 0; i < swcs_book_n_zones(b); ++i)
        if (swcs_book_zone_type(b, (int)i) != SWCS_NONE) ++n;
    const cs_lagr_zone_data_t *bcs = cs_lagr_get_boundary_conditions();
    for (int i = 0; i < bcs->n_zones && i < (int)swcs_book_n_zones(b); ++i)
        if (bcs->zone_type[i] == CS_LAGR_BC_USER && swcs_book_zone_type(b, i) == SWCS_NONE)
            stop("zone '%s' has the Lagrangian type CS_LAGR_BC_USER but no swcs_zone call "
                 "names it (swcs_zone(bc_type, \"%s\", \"snow\" or \"escape\"))",
                 cs_boundary_zone_by_id(i)->name, cs_boundary_zone_by_id(i)->name);
    if (n == 0) stop("no zone named by swcs_zone(bc_type, name, \"snow\" or \"escape\")%s%s",
                     NULL, NULL);
    if (sww_shear_on(_s.model)) {
        if (cs_field_by_name_try("boundary_forces")) _s.shear_source = 1;
        else if (cs_field_by_name_try("ustar")) _s.shear_source = 2;
        else stop("the shear gate is on but the solver has neither the field "
                  "'boundary_forces' nor 'ustar' to read the wall shear stress from%s%s",
                  NULL, NULL);
        bft_printf("SnowWall: shear gate reads the wall shear stress from '%s'\n",
                   _s.shear_source == 1 ? "boundary_forces" : "ustar");
    }
    _s.frozen = 1;
}

void swcs_deposit_field(void)
{
    cs_field_t *f = cs_field_find_or_create(SWCS_DEPOSIT_FIELD,
                                            CS_FIELD_INTENSIVE | CS_FIELD_POSTPROCESS,
                                            CS_MESH_LOCATION_BOUNDARY_FACES, 1, false);
    cs_field_set_key_int(f, cs_field_key_id("post_vis"), CS_POST_ON_LOCATION);
}

/* the deposit per area into the field, when the case made it */
static void fill_field(void)
{
    cs_field_t *f = cs_field_by_name_try(SWCS_DEPOSIT_FIELD);
    if (!f || !f->val) return;
    const cs_lnum_t nf = cs_glob_mesh->n_b_faces;
    const cs_real_t *area = cs_glob_mesh_quantities->b_face_surf;
    const double *dep = swcs_book_deposit(_s.book);
    for (cs_lnum_t i = 0; i < nf; ++i)
        f->val[i] = area[i] > 0 ? dep[i] / area[i] : 0;
}

double swcs_wall_shear(cs_lnum_t face_id)
{
    const cs_mesh_quantities_t *q = cs_glob_mesh_quantities;
    if (_s.shear_source == 0) {
        /* first use without the shear gate (the near-wall model): the same
           sources in the same order */
        if (cs_field_by_name_try("boundary_forces")) _s.shear_source = 1;
        else if (cs_field_by_name_try("ustar")) _s.shear_source = 2;
        else stop("the wall shear stress is needed but the solver has neither the field "
                  "'boundary_forces' nor 'ustar'%s%s", NULL, NULL);
    }
    if (_s.shear_source == 1) {
        const cs_field_t *f = cs_field_by_name("boundary_forces");
        const cs_real_t *fv = f->val + 3 * face_id;
        const cs_real_t *sn = q->b_face_normal + 3 * face_id;
        const double s = q->b_face_surf[face_id];
        if (!(s > 0)) return 0;
        const double fn = (fv[0] * sn[0] + fv[1] * sn[1] + fv[2] * sn[2]) / s;
        double ft2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double t = fv[k] - fn * sn[k] / s;
            ft2 += t * t;
        }
        return sqrt(ft2) / s;
    }
    if (_s.shear_source == 2) {
        const double us = cs_field_by_name("ustar")->val[face_id];
        const cs_field_t *rho = cs_field_by_name_try("boundary_density");
        const double r = rho ? rho->val[face_id] : cs_glob_fluid_properties->ro0;
        return r * us * us;
    }
    return 0;
}

/* One impact of a particle of mass `mass` with velocity u on boundary face
 * face_id of zone `zone`, decided by the core and booked: the outcome, the
 * rebound velocity, and (for the caller's log) the face's outward unit normal,
 * the wall shear stress read and the random number drawn. */
static void decide(cs_lagr_particle_set_t *particles, cs_lnum_t p_id, cs_lnum_t face_id,
                   int zone, double mass, const double u[3], sww_outcome *out, double u_new[3],
                   double n[3], double *tau_w, double *r)
{
    /* Code_Saturne's boundary normals point out of the fluid domain */
    const cs_real_t *sn = cs_glob_mesh_quantities->b_face_normal + 3 * face_id;
    const double sm = sqrt(sn[0] * sn[0] + sn[1] * sn[1] + sn[2] * sn[2]);
    for (int k = 0; k < 3; ++k) n[k] = sn[k] / sm;
    *tau_w = sww_shear_on(_s.model) ? swcs_wall_shear(face_id) : 0;
    cs_real_t rr = 0;
    cs_random_uniform(1, &rr);
    *r = rr >= 0 && rr < 1 ? rr : 0;
    const double d = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_DIAMETER);
    if (swcs_book_impact(_s.book, _s.model, zone, (size_t)face_id, d, mass, u, NULL, n, *tau_w,
                         *r, out, u_new) != SWW_OK)
        stop("%s%s", swcs_book_errmsg(_s.book), NULL);
}

void swcs_boundary_interaction(cs_lagr_particle_set_t    *particles,
                               cs_lnum_t                  p_id,
                               cs_lnum_t                  face_id,
                               const cs_real_t            face_norm[3],
                               const cs_real_t            c_intersect[3],
                               cs_real_t                  t_intersect,
                               int                        b_zone_id,
                               int                       *event_flag,
                               cs_lagr_tracking_state_t  *tracking_state)
{
    CS_UNUSED(face_norm);
    CS_UNUSED(t_intersect);
    freeze();
    swcs_book *b = _s.book;
    const swcs_type t = swcs_book_zone_type(b, b_zone_id);
    const cs_zone_t *z = cs_boundary_zone_by_id(b_zone_id);
    if (t == SWCS_NONE)
        stop("an impact on zone '%s', whose Lagrangian type is CS_LAGR_BC_USER but which no "
             "swcs_zone call names%s", z ? z->name : "?", NULL);

    const double w = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_STAT_WEIGHT);
    const double mass = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_MASS) * w;
    cs_real_t *x = cs_lagr_particles_attr(particles, p_id, CS_LAGR_COORDS);
    cs_real_t *u = cs_lagr_particles_attr(particles, p_id, CS_LAGR_VELOCITY);
    cs_real_t *us = cs_lagr_particles_attr(particles, p_id, CS_LAGR_VELOCITY_SEEN);

    if (t == SWCS_ESCAPE) {
        if (swcs_book_escape(b, b_zone_id, mass) != SWW_OK)
            stop("%s%s", swcs_book_errmsg(b), NULL);
        /* (Code_Saturne counts a particle that leaves, CS_LAGR_PART_OUT, in its
           "exited" counter itself) */
        for (int k = 0; k < 3; ++k) x[k] = c_intersect[k];
        *event_flag |= CS_EVENT_OUTFLOW;
        *tracking_state = CS_LAGR_PART_OUT;
        return;
    }

    const double u0[3] = {u[0], u[1], u[2]};
    sww_outcome out;
    double un[3], n[3], tau_w, r;
    decide(particles, p_id, face_id, b_zone_id, mass, u0, &out, un, n, &tau_w, &r);
    const double d = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_DIAMETER);
    if (_s.verbose) {
        const double ut = sqrt(fmax(0, (u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2])
                                        - pow(u0[0] * n[0] + u0[1] * n[1] + u0[2] * n[2], 2)));
        bft_printf("SnowWall impact: zone %s face %ld t %.9g x %.9g %.9g %.9g n %g %g %g "
                   "d %.9g vn %.9g vt %.9g tau_w %.9g u %.6g -> %s\n",
                   z->name, (long)face_id, cs_glob_time_step->t_cur, c_intersect[0],
                   c_intersect[1], c_intersect[2], n[0], n[1], n[2], d,
                   fmax(0, u0[0] * n[0] + u0[1] * n[1] + u0[2] * n[2]), ut, tau_w, r,
                   sww_fate_name(out.fate));
    }

    if (out.fate == SWW_STICK) {
        /* deposited: removed from the tracking, its mass in the face's deposit */
        cs_lagr_particles_set_flag(particles, p_id, CS_LAGR_PART_DEPOSITED);
        for (int k = 0; k < 3; ++k) {
            x[k] = c_intersect[k];
            u[k] = 0;
        }
        particles->n_part_dep += 1;   /* Code_Saturne's deposit counter (the
                                         library's own example does the same) */
        particles->weight_dep += w;
        *event_flag |= CS_EVENT_OUTFLOW | CS_EVENT_DEPOSITION;
        *tracking_state = CS_LAGR_PART_OUT;
        return;
    }

    /* bounce or rip-off: the core's rebound. The rest of this step's
       displacement (from the face to the end point beyond it) leaves the face
       with the same factors as the velocity; the velocity seen by the particle
       is mirrored as Code_Saturne's own rebound does. */
    const double vn0 = u0[0] * n[0] + u0[1] * n[1] + u0[2] * n[2];
    double rest[3], rn = 0;
    for (int k = 0; k < 3; ++k) rest[k] = x[k] - c_intersect[k];
    for (int k = 0; k < 3; ++k) rn += rest[k] * n[k];
    const double e_n = vn0 > 0 ? out.e_n : 1;
    for (int k = 0; k < 3; ++k) {
        const double rt = rest[k] - rn * n[k];
        const double rn_new = rn > 0 ? -e_n * rn : rn;
        x[k] = c_intersect[k] + out.e_t * rt + rn_new * n[k];
        u[k] = un[k];
    }
    const double sn_seen = us[0] * n[0] + us[1] * n[1] + us[2] * n[2];
    for (int k = 0; k < 3; ++k) us[k] -= 2 * sn_seen * n[k];
    *event_flag |= CS_EVENT_REBOUND;
    *tracking_state = CS_LAGR_PART_TO_SYNC;
}

int swcs_is_snow_zone(int zone_id)
{
    freeze();
    return swcs_book_zone_type(_s.book, zone_id) == SWCS_SNOW;
}

int swcs_closure_impact(cs_lagr_particle_set_t *particles, cs_lnum_t p_id, cs_lnum_t face_id,
                        int zone_id, const double u_imp[3], double u_out[3])
{
    freeze();
    const double w = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_STAT_WEIGHT);
    const double mass = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_MASS) * w;
    sww_outcome out;
    double n[3], tau_w, r;
    decide(particles, p_id, face_id, zone_id, mass, u_imp, &out, u_out, n, &tau_w, &r);
    if (out.fate != SWW_STICK) return 0;
    cs_lagr_particles_set_flag(particles, p_id, CS_LAGR_PART_DEPOSITED | CS_LAGR_PART_TO_DELETE);
    particles->n_part_dep += 1;
    particles->weight_dep += w;
    return 1;
}

void swcs_end_of_step(void)
{
    if (!_s.book || !_s.model) return;   /* no set-up: nothing to report */
    freeze();
    fill_field();
    const cs_time_step_t *ts = cs_glob_time_step;
    const int last = ts->nt_max > 0 && ts->nt_cur >= ts->nt_max;
    if (!(last || ts->nt_cur % _s.every == 0) || ts->nt_cur == _s.last_written) return;
    _s.last_written = ts->nt_cur;

    swcs_book *b = _s.book;
    const size_t nz = swcs_book_n_zones(b);
    /* the totals over every rank, in a book of their own */
    swcs_book *g = swcs_book_alloc(nz, 1);
    double *v = NULL;
    BFT_MALLOC(v, SWCS_PACK_PER_ZONE * nz, double);
    if (!g) stop("out of memory for the totals%s%s", NULL, NULL);
    for (size_t i = 0; i < nz; ++i) {
        const swcs_zone_counts *zi = swcs_book_zone(b, (int)i);
        if (zi->type != SWCS_NONE)
            swcs_book_set_zone(g, (int)i, zi->name, swcs_type_name(zi->type));
    }
    swcs_book_pack(b, v);
    cs_parall_sum((cs_lnum_t)(SWCS_PACK_PER_ZONE * nz), CS_DOUBLE, v);
    swcs_book_unpack(g, v);
    BFT_FREE(v);

    char line[4096];
    swcs_book_summary(g, "SnowWall: ", line, sizeof line);
    bft_printf("SnowWall: time step %d, t = %.9g s\n%s", ts->nt_cur, ts->t_cur, line);
    swcs_nearwall_end_of_step(1);

    char path[256];
    if (cs_glob_rank_id <= 0) {
        snprintf(path, sizeof path, "snowwall-counts-%06d.csv", ts->nt_cur);
        if (swcs_book_write_counts(g, path, ts->t_cur, ts->nt_cur) != SWW_OK)
            stop("%s%s", swcs_book_errmsg(g), NULL);
    }
    swcs_book_free(g);

    const cs_mesh_t *m = cs_glob_mesh;
    const cs_mesh_quantities_t *q = cs_glob_mesh_quantities;
    long long *num = NULL;
    BFT_MALLOC(num, m->n_b_faces > 0 ? m->n_b_faces : 1, long long);
    for (cs_lnum_t i = 0; i < m->n_b_faces; ++i)
        num[i] = m->global_b_face_num ? (long long)m->global_b_face_num[i] - 1 : (long long)i;
    if (cs_glob_n_ranks > 1)
        snprintf(path, sizeof path, "snowwall-deposit-%06d.r%d.csv", ts->nt_cur, cs_glob_rank_id);
    else
        snprintf(path, sizeof path, "snowwall-deposit-%06d.csv", ts->nt_cur);
    if (swcs_book_write_deposit(b, path, num, q->b_face_cog, q->b_face_surf,
                                cs_boundary_zone_face_zone_id()) != SWW_OK)
        stop("%s%s", swcs_book_errmsg(b), NULL);
    BFT_FREE(num);
}

END_C_DECLS
