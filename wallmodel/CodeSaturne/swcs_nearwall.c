/* swcs_nearwall.c - the C core's near-wall dispersion model (swd.h) in Code_Saturne
 * 6.0's Lagrangian module (swcs.h, doc/codesaturne.md).
 *
 * No physics here: swd_advance gives each particle's turbulent kick and the
 * sublayer closure's deposition rate; this file finds the particle's wall, reads
 * the flow there and hands the kick to Code_Saturne as the external force
 *   f = kick / (tau_p (1 - exp(-dt / tau_p)))     [m/s2],
 * which its first-order integrator turns into exactly the velocity change
 * `kick` over the step (the force term of the particle velocity is
 * f tau_p (1 - exp(-dt / tau_p))). Code_Saturne's own fluctuation must be off
 * (idistu = 0: the velocity seen is the mean flow). A particle the closure takes
 * meets its wall through the binding's impact (swcs_closure_impact): the wall
 * model decides it like a tracked impact. */
#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bft_error.h"
#include "bft_mem.h"
#include "bft_printf.h"
#include "cs_boundary_zone.h"
#include "cs_field.h"
#include "cs_field_pointer.h"
#include "cs_lagr.h"
#include "cs_lagr_particle.h"
#include "cs_math.h"
#include "cs_mesh.h"
#include "cs_mesh_location.h"
#include "cs_mesh_quantities.h"
#include "cs_parall.h"
#include "cs_physical_constants.h"
#include "cs_random.h"
#include "cs_time_step.h"

#include "swcs.h"
#include "swcs_internal.h"
#include "swd.h"
#include "swp_nearwall.h"

BEGIN_C_DECLS

#define NW_MAX_ZONES 64
#define NW_USER_VARS 4   /* w in x, y, z, and 1 once drawn */

static struct {
    swd_model *m;
    int user0;                  /* our first user variable; -1: not reserved */
    int set;                    /* swcs_nearwall called (later calls ignored) */
    int nz;
    int zone[NW_MAX_ZONES];
    char closure[1024];
    cs_lnum_t *near;            /* per cell: the nearest face of the zones, -1 none */
    double expected[NW_MAX_ZONES];
    long long drawn[NW_MAX_ZONES];
} _nw = {NULL, -1, 0, 0, {0}, "", NULL, {0}, {0}};

static void nw_stop(const char *fmt, const char *a, const char *b)
{
    char msg[1400];
    snprintf(msg, sizeof msg, fmt, a ? a : "", b ? b : "");
    bft_error(__FILE__, __LINE__, 0, "SnowWall near-wall model: %s\n", msg);
}

void swcs_nearwall_model(void)
{
    if (_nw.user0 >= 0) return;
    _nw.user0 = cs_glob_lagr_model->n_user_variables;
    cs_glob_lagr_model->n_user_variables += NW_USER_VARS;
    /* the walls' friction velocity: the flow's boundary conditions fill this
       field when it exists, also on a frozen flow (as for Code_Saturne's own
       deposition model, which creates it the same way) */
    cs_field_find_or_create("ustar", CS_FIELD_INTENSIVE | CS_FIELD_PROPERTY,
                            CS_MESH_LOCATION_BOUNDARY_FACES, 1, false);
}

