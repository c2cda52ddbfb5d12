/* swr_collide.h - one ice sphere hitting a wall: the DEM collision kernel.
 *
 * Lifecycle (GSL style): swr_model_alloc() derives every constant and table
 * from a validated swr_params once; swr_collide() runs one impact and is
 * thread-safe (the model is read-only); swr_model_free() releases it.
 *
 *   swr_params p; swr_params_default(&p); swr_params_set(&p, "gamma", "0.5", err, n);
 *   swr_model *m = swr_model_alloc(&p, err, n);
 *   swr_impact in = { .d = 50e-6, .vn = 1.0, .vt = 0.0, .omega = 0.0 };
 *   swr_result r; swr_collide(m, &in, &r, NULL);
 *   swr_model_free(m);
 *
 * Sub-models, each in its own file under regime/kernel, formulas in pure
 * functions (regime/physics): normal contact (swr_normal.c: Hertz, JKR with
 * hysteresis; swr_plastic.c: Thornton & Ning's adhesive elastic-plastic
 * contact, cor thornton-ning), damping (swr_damping.c: COR modes), tangential sliding
 * (swr_tangential.h, one law for the flat wall and the rough wall's 3-D
 * contacts; swr_tangential.c: the arrest of sliding and rolling), rolling
 * resistance (swr_rolling.h, likewise), the history springs they share
 * (swr_spring.h), wall geometry (swr_wall.c: flat, or a rough lattice of
 * asperities), time integration (swr_collide.c; on a rough wall the 3-D
 * multi-contact swr_rough.c with its contact detection swr_rough_contacts.c).
 */
#ifndef SWR_COLLIDE_H
#define SWR_COLLIDE_H

#include "swr_params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct swr_model swr_model;

/* One impact. Velocities are of the particle relative to the wall, at first
 * contact: vn > 0 is the approach speed along the wall normal, vt >= 0 the
 * tangential speed (along +x), omega the initial spin about the axis that
 * makes the contact point slide along vt (rad/s, sign as in swr_collide.c).
 * On a rough wall (wall lattice) x, y is the impact point: where the sphere
 * centre is when its lowest point crosses the plane of the asperity tops
 * (swr_wall.h); a flat wall ignores it. */
typedef struct {
    double d;      /* particle diameter [m] */
    double vn;     /* normal approach speed [m/s], > 0 */
    double vt;     /* tangential speed [m/s], >= 0 */
    double omega;  /* initial angular velocity [rad/s] */
    double x, y;   /* impact point on a rough wall [m] (finite, |x|, |y| <= 1 m) */
} swr_impact;

typedef enum {
    SWR_OK = 0,          /* outcome decided by a physical criterion */
    SWR_STEP_BOUND = 1,  /* step bound reached: outcome is the best estimate */
    SWR_EINVAL = -1      /* bad input (message in swr_result.msg) */
} swr_status;

typedef struct {
    swr_status status;
    int contact_kept;    /* 1: the normal contact never broke (normal stick) */
    int stick;           /* 1: contact kept AND sliding and rolling arrested */
    double e_n;          /* rebound normal COR  v_n,out / v_n,in (0 if kept) */
    double e_t;          /* rebound tangential ratio v_t,out / v_t,in (NaN if vt = 0) */
    double t_contact;    /* contact duration [s] (time to decision if kept) */
    double delta_max;    /* largest overlap [m] */
    double e_target;     /* plastic COR the dashpot was set to (1 elastic) */
    double dt;           /* time step used [s] (the smallest, when the contact law
                            changes it between loading and unloading; 0: closed form) */
    long steps;          /* steps taken */
    long max_steps;      /* guaranteed upper bound on steps */
    double energy_err;   /* energy-balance error of the integration, relative to the
                            largest of the impact energy, the adhesive separation
                            energy and the kinetic energy during the contact */
    char msg[160];       /* warning or error text ("" when none) */
    /* Kept contacts: sliding and rolling stop under the adhesive resistances
     * (mu 2F_c, 4F_c xi_crit) after this time and displacement of the centre
     * along the wall, predicted from the state at the decision; INFINITY when
     * they never stop (mu = 0 with slip). 0 for bounces and head-on impacts. */
    double t_rest;       /* [s] */
    double s_rest;       /* [m] */
    /* Rough wall: contacts made (asperities and the base plane, counted once
     * per touch); the outcome is then decided by energy (doc/kernel.md: stick
     * = the sphere can never leave), t_rest and s_rest are not predicted (0).
     * 1 on a flat wall. */
    long contacts;
    /* Rough wall, a bounce: the velocity [m/s] and spin [rad/s] with which the
     * sphere leaves, in the impact's frame (x along the incoming tangential
     * motion, z the wall normal out of the wall; the incoming spin is about
     * -y); 0 when it sticks and on a flat wall. */
    double v_out[3], w_out[3];
} swr_result;

