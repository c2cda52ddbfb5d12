/* swr_params.h - material and model settings of one regime computation.
 *
 * One flat struct of SI values with documented keys. Sources, in order:
 * swr_params_default() (dry snow = ice on ABS, doc/physics-brief.md
 * section 2), an optional config file (swr_params_load: "key value" or
 * "key = value", one per line, '#' comments), and "key=value" overrides
 * (swr_params_set). Every setter validates; errors name the key and value.
 * Implemented in swr_params.c.
 */
#ifndef SWR_PARAMS_H
#define SWR_PARAMS_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Key `cor`: how the normal dashpot is set. */
typedef enum {
    SWR_COR_ELASTIC = 0,          /* "elastic": no damping (e = 1) */
    SWR_COR_CONSTANT,             /* a number in (0, 1]: constant e */
    SWR_COR_THORNTON,             /* "thornton": full Thornton (1997) e_p(V_y/V_i) */
    SWR_COR_THORNTON_ASYMPTOTE,   /* "thornton-asymptote": e_p = 1.324 (...)^(1/8) V_i^(-1/4),
                                     per impact, exactly as the original work */
    SWR_COR_THORNTON_NING         /* "thornton-ning": no dashpot; the normal contact is
                                     Thornton & Ning's (1998) adhesive elastic-plastic
                                     law (swr_plastic.h), yielding at p_y = 2.5 sigma_y */
} swr_cor_mode;

/* Key `cor_pair`: which yield velocity the Thornton COR uses. */
typedef enum { SWR_PAIR_WALL = 0, SWR_PAIR_PARTICLE } swr_pair;

/* Key `dashpot`: when the COR dashpot acts (not for thornton-ning, which has none). */
typedef enum {
    SWR_DASHPOT_LOADING = 0,      /* "loading": while the contact is loaded (Thornton's picture) */
    SWR_DASHPOT_BOTH              /* "both": while loading and unloading (delta > 0), as common
                                     DEM codes do; for comparison (doc/kernel.md) */
} swr_dashpot;

/* Key `wall`: wall geometry (swr_wall.h). */
typedef enum { SWR_WALL_KIND_FLAT = 0, SWR_WALL_KIND_LATTICE } swr_wall_kind;
/* Key `asperity_shape`: hemispheres centred on the base plane, or whole
 * spheres resting on it (centres at asperity_r above it). */
typedef enum { SWR_ASPERITY_HEMISPHERE = 0, SWR_ASPERITY_SPHERE } swr_asperity_shape;
/* Key `asperity_yield`: the plastic COR of an asperity contact (swr_rough.c,
 * contact_target): Thornton's e_p with the yield velocity of a sphere of
 * the contact's R* and the particle's mass (contact), with the flat wall's
 * (particle), or none: the asperity contacts elastic, only the adhesive
 * hysteresis dissipates (elastic). The base plane keeps the particle's. */
typedef enum { SWR_YIELD_CONTACT = 0, SWR_YIELD_PARTICLE, SWR_YIELD_ELASTIC } swr_asperity_yield;
/* Key `rough_step`: the rough wall's time step (swr_rough.c, step_size). */
typedef enum { SWR_ROUGH_STEP_ADAPTIVE = 0, SWR_ROUGH_STEP_FIXED } swr_rough_step;
/* Key `lattice`: arrangement of the asperities of a lattice wall. */
typedef enum { SWR_LATTICE_SQUARE = 0, SWR_LATTICE_HEX } swr_lattice;

/* Key `adhesion`: normal contact law. */
typedef enum { SWR_ADHESION_JKR = 0, SWR_ADHESION_NONE } swr_adhesion;