void swcs_nearwall(const char *zones, const char *closure)
{
    if (_nw.set) return;
    if (_nw.user0 < 0)
        nw_stop("call swcs_nearwall_model() from cs_user_lagr_model first (it reserves the "
                "particle's user variables of the model)%s%s", NULL, NULL);
    if (!zones || !*zones) nw_stop("no zone given%s%s", NULL, NULL);
    char list[1024];
    snprintf(list, sizeof list, "%s", zones);
    for (char *tok = strtok(list, ","); tok; tok = strtok(NULL, ",")) {
        const cs_zone_t *z = cs_boundary_zone_by_name_try(tok);
        if (!z) nw_stop("zone '%s' (of '%s') is not a boundary zone of the case", tok, zones);
        if (!swcs_is_snow_zone(z->id))
            nw_stop("zone '%s' is not a SnowWall snow zone: name it first with "
                    "swcs_zone(bc_type, \"%s\", \"snow\")", tok, tok);
        for (int i = 0; i < _nw.nz; ++i)
            if (_nw.zone[i] == z->id) nw_stop("zone '%s' is given twice in '%s'", tok, zones);
        if (_nw.nz == NW_MAX_ZONES) nw_stop("more than 64 zones in '%s'%s", zones, NULL);
        _nw.zone[_nw.nz++] = z->id;
    }
    if (!_nw.m) _nw.m = swd_alloc();
    if (!_nw.m) nw_stop("out of memory%s%s", NULL, NULL);
    if (closure && *closure) {
        snprintf(_nw.closure, sizeof _nw.closure, "%s", closure);
        if (swd_load_closure(_nw.m, closure) != SWD_OK) nw_stop("%s%s", swd_errmsg(_nw.m), NULL);
    }
    if (swd_commit(_nw.m) != SWD_OK) nw_stop("%s%s", swd_errmsg(_nw.m), NULL);
    char d[600];
    swd_describe(_nw.m, d, sizeof d);
    bft_printf("SnowWall near-wall model on '%s': %s; sublayer closure %s\n", zones, d,
               swd_closure_on(_nw.m) ? _nw.closure : "off");
    _nw.set = 1;
}

void swcs_nearwall_scale(const char *name)
{
    if (!_nw.m) _nw.m = swd_alloc();
    if (!_nw.m) nw_stop("out of memory%s%s", NULL, NULL);
    if (swd_set_scale(_nw.m, swd_scale_of(name)) != SWD_OK)
        nw_stop("velocity scale '%s' is not max, wallShear or turbulence%s", name, NULL);
}

/* The nearest face of the zones to every cell centre, by a uniform grid of the
 * faces' centres searched in growing shells (each shell stops the search once
 * the best distance is inside its lower bound). */
static void build_near(void)
{
    const cs_mesh_t *mesh = cs_glob_mesh;
    const cs_real_t *cog = cs_glob_mesh_quantities->b_face_cog;
    const cs_real_t *cen = cs_glob_mesh_quantities->cell_cen;
    const int *fz = cs_boundary_zone_face_zone_id();
    const cs_lnum_t nb = mesh->n_b_faces, nc = mesh->n_cells;
    cs_lnum_t *faces = NULL;
    BFT_MALLOC(faces, nb, cs_lnum_t);
    cs_lnum_t nf = 0;
    for (cs_lnum_t f = 0; f < nb; ++f)
        for (int i = 0; i < _nw.nz; ++i)
            if (fz[f] == _nw.zone[i]) { faces[nf++] = f; break; }
    BFT_MALLOC(_nw.near, nc, cs_lnum_t);
    for (cs_lnum_t c = 0; c < nc; ++c) _nw.near[c] = -1;
    if (nf == 0) { BFT_FREE(faces); return; }   /* no face of the zones on this rank */
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = cog[3 * faces[0] + k];
    for (cs_lnum_t i = 1; i < nf; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], cog[3 * faces[i] + k]);
            hi[k] = fmax(hi[k], cog[3 * faces[i] + k]);
        }
    double span = 0;
    for (int k = 0; k < 3; ++k) span = fmax(span, hi[k] - lo[k]);
    span = fmax(span, 1e-12);
    int dim[3];
    double h[3];
    const double target = cbrt((double)nf) + 1;
    for (int k = 0; k < 3; ++k) {
        dim[k] = (int)fmin(128, fmax(1, ceil(target * (hi[k] - lo[k]) / span)));
        h[k] = fmax((hi[k] - lo[k]) / dim[k], span * 1e-9);
    }
    const size_t ncell = (size_t)dim[0] * dim[1] * dim[2];
    cs_lnum_t *start = NULL, *item = NULL;
    BFT_MALLOC(start, ncell + 1, cs_lnum_t);
    BFT_MALLOC(item, nf, cs_lnum_t);
    for (size_t g = 0; g <= ncell; ++g) start[g] = 0;
