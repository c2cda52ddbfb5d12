/* swd.h - SnowWall near-wall particle dispersion: the fluid velocity that a
 * particle sees in a turbulent wall layer, as a continuous random walk (CRW)
 * with anisotropic, DNS-based statistics in wall units (doc/deposition.md).
 *
 * Why: an isotropic random walk with sigma = sqrt(2k/3) from a RANS model
 * throws fine particles at walls far too often (the wall-normal fluctuation
 * vanishes as y^2 at a wall, and the modelled k does not), and on a
 * wall-function mesh the whole viscous sublayer lies inside one cell. This
 * model takes the statistics of the layer from the particle's own wall
 * distance y and the wall's friction velocity, not from the mesh:
 *   y+ <= layerYPlus:           sigma_i = u* f_i(y+), T_L = T_L+(y+) nu / u*^2
 *                               (regime/physics/swp_nearwall.h)
 *   y+ >= blendYPlus (or no wall): isotropic, sigma = sqrt(2k/3), T_L = CT k/eps
 *   in between:                 linear blend in y+
 * with u* = max(u_tau, Cmu^(1/4) sqrt(k)) (the friction velocity; the k-based
 * scale of wall functions where the wall shear vanishes, at separation and
 * reattachment) and y+ = y u* / nu. Other scales: u_tau alone,
 * Cmu^(1/4) sqrt(k) alone, or max(u_tau, Cmu^(1/4) sqrt(k_wall)) with the k
 * of the wall face's own cell, one value a face (swd_set_scale).
 *
 * The state of a particle is its normalized fluctuation w_i = u'_i / sigma_i
 * in the wall frame (0 streamwise, 1 wall-normal away from the wall, 2
 * spanwise), advanced by the normalized Langevin equation whose drift keeps
 * tracers well mixed in inhomogeneous turbulence (Thomson 1987; the
 * normalized form of Wilson, Legg & Thomson 1983, exact for Gaussian
 * turbulence with a diagonal stress; doc/deposition.md derives it):
 *   dw_i = -w_i dt / T_L + sqrt(2 / T_L) dW_i + (d sigma_i / d x_i) dt,
 * with d sigma_i / d x_i the whole derivative of the sigma_i that sets the
 * noise along direction i: through the wall distance, through u* where u*
 * follows the k at the particle, and through the bulk's sqrt(2k/3), from the
 * gradient of k that the host gives (swd_local.grad_k; zero: k uniform).
 * It is integrated exactly over a step of constant coefficients:
 *   w_i <- a w_i + sqrt(1 - a^2) xi_i + (1 - a) T_L d sigma_i / d x_i,
 *   a = exp(-dt / T_L), xi_i standard normal numbers given by the host.
 * The host moves the particle with the new fluctuation, sigma_i w_i with
 * sigma_i at the coming step's midpoint (the kick below); at a wall that
 * reflects the particle the host mirrors w too (w_n -> |w_n|), so that the
 * fluid velocity it sees is reflected with it.
 *
 * Lifecycle (plain C11, no global state):
 *   swd_model *m = swd_alloc();
 *   swd_set(m, "layerYPlus", 100) ...     (optional; defaults below)
 *   swd_commit(m)                          (checks the settings together)
 *   swd_advance(m, &local, dt, tau_p, w, xi, kick)   per particle and step
 *                                          (swd_local zero-initialised first:
 *                                          fields added later read as 0)
 *   swd_free(m);
 * Set functions return SWD_OK or a negative SWD_E* code with the message in
 * swd_errmsg(m). swd_stats_at / swd_advance only read the model: thread-safe.
 */
#ifndef SWD_H
#define SWD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { SWD_OK = 0, SWD_EINVAL = -1, SWD_ENOTREADY = -5 };

typedef struct swd_model swd_model;

/* Where the particle is. */
typedef struct {
    double y;      /* distance of the particle centre from the nearest wall [m];
                      any negative value: no wall nearby (bulk statistics);
                      y < 0 is not an error, NaN is                              */
    double u_tau;  /* friction velocity sqrt(tau_w / rho) of that wall [m/s], >= 0 */
    double nu;     /* kinematic viscosity of the fluid [m2/s], > 0               */
    double k;      /* modelled turbulent kinetic energy at the particle [m2/s2], >= 0 */
    double eps;    /* its dissipation rate [m2/s3], >= 0                         */
    double grad_k[3]; /* the gradient of k at the particle [m/s2], in the frame of
                      w (streamwise, wall-normal away from the wall, spanwise);
                      the gradient of the same k field as k (the drift is only
                      as consistent as the two); zeros: k uniform            */
    double k_wall; /* k of the nearest wall face's own cell [m2/s2], >= 0: the
                      scale SWD_USTAR_WALLCELL only                             */
} swd_local;