/* Optional trajectory sink: called every `stride` steps with time, overlap,
 * normal velocity, normal force, contact radius, tangential velocity, spin.
 * SI units; the normal velocity is the approach speed d delta/dt (> 0 towards
 * the wall, like swr_impact.vn), the force is the total normal contact force
 * (> 0 repulsive). A trace makes swr_collide step through the whole contact
 * (otherwise a conservative remainder is done in closed form). */
typedef struct {
    int stride;
    void (*fn)(void *ctx, double t, double delta, double vn, double fn,
               double a, double vt, double omega);
    void *ctx;
} swr_trace;

/* Derive the model. NULL with a message in err on invalid params. */
swr_model *swr_model_alloc(const swr_params *p, char *err, size_t errlen);
void swr_model_free(swr_model *m);
const swr_params *swr_model_params(const swr_model *m);

/* Run one impact. Returns r->status. Never NaN, never past r->max_steps. */
swr_status swr_collide(const swr_model *m, const swr_impact *in, swr_result *r,
                       const swr_trace *trace);

/* 1 when the wall is rough (wall lattice), 0 flat. */
int swr_model_rough(const swr_model *m);
/* The rectangle [0, lx) x [0, ly) of impact points that covers every impact
 * on the wall (swr_wall_sample_area; 0 x 0 for a flat wall). */
void swr_model_sample_area(const swr_model *m, double *lx, double *ly);

/* Tabor parameter of diameter d; sets *jkr_ok = lambda > SWP_TABOR_JKR_MIN. */
double swr_model_tabor(const swr_model *m, double d, int *jkr_ok);

/* Accepted impact inputs (swr_collide returns SWR_EINVAL outside them). */
#define SWR_D_MIN 1.0e-7   /* diameter [m] */
#define SWR_D_MAX 1.0e-1
#define SWR_V_MAX 1.0e3    /* normal and tangential speed [m/s] */
#define SWR_V_MIN 1.0e-60  /* normal speed [m/s] without adhesion: below it a Hertz
                              contact's scaled radii overflow (with adhesion any
                              vn > 0 is accepted: an impact that slow sticks) */
/* On a rough wall d is at most this many asperity radii (beyond it a sphere
 * holds hundreds of asperity contacts at once; use the flat wall there). */
#define SWR_ROUGH_D_OVER_R_MAX 2000.0

/* Critical normal sticking velocity of diameter d (head-on, vt = omega = 0):
 * the largest vn at which the contact is kept, by bisection in ln vn to the
 * relative tolerance rtol (e.g. 1e-4), searched in [vlo, vhi]. Returns 0 and
 * *vcrit, or -1 when every vn in the range bounces (*vcrit = 0) or none does
 * (*vcrit = vhi). Thread-safe like swr_collide. */
int swr_vcrit_normal(const swr_model *m, double d, double vlo, double vhi, double rtol,
                     double *vcrit);

#ifdef __cplusplus
}
#endif
#endif