#define NW_BIN(x, k) ((int)fmin(dim[k] - 1, fmax(0, floor(((x) - lo[k]) / h[k]))))
    for (cs_lnum_t i = 0; i < nf; ++i) {
        const cs_real_t *x = cog + 3 * faces[i];
        const size_t g = ((size_t)NW_BIN(x[2], 2) * dim[1] + NW_BIN(x[1], 1)) * dim[0] + NW_BIN(x[0], 0);
        start[g + 1]++;
    }
    for (size_t g = 0; g < ncell; ++g) start[g + 1] += start[g];
    {
        cs_lnum_t *fill = NULL;
        BFT_MALLOC(fill, ncell, cs_lnum_t);
        for (size_t g = 0; g < ncell; ++g) fill[g] = start[g];
        for (cs_lnum_t i = 0; i < nf; ++i) {
            const cs_real_t *x = cog + 3 * faces[i];
            const size_t g = ((size_t)NW_BIN(x[2], 2) * dim[1] + NW_BIN(x[1], 1)) * dim[0] + NW_BIN(x[0], 0);
            item[fill[g]++] = faces[i];
        }
        BFT_FREE(fill);
    }
    const double hmin = fmin(h[0], fmin(h[1], h[2]));
    const int rmax = (int)fmax(dim[0], fmax(dim[1], dim[2]));
    for (cs_lnum_t c = 0; c < nc; ++c) {
        const cs_real_t *x = cen + 3 * c;
        int b[3];
        for (int k = 0; k < 3; ++k) b[k] = NW_BIN(x[k], k);
        double best = HUGE_VAL;
        cs_lnum_t bf = -1;
        for (int r = 0; r <= rmax; ++r) {
            /* the cells at Chebyshev distance r from b */
            for (int i2 = b[2] - r; i2 <= b[2] + r; ++i2) {
                if (i2 < 0 || i2 >= dim[2]) continue;
                for (int i1 = b[1] - r; i1 <= b[1] + r; ++i1) {
                    if (i1 < 0 || i1 >= dim[1]) continue;
                    for (int i0 = b[0] - r; i0 <= b[0] + r; ++i0) {
                        if (i0 < 0 || i0 >= dim[0]) continue;
                        if (abs(i0 - b[0]) != r && abs(i1 - b[1]) != r && abs(i2 - b[2]) != r)
                            continue;
                        const size_t g = ((size_t)i2 * dim[1] + i1) * dim[0] + i0;
                        for (cs_lnum_t j = start[g]; j < start[g + 1]; ++j) {
                            const cs_real_t *y = cog + 3 * item[j];
                            const double d2 = cs_math_3_square_distance(x, y);
                            if (d2 < best) { best = d2; bf = item[j]; }
                        }
                    }
                }
            }
            /* a face in shell r + 1 is at least r h_min away from x (x lies
               inside its own bin, clamped bins only add distance) */
            if (bf >= 0 && best <= (r * hmin) * (r * hmin)) break;
        }
        _nw.near[c] = bf;
    }
#undef NW_BIN
    BFT_FREE(start);
    BFT_FREE(item);
    BFT_FREE(faces);
}

static double cell_value(const cs_field_t *f, cs_lnum_t c, double dflt)
{
    return f && f->val ? f->val[c] : dflt;
}