/* The statistics the particle sees there. */
typedef struct {
    double sigma[3];  /* rms fluctuation [m/s]: streamwise, wall-normal, spanwise */
    double dsigma[3]; /* d sigma_i / d x_i [1/s]: the drift of component i        */
    double tl;        /* Lagrangian integral time scale [s] (INFINITY: frozen)    */
    double ustar;     /* velocity scale u* [m/s]                                  */
    double yplus;     /* y u* / nu (-1 without a wall)                            */
    double layer;     /* weight of the wall-layer statistics, 1 .. 0              */
} swd_stats;

swd_model *swd_alloc(void);
void swd_free(swd_model *m);
const char *swd_errmsg(const swd_model *m);

/* Settings (number keys):
 *   layerYPlus  100   wall-layer statistics up to this y+ (5 .. 200)
 *   blendYPlus  150   isotropic RANS statistics from this y+ on (> layerYPlus, <= 400)
 *   CT          0.3   bulk Lagrangian time T_L = CT k / eps (0 < CT <= 2)
 *   Cmu         0.09  of the k-based velocity scale Cmu^(1/4) sqrt(k) (0 .. 1; 0: u_tau only)
 * An unknown key, a NaN or a value outside its range is refused (SWD_EINVAL,
 * the message names the key, the value and the range) and leaves the model
 * as it was. Any set makes the model not ready until swd_commit. */
int swd_set(swd_model *m, const char *key, double v);
/* The current value of a key (NaN for an unknown key). */
double swd_get(const swd_model *m, const char *key);
/* The i-th key name (NULL past the last): for hosts that check dictionaries. */
const char *swd_key(size_t i);
/* The velocity scale u* of the wall layer (default SWD_USTAR_MAX):
 *   SWD_USTAR_MAX         max(u_tau, Cmu^(1/4) sqrt(k))
 *   SWD_USTAR_SHEAR       u_tau alone (the wall's friction velocity; 0 where
 *                         the wall shear vanishes)
 *   SWD_USTAR_TURBULENCE  Cmu^(1/4) sqrt(k) alone (k at the particle: the
 *                         log layer's scale in a wall-function cell, small in
 *                         a resolved near-wall cell, where k falls as y^2)
 *   SWD_USTAR_WALLCELL    max(u_tau, Cmu^(1/4) sqrt(k_wall)), k_wall the k of
 *                         the wall face's cell: one u* a face, as wall
 *                         functions take it (it does not change with the
 *                         particle's place)
 * Another value is refused (SWD_EINVAL, the model unchanged). Makes the model
 * not ready until swd_commit, as every set does. */
enum { SWD_USTAR_MAX = 0, SWD_USTAR_SHEAR = 1, SWD_USTAR_TURBULENCE = 2, SWD_USTAR_WALLCELL = 3 };
int swd_set_scale(swd_model *m, int scale);
int swd_get_scale(const swd_model *m);
/* The name of a scale ("max", "wallShear", "turbulence", "wallCell"; NULL for another
 * value) and the scale of a name (-1 for another name). */
const char *swd_scale_name(int scale);
int swd_scale_of(const char *name);
int swd_commit(swd_model *m);
int swd_ready(const swd_model *m);
/* One line describing the settings, into buf (always terminated). */
void swd_describe(const swd_model *m, char *buf, size_t n);

/* The statistics at a place. SWD_EINVAL for a NaN or out-of-range input
 * (u_tau, k, eps, k_wall negative or not finite, nu not positive, grad_k
 * not finite). */
int swd_stats_at(const swd_model *m, const swd_local *at, swd_stats *out);