typedef struct {
    /* particle (ice) */
    double rho;        /* `rho`      density [kg/m3]                 920      */
    double E;          /* `E`        Young's modulus [Pa]            9.8e9    */
    double nu;         /* `nu`       Poisson's ratio [-]             0.31     */
    double sigma_y;    /* `sigma_y`  yield stress [Pa]               1.0e6    */
    /* wall (ABS) */
    double E_wall;     /* `E_wall`   Young's modulus [Pa]            2.0e9    */
    double nu_wall;    /* `nu_wall`  Poisson's ratio [-]             0.35     */
    double rho_wall;   /* `rho_wall` density [kg/m3] (informative)   1100     */
    /* interface */
    double gamma;      /* `gamma`    work of adhesion [J/m2]         0.2      */
    swr_adhesion adhesion; /* `adhesion` jkr | none                  jkr      */
    double z0;         /* `z0`       equilibrium separation for the Tabor check [m] 0.3e-9 */
    swr_cor_mode cor;  /* `cor`      elastic | <number> | thornton | thornton-asymptote | thornton-ning  thornton */
    double cor_value;  /*            the number when cor is constant               */
    swr_pair cor_pair; /* `cor_pair` wall | particle                     wall     */
    swr_dashpot dashpot; /* `dashpot` loading | both                     loading  */
    int dashpot_given;   /* 1 once the key `dashpot` is set: validate refuses it with a
                            law that has no dashpot (cor elastic, thornton-ning)    0 */
    double mu;         /* `mu`       sliding friction coefficient [-] 0.05    */
    double xi_crit;    /* `xi_crit`  critical rolling displacement [m] (Dominik & Tielens) 1e-9 */
    /* wall geometry (swr_wall.h); printed only for wall lattice */
    swr_wall_kind wall; /* `wall`     flat | lattice                  flat     */
    swr_lattice lattice; /* `lattice` square | hex                    square   */
    double asperity_r;   /* `asperity_r` asperity radius [m]           1e-6     */
    swr_asperity_shape asperity_shape; /* `asperity_shape` hemisphere | sphere  hemisphere */
    swr_asperity_yield asperity_yield; /* `asperity_yield` contact | particle | elastic  contact */
    double asperity_spacing; /* `asperity_spacing` nearest-neighbour distance [m] 2e-6 */
    double asperity_jitter;  /* `asperity_jitter` random lateral offset / spacing [-] 0 */
    double asperity_dz;  /* `asperity_dz` random sinking depth [m]     0        */
    double wall_seed;    /* `wall_seed` seed of the random offsets (integer) 1    */
    double rough_hold;   /* `rough_hold` contact times t_c (flat wall, impact speed) a
                            sphere may spend in contact before, still held, it counts
                            as stuck (swr_rough.c)                     30       */
    swr_rough_step rough_step; /* `rough_step` adaptive | fixed: the step follows the
                            contacts held (adaptive) or is the reference contact's
                            step over sqrt(contacts) (fixed, the former
                            integrator's; kept to measure against)    adaptive */
    /* numerics */
    double accuracy;   /* `accuracy` steps per Hertz contact time (the one accuracy knob) 60 */
} swr_params;

/* Fill p with the embedded defaults (dry snow, ice on ABS). */
void swr_params_default(swr_params *p);
/* Set one key from text. Returns 0, or -1 with a one-line message in err
 * naming the key and the value (unknown key, not a number, NaN, out of range). */
int swr_params_set(swr_params *p, const char *key, const char *value, char *err, size_t errlen);
/* Parse "key=value" (as given to --set). */
int swr_params_set_kv(swr_params *p, const char *kv, char *err, size_t errlen);
/* Read a config file. Returns 0 or -1 with "FILE:LINE: message" in err. */
int swr_params_load(swr_params *p, const char *path, char *err, size_t errlen);
/* Check the whole set (ranges, consistency). 0 or -1 with a message. */
int swr_params_validate(const swr_params *p, char *err, size_t errlen);
/* Write every key and value, one "key value" line each, prefixed by `prefix`
 * (e.g. "# "), to the stream; used to document outputs. */
void swr_params_print(const swr_params *p, const char *prefix, FILE *stream);

#ifdef __cplusplus
}
#endif
#endif
