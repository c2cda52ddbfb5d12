/* swc_channel.h - turbulent deposition in a fully developed channel, one
 * dimension, with the C core's near-wall dispersion model (wallmodel/core/swd.h):
 * the reference that the OpenFOAM benchmark (validation/deposition) is checked
 * against, and the fast way to see what the model predicts (doc/deposition.md).
 *
 * Everything is in wall units (u_tau = nu = 1): the half channel 0 < y+ < Re_tau,
 * the wall at y+ = 0, the centreplane at y+ = Re_tau (a mirror: the flow is
 * symmetric). N particles of relaxation time tau+ move in the wall-normal
 * direction only:
 *   dv/dt = (v_f - v) / tau+ - g+,   dy/dt = v,   v_f = sigma_n(y) w_n (swd_advance),
 * with the bulk k+, eps+ of a fully developed channel (the log layer's
 * k+ = 1/sqrt(Cmu) and eps+ = 1/(kappa y+), both falling to the centre as
 * 1 - 0.6 y/h), and g+ >= 0 gravity towards the wall (0: none; with it the
 * centreplane's mirror makes the half channel one of height 2 h with gravity
 * towards both walls, which leaves the wall layer's physics as under a floor).
 * A particle whose centre reaches y+ = r+ (its radius, with
 * interception; else 0) deposits and a new one is released at a uniformly
 * random height with the fluid's velocity, so the population and its mean
 * concentration stay constant. After a warm-up the deposition velocity is
 *   V+ = J+ / C+ = D Re_tau / (N T+)      (D deposits in the window T+)
 * with its standard error from the scatter of 20 batch means (never below
 * the Poisson error of the tracked deposits). With the model's sublayer
 * closure on, a particle inside the sublayer also deposits with probability
 * 1 - exp(-lambda dt) in every step (swd_deposit_rate); D then counts the
 * particles that reached the wall by their own motion plus the closure's
 * expected deposits (its probabilities summed), the same mean as its draws
 * with far less noise.
 *
 * Steps (adaptive, the largest allowed at the particle's place):
 *   dt+ = min(dtMax+, cT T_L+(y), cY max(y+, 0.5) / (|v+| + sigma_n+)),
 * scheme exact: the particle's velocity and position integrated exactly for
 * a constant fluid velocity over the step; scheme host: the position moved
 * with the velocity at the start of the step, the velocity then updated
 * exactly (what OpenFOAM's tracking and the snowNearWall cloud function do).
 */
#ifndef SWC_CHANNEL_H
#define SWC_CHANNEL_H

#include "swd.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { SWC_EXACT = 0, SWC_HOST = 1 } swc_scheme;

typedef struct {
    double re_tau;      /* h+ (> 10)                                              */
    double tau_plus;    /* particle relaxation time tau+ (> 0)                    */
    double r_plus;      /* particle radius r+ (>= 0; 0: point particle)           */
    size_t n;           /* particles (>= 1)                                       */
    double t_warm;      /* warm-up t+ (>= 0)                                      */
    double t_run;       /* measurement window t+ (> 0)                            */
    double dt_max;      /* largest step dtMax+ (> 0)                              */
    double c_tl;        /* cT: step <= cT T_L (0 < cT <= 1)                       */
    double c_y;         /* cY: step <= cY y / speed (0 < cY <= 1)                 */
    double y_sub;       /* the sublayer whose concentration is reported (> 0)     */
    double g_plus;      /* gravity towards the wall, g+ = g nu / u_tau^3 (>= 0, <= 1):
                           the particle's settling velocity is g+ tau+            */
    swc_scheme scheme;
    unsigned long seed;
} swc_params;

typedef struct {
    double vplus;       /* deposition velocity V+                                 */
    double vplus_se;    /* its standard error (batch means)                       */
    size_t deposits;    /* particles that reached the wall by their own motion    */
    size_t deposits_closure; /* particles the closure took (its draws)           */
    double expected_closure; /* the closure's expected deposits (in V+)          */
    double steps;       /* particle steps taken                                   */
    double dt_mean;     /* mean step dt+                                          */
    double frac_layer;  /* time fraction particles spent below layerYPlus          */
    double c_sub;       /* concentration in y+ < y_sub over the mean (window)     */
} swc_result;

/* Defaults: Re_tau 314, tau+ 1, r+ 0, 2000 particles, warm-up 2000, window
 * 20000, dtMax+ 2, cT 0.1, cY 0.2, y_sub 10, g+ 0, exact, seed 1. */
void swc_params_default(swc_params *p);
/* Check the parameters: 0, or -1 with a message naming the field and value. */
int swc_params_check(const swc_params *p, char *err, size_t errlen);
/* Run (needs a committed model). 0 on success; -1 with a message on bad
 * parameters, -2 out of memory. */
int swc_run(const swd_model *m, const swc_params *p, swc_result *r, char *err, size_t errlen);

/* The calibration of the sublayer closure (swd.h) for a deposition law
 * (always without gravity, whatever p->g_plus: the laws are turbulent deposition):
 * for each tau_plus[i] a CRW-only run (closure off) gives V+_crw and c_s
 * (y_sub = sublayer_yplus), then
 *   vs[i] = max(0, law[i] - V+_crw) / c_s,
 * and a second run with the closure on corrects vs once for the depletion of
 * the sublayer: vs *= (law - V+_crw) / (V+_tot - V+_crw) (when that is > 0).
 * The model m is copied (its settings), not changed. Outputs (arrays of n,
 * any may be NULL except vs): vcrw, vcrw_se, c_s, vtot, vtot_se. 0 on success,
 * -1 bad input (message), -2 out of memory. */
int swc_calibrate(const swd_model *m, const swc_params *p, double sublayer_yplus,
                  const double *tau_plus, const double *law, size_t n, double *vs, double *vcrw,
                  double *vcrw_se, double *c_s, double *vtot, double *vtot_se, char *err,
                  size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