/* One step of length dt [s] > 0 for a particle of relaxation time tau_p [s] > 0
 * at `at` (its place now, where the step starts):
 *   w        is advanced over dt (see the top of this file), with the
 *            statistics at `at`;
 *   kick[i] = sigma_i w_i (1 - exp(-dt / tau_p)) with the new w and sigma_i
 *             at the coming step's midpoint (predicted from the fluid's
 *             displacement sigma w dt / 2), the change of the particle's
 *             velocity [m/s] that the fluctuation u'_i = sigma_i w_i causes
 *             over the step through linear drag (exact for a constant u');
 *             the host adds it to the velocity its own drag gave towards the
 *             mean flow and moves the particle with it over about dt (for a
 *             tracer: u = U + sigma w). The midpoint keeps tracers well mixed
 *             at steps of several wall units, where sigma at the start of the
 *             step piles them up in the buffer layer;
 * xi: three independent standard normal numbers, new ones every step. kick
 * may be NULL. Components are in the wall frame (streamwise, wall-normal away
 * from the wall, spanwise); in the bulk any orthonormal frame. Returns SWD_OK,
 * SWD_EINVAL (bad input: NaN, dt or tau_p not positive) or SWD_ENOTREADY; on
 * an error w and kick are unchanged. Optional *st receives the statistics. */
int swd_advance(const swd_model *m, const swd_local *at, double dt, double tau_p,
                double w[3], const double xi[3], double kick[3], swd_stats *st);

/* The wall frame of a particle, for the hosts: en the wall normal into the
 * fluid (minus n_out, the wall's outward unit normal), es the unit direction of
 * the fluid velocity u along the wall (when u has no part along it, relative to
 * its size, any direction in the wall's plane), ez = es x en. */
void swd_wall_frame(const double n_out[3], const double u[3], double es[3], double en[3],
                    double ez[3]);

/* The fluid's speed along the wall at the centre of a particle of diameter d
 * touching it: u* u+(y+) of the viscous sublayer at y = d/2 (u+ = y+ there),
 * with u* of the statistics st; the along-wall part of the impact velocity the
 * hosts give a particle the closure brings to the wall. */
double swd_contact_speed(const swd_stats *st, double nu, double d);

/* ---- the sublayer deposition closure (optional; off until a table is set) --
 * A Gaussian CRW carries particles of tau+ below about 5 into the viscous
 * sublayer far too rarely: it misses most of the measured diffusion-impaction
 * deposition, while it reproduces the inertial regime (doc/deposition.md). The
 * closure adds what it misses as a deposition rate of the particles inside the
 * sublayer y+ < sublayerYPlus:
 *   lambda = Vs+(tau+) u*^2 / (sublayerYPlus nu)     [1/s],
 * tau+ = tau_p u*^2 / nu (Stokes), Vs+ from a table over tau+ that
 * `snowdeposit calibrate` computes in a fully developed channel so that CRW +
 * closure give the measured law (Vs+ = (V+_law - V+_crw) / c_s, c_s the
 * CRW's sublayer concentration over the mean), interpolated linearly in ln tau+
 * (ln Vs+ between two positive nodes), held at the end values outside. */
/* Set the table: n >= 2 nodes, tau_plus strictly increasing and > 0, vs >= 0,
 * all finite; sublayer_yplus in (0, layerYPlus]. All or nothing. */
int swd_set_closure(swd_model *m, double sublayer_yplus, const double *tau_plus,
                    const double *vs, size_t n);
/* Read the table from the file `snowdeposit calibrate` writes (deposition.coeffs:
 * sublayerYPlus, tauPlus and vPlusSublayer of its sub-dictionary
 * depositionClosure), for hosts without a dictionary reader of their own. The
 * CRW settings the file records (layerYPlus, blendYPlus, CT, Cmu) must equal the
 * model's: the closure belongs to the walk it was calibrated with. A path that
 * is not a regular file is refused without opening it. All or nothing: on an
 * error (the message names the file, the line and the key) the model is
 * unchanged. Like a set, a success makes the model not ready until
 * swd_commit. */
int swd_load_closure(swd_model *m, const char *path);
void swd_closure_off(swd_model *m);
int swd_closure_on(const swd_model *m);
/* Vs+(tau+) of the table (0 without a table; NaN for NaN). */
double swd_closure_vs(const swd_model *m, double tau_plus);
/* The deposition rate lambda [1/s] of a particle with Stokes relaxation time
 * tau_stokes [s] at the statistics st (swd_stats_at / swd_advance): 0 outside
 * the sublayer, without a table or without turbulence. The probability that
 * it deposits in a step dt is 1 - exp(-lambda dt). */
double swd_deposit_rate(const swd_model *m, const swd_stats *st, double nu, double tau_stokes);

#ifdef __cplusplus
}
#endif
#endif