void swcs_nearwall_force(cs_real_t dt_p, const cs_real_t taup[], cs_real_3_t fextla[])
{
    if (!_nw.set) nw_stop("swcs_nearwall_force before swcs_nearwall (call it from "
                          "cs_user_lagr_boundary_conditions)%s%s", NULL, NULL);
    if (cs_glob_lagr_time_scheme->idistu != 0)
        nw_stop("Code_Saturne's own turbulent dispersion is on (idistu = 1): the near-wall "
                "model is the dispersion; set cs_glob_lagr_time_scheme->idistu = 0%s%s",
                NULL, NULL);
    if (!_nw.near) build_near();
    cs_lagr_particle_set_t *p_set = cs_glob_lagr_particle_set;
    const cs_mesh_quantities_t *q = cs_glob_mesh_quantities;
    const int *fz = cs_boundary_zone_face_zone_id();
    const cs_field_t *fk = cs_field_by_name_try("k");
    const cs_field_t *feps = cs_field_by_name_try("epsilon");
    const cs_field_t *fomg = cs_field_by_name_try("omega");
    const cs_field_t *frho = cs_field_by_name_try("density");
    const cs_field_t *fmu = cs_field_by_name_try("molecular_viscosity");
    const cs_field_t *fvel = CS_F_(vel);
    if (!fk || (!feps && !fomg))
        nw_stop("the flow has no k and epsilon or omega fields: the model walks with a RANS "
                "model's turbulence%s%s", NULL, NULL);
    const double ro0 = cs_glob_fluid_properties->ro0, mu0 = cs_glob_fluid_properties->viscl0;
    const int closure = swd_closure_on(_nw.m);

    for (cs_lnum_t ip = 0; ip < p_set->n_particles; ++ip) {
        const cs_lnum_t c = cs_lagr_particles_get_lnum(p_set, ip, CS_LAGR_CELL_ID);
        if (c < 0) continue;
        if (cs_lagr_particles_get_flag(p_set, ip, CS_LAGR_PART_DEPOSITION_FLAGS)) continue;
        const double rho = cell_value(frho, c, ro0), mu = cell_value(fmu, c, mu0);
        swd_local at = { 0 };   /* the bulk drift: grad_k 0 (Code_Saturne gives no gradient here yet) */
        at.nu = mu / rho;
        at.k = fmax(fk->val[c], 0);
        at.eps = fmax(feps ? feps->val[c] : 0.09 * fk->val[c] * fomg->val[c], 0);
        const cs_lnum_t f = _nw.near[c];
        const cs_real_t *x = cs_lagr_particles_attr(p_set, ip, CS_LAGR_COORDS);
        double n_out[3] = {0, -1, 0};   /* the wall's outward normal (any without a wall) */
        if (f >= 0) {
            /* Code_Saturne's boundary normals point out of the fluid */
            const cs_real_t *sn = q->b_face_normal + 3 * f, *xf = q->b_face_cog + 3 * f;
            const double s = cs_math_3_norm(sn);
            double y = 0;   /* the distance from the face's plane into the fluid */
            for (int k = 0; k < 3; ++k) {
                n_out[k] = sn[k] / s;
                y -= (x[k] - xf[k]) * n_out[k];
            }
            at.y = fmax(y, 0);
            const double tau_w = swcs_wall_shear(f);
            const double rf = rho > 0 ? rho : ro0;
            at.u_tau = tau_w > 0 ? sqrt(tau_w / rf) : 0;
        } else {
            at.y = -1;
            at.u_tau = 0;
        }
        const cs_real_t *uc = fvel->val + 3 * c;
        const double ucd[3] = {uc[0], uc[1], uc[2]};
        double es[3], en[3], ez[3];   /* streamwise, wall-normal into the fluid, spanwise */
        swd_wall_frame(n_out, ucd, es, en, ez);

        /* the particle's normalized fluctuation, kept in its user variables */
        cs_real_t *u = cs_lagr_particles_attr(p_set, ip, CS_LAGR_USER);
        cs_real_t *wg = u + _nw.user0;
        double w[3];
        if (wg[3] != 1) {
            cs_real_t g[3];
            cs_random_normal(3, g);
            for (int k = 0; k < 3; ++k) w[k] = g[k];
            wg[3] = 1;
        } else {
            w[0] = cs_math_3_dot_product(wg, es);
            w[1] = cs_math_3_dot_product(wg, en);
            w[2] = cs_math_3_dot_product(wg, ez);
        }
        cs_real_t xi[3];
        cs_random_normal(3, xi);
        const double tp = taup[ip];
        double kick[3];
        swd_stats st;
        const double xid[3] = {xi[0], xi[1], xi[2]};
        if (swd_advance(_nw.m, &at, dt_p, tp, w, xid, kick, &st) != SWD_OK) {
            char a[400];
            snprintf(a, sizeof a, "at (%g %g %g): y %g u_tau %g nu %g k %g epsilon %g dt %g tau_p %g",
                     x[0], x[1], x[2], at.y, at.u_tau, at.nu, at.k, at.eps, dt_p, tp);
            nw_stop("invalid state of a particle %s%s", a, NULL);
        }
        const double g = -expm1(-dt_p / tp);
        for (int k = 0; k < 3; ++k) {
            const double kx = kick[0] * es[k] + kick[1] * en[k] + kick[2] * ez[k];
            fextla[ip][k] += g > 0 ? kx / (tp * g) : 0;
            wg[k] = w[0] * es[k] + w[1] * en[k] + w[2] * ez[k];
        }

        /* the sublayer closure: reaches the wall at the rate lambda */
        if (f < 0 || !closure) continue;
        const double d = cs_lagr_particles_get_real(p_set, ip, CS_LAGR_DIAMETER);
        const double mass = cs_lagr_particles_get_real(p_set, ip, CS_LAGR_MASS);
        const double rho_p = 6 * mass / (cs_math_pi * d * d * d);
        const double tau_st = swp_tau_p(rho_p, d, mu, 0);   /* Stokes */
        const double lambda = swd_deposit_rate(_nw.m, &st, at.nu, tau_st);
        if (!(lambda > 0)) continue;
        const double prob = -expm1(-lambda * dt_p);
        int zi = 0;
        while (zi < _nw.nz && _nw.zone[zi] != fz[f]) ++zi;
        if (zi == _nw.nz) continue;   /* the nearest face is not of a listed zone */
        _nw.expected[zi] += prob;
        cs_real_t r;
        cs_random_uniform(1, &r);
        if (!(r < prob)) continue;
        /* the impact: the particle's own wall-normal velocity towards the wall,
           and along the wall the fluid's speed at contact height (the viscous
           sublayer carries it: u+ = y+ at y = d/2) */
        cs_real_t *v = cs_lagr_particles_attr(p_set, ip, CS_LAGR_VELOCITY);
        const double vn = -cs_math_3_dot_product(v, en);
        const double ut = swd_contact_speed(&st, at.nu, d);
        double uimp[3], uout[3];
        for (int k = 0; k < 3; ++k) uimp[k] = -fmax(vn, 0) * en[k] + ut * es[k];
        _nw.drawn[zi]++;
        if (!swcs_closure_impact(p_set, ip, f, fz[f], uimp, uout)) {
            /* bounced or ripped off: on its way with the rebound velocity plus
               the wall-parallel velocity it had, less the one of the impact */
            cs_real_t *v0 = cs_lagr_particles_attr_n(p_set, ip, 1, CS_LAGR_VELOCITY);
            const double vnn = cs_math_3_dot_product(v, en);
            for (int k = 0; k < 3; ++k) {
                v[k] = uout[k] + (v[k] - vnn * en[k]) - ut * es[k];
                v0[k] = v[k];
            }
        }
    }
}

void swcs_nearwall_end_of_step(int write)
{
    if (!_nw.set || !write) return;
    double e[NW_MAX_ZONES];
    cs_gnum_t n[NW_MAX_ZONES];
    for (int i = 0; i < _nw.nz; ++i) {
        e[i] = _nw.expected[i];
        n[i] = (cs_gnum_t)_nw.drawn[i];
    }
    cs_parall_sum(_nw.nz, CS_DOUBLE, e);
    cs_parall_sum(_nw.nz, CS_GNUM_TYPE, n);
    bft_printf("SnowWall near-wall closure, step %d:", cs_glob_time_step->nt_cur);
    for (int i = 0; i < _nw.nz; ++i)
        bft_printf(" %s %llu (expected %.6g)", cs_boundary_zone_by_id(_nw.zone[i])->name,
                   (unsigned long long)n[i], e[i]);
    bft_printf("\n");
}

END_C_DECLS
