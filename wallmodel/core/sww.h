/* sww.h - SnowWall wall-interaction core: stick / bounce / rip-off of one
 * particle impact from a regime map (doc/wallmodel.md, doc/regime-coeffs.md).
 *
 * Plain C11, no global state. Lifecycle:
 *   sww_model *m = sww_alloc();
 *   sww_regime_load(m, "regime.coeffs")            -- or sww_regime_number/list/word
 *                                                      + sww_regime_commit (from code)
 *   sww_set_tangential_gate(...), sww_set_shear_gate_*(...), ...   (optional)
 *   sww_decide(m, &impact, &outcome)                -- any number of times, any thread
 *   sww_free(m);
 * Every set/load function returns SWW_OK (0) or a negative SWW_E* code; the
 * message (one line naming input and value) is then in sww_errmsg(m). Setting
 * up a model is not thread-safe; sww_decide and the sww_* queries only read the
 * (const) model, allocate nothing and may run concurrently in many threads.
 */
#ifndef SWW_H
#define SWW_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    SWW_OK = 0,
    SWW_EINVAL = -1,     /* bad value (NaN, out of range, wrong type)        */
    SWW_EMISSING = -2,   /* a required key is missing                        */
    SWW_EPARSE = -3,     /* malformed coefficients file                      */
    SWW_EIO = -4,        /* cannot read the file                             */
    SWW_ENOTREADY = -5,  /* sww_decide before a successful commit / load     */
    SWW_ENOMEM = -6
};

typedef enum { SWW_STICK = 0, SWW_BOUNCE = 1, SWW_RIPOFF = 2 } sww_fate;

/* Why the fate was chosen. */
typedef enum {
    SWW_BY_CRITERION = 0,   /* d <= d_crit(v_n): stick; d > d_crit: bounce      */
    SWW_BY_TANGENTIAL = 1,  /* stick candidate bounced by its tangential speed:
                               |v_t| > vtMax(d) (constant gate), d above the
                               oblique limit d_crit(v_n, v_t) (regime gate), or
                               a rough wall's stick probability lower at v_t
                               than at v_t = 0 (the draw between the two)     */
    SWW_BY_SHEAR = 2        /* stick candidate ripped off: tau_w >= tau_c(d)    */
} sww_reason;

/* One impact, velocities relative to the wall. */
typedef struct {
    double d;      /* particle diameter [m], > 0                                   */
    double vn;     /* normal impact speed towards the wall [m/s], >= 0             */
    double vt;     /* tangential impact speed magnitude [m/s], >= 0                */
    double tau_w;  /* wall shear stress magnitude [Pa], >= 0 and finite: checked
                      at every impact when the shear gate is on (SWW_EINVAL),
                      not read when it is off                                      */
    double u;      /* caller's uniform random number in [0, 1), a new one per
                      impact: a stick candidate needs u < p_stick. With a rough
                      wall's probability table (probabilityStick) p_stick lies
                      between 0 and 1 and u decides; with a sharp map (no table,
                      or outside the table's span) p_stick is 0 or 1 and any u
                      gives the same answer                                        */
} sww_impact;

typedef struct {
    sww_fate fate;
    sww_reason reason;
    double d_crit;   /* d_crit(v_n) [m] (INFINITY for v_n = 0)                       */
    double p_stick;  /* stick probability used (0 or 1 for a sharp map; the table's
                        interpolated value inside a probability table's span;
                        before the gates)                                            */
    double e_n;      /* bounce / rip-off: v_n' = e_n v_n (1 for a stick)            */
    double e_t;      /* bounce / rip-off: v_t' = e_t v_t (1 for a stick)            */
    int range;       /* where v_n lies: 0 inside [vnMin, vnMax] (the fit), -1 below,
                        +1 above (the power-law extrapolation)                      */
    int by_draw;     /* 1: the random number decided against a stick that had a
                        probability > 0 (u >= p_stick > 0: a rough wall's table or a
                        build-up blend); the fate and reason then say how it left */
} sww_outcome;

/* What decided an impact, for counts by reason: each outcome is
 * exactly one of these. */
typedef enum {
    SWW_CLASS_STUCK = 0,        /* stuck                                             */
    SWW_CLASS_CRITERION = 1,    /* bounced: d > d_crit(v_n) (p_stick 0)              */
    SWW_CLASS_TANGENTIAL = 2,   /* bounced by the tangential gate                    */
    SWW_CLASS_SHEAR = 3,        /* ripped off by the shear gate                      */
    SWW_CLASS_PROBABILITY = 4,  /* bounced by the probability draw (by_draw)         */
    SWW_NCLASS = 5
} sww_class;
sww_class sww_outcome_class(const sww_outcome *o);
/* "stuck", "criterion", "tangential", "shear", "probability" */
const char *sww_class_name(sww_class c);

typedef struct sww_model sww_model;

sww_model *sww_alloc(void);
void sww_free(sww_model *m);
/* The message of the last set/load/commit call ("" when it succeeded). */
const char *sww_errmsg(const sww_model *m);

/* ---- the regime map (doc/regime-coeffs.md) ---------------------------------
 * Load the file `snowregime map` writes: the sub-dictionary regime { ... }.
 * A path that is not a regular file (a folder, a FIFO, a device) is refused
 * without opening it (SWW_EIO). All or nothing: a file that does not load and commit leaves the model as it
 * was (a loaded model stays ready, its options unchanged); success clears the
 * message. */
int sww_regime_load(sww_model *m, const char *path);
/* Or set the same keys from code (the keys of the regime dictionary), then commit.
 * number keys: version degree vnMin vnMax dMin dMax slopeLow slopeHigh rmsResidual
 *   maxResidual yieldVelocity reboundNormal gamma Estar rhoParticle mu obliqueSlide
 *   probabilityPoints
 * list keys: coeffs vn dCrit obliqueVt obliqueVn obliqueDCrit probabilityD
 *   probabilityVn probabilityVt probabilityStick reboundD reboundVn reboundVt reboundEn reboundEt;
 * word keys: representation basis label
 * An unknown key, or a key given as the wrong kind (a number for a list key, ...),
 * is SWW_EINVAL with a message naming it (a misspelt key is an error, not a silent
 * default). Setting any key makes the model not ready until the next successful
 * sww_regime_commit. */
int sww_regime_number(sww_model *m, const char *key, double v);
int sww_regime_list(sww_model *m, const char *key, const double *v, size_t n);
int sww_regime_word(sww_model *m, const char *key, const char *w);
/* Check required keys and consistency; origin names the source in messages. */
int sww_regime_commit(sww_model *m, const char *origin);
/* Forget every regime key (before setting a new map from code). */
void sww_regime_clear(sww_model *m);

/* ---- options (each off / neutral by default) ----------------------------- */
/* Tangential gate: a stick candidate sticks only if vt <= vt_max (d/d_ref)^exponent
 * (vt_max finite >= 0, d_ref finite > 0, |exponent| <= 1000; SWW_EINVAL otherwise). */
int sww_set_tangential_gate(sww_model *m, double vt_max, double d_ref, double exponent);
/* Tangential gate from the regime map's oblique table (model regime): a stick
 * candidate sticks only if d <= sww_dcrit_oblique(vn, vt). Needs a committed
 * regime with obliqueVt/obliqueVn/obliqueDCrit (SWW_EMISSING otherwise). */
int sww_set_tangential_regime(sww_model *m);
void sww_set_tangential_off(sww_model *m);
/* Shear gate with a constant critical wall shear stress tau_c [Pa]. */
int sww_set_shear_gate_constant(sww_model *m, double tau_c);
/* Shear gate with tau_c(d) from JKR rolling / sliding detachment
 * (regime/physics/swp_detach.h) using the regime's gamma, Estar and mu (mu
 * missing: sliding ignored); roughness in (0, 1] multiplies the pull-off force. */
int sww_set_shear_gate_adhesion(sww_model *m, double roughness);
void sww_set_shear_off(sww_model *m);
/* Tangential rebound factor e_t in [0, 1] (default 1): the classic rebound's. */
int sww_set_rebound_tangential(sww_model *m, double e_t);
/* Which rebound a bounce / rip-off leaves with:
 *   SWW_REBOUND_AUTO (default): the kernel's tables (reboundEn, reboundEt) when the
 *     regime has them, else the classic rebound;
 *   SWW_REBOUND_TABLE: the tables (SWW_EMISSING, and the model unchanged, when the
 *     regime has none; a later commit of a regime without them fails the same way);
 *   SWW_REBOUND_CLASSIC: e_n Thornton e_p(yieldVelocity / v_n) or reboundNormal,
 *     e_t the reboundTangential factor; the kernel's tables are not used.
 * With the tables, e_t comes from reboundEt when the regime has it (a map made with
 * --vt), else from the reboundTangential factor. */
enum { SWW_REBOUND_AUTO = 0, SWW_REBOUND_TABLE = 1, SWW_REBOUND_CLASSIC = 2 };
int sww_set_rebound_model(sww_model *m, int model);

/* ---- use ------------------------------------------------------------------ */
/* Decide one impact: p_stick from the map (the rough wall's probability table
 * inside its span, bilinear in ln d and ln v_n; else 1 for d <= d_crit(v_n),
 * 0 otherwise); a stick candidate (u < p_stick) then passes the tangential
 * and shear gates or bounces / is ripped off. Returns SWW_OK, SWW_EINVAL
 * (bad impact: NaN, d <= 0, negative speed, u outside [0,1), tau_w bad while
 * the shear gate is on) or SWW_ENOTREADY. Thread-safe, allocates nothing, writes no message. */
int sww_decide(const sww_model *m, const sww_impact *in, sww_outcome *out);

/* ---- build-up feedback: a face covered by snow ------------------------------
 * A face's state follows from its own deposit m [kg/m2]: bare at m = 0,
 * covered from the covering mass m_c on, in between a blend of the stick
 * probabilities with the covered fraction w = min(1, m / m_c):
 *     p_stick = (1 - w) p_bare + w p_covered,
 * p of each regime its own stick probability with its own gates (out.p_stick
 * of sww_decide with u = 0, and 0 when a gate stops the stick; 0 or 1 for a
 * sharp map). The particle sticks if u < p_stick (with the outcome of the
 * regime more likely to stick); otherwise it leaves with the outcome (reason,
 * rebound, rip-off) of the regime less likely to stick there (the covered one
 * on a tie and w >= 1/2; a bounce by the criterion when that regime's own
 * p > 0). out->d_crit is the blend
 * (1 - w) d_bare + w d_covered, out->p_stick the blended probability.
 * w = 0 and w = 1 are exactly sww_decide of the bare / covered regime.
 * Returns SWW_EINVAL for w outside [0, 1] (or a bad impact). */
int sww_decide_blend(const sww_model *bare, const sww_model *covered, double w,
                     const sww_impact *in, sww_outcome *out);
/* Covered fraction min(1, m / m_c) (0 for m <= 0; NaN for NaN m or m_c <= 0). */
double sww_cover_fraction(double mass_per_area, double cover_mass);
/* Mass per area of one monolayer of spheres of diameter d and density rho,
 * hexagonally close packed: m_c = (pi / (2 sqrt 3)) (2/3) rho d = 0.6046 rho d
 * [kg/m2] (NaN for non-positive or non-finite input, INFINITY where rho d
 * overflows). */
double sww_monolayer_mass(double rho, double d);

/* A uniform number in [0, 1) fixed by its key: a counter-based
 * hash (SplitMix64's finaliser chained over seed, a, b, c, k), 53 random bits;
 * the same on every machine, processor and thread, so an impact's draw can be
 * tied to the parcel (its origin processor and id), the time step and the
 * impacts it made before in that step instead of to a random stream. */
double sww_uniform_hash(unsigned long long seed, long long a, long long b, long long c,
                        long long k);

/* d_crit(v_n) [m]: the fit inside [vnMin, vnMax]; outside it the power law
 * d_crit(vn_end) (v_n/vn_end)^slope anchored at the range end; INFINITY for
 * v_n <= 0 and where the power law exceeds e^709 = 8e307 m (a subnormal v_n),
 * without an overflow; NaN only for NaN input or a model that is not ready. */
double sww_dcrit(const sww_model *m, double vn);
/* d_crit(v_n, v_t) [m] with the oblique table: min(d_crit(v_n), D_t(v^_n, v_t)),
 * d_crit(v_n) the normal interface (above), D_t the tangential limit taken
 * from the table at commit (at nodes where d_crit falls below the head-on
 * value of its v_n column; where the normal limit binds, the lowest-v_n
 * column's value of the row), interpolated bilinearly in ln d over ln v_n and
 * ln v_t, continued below the first non-zero and beyond the last v_t node as
 * a power law with the end segment's slope (never rising with v_t); v^_n = v_n
 * clamped to the table's span (snowregime extends it a decade below the map's
 * speeds). v_t = 0 gives d_crit(v_n) exactly and so does v_t -> 0 when the
 * table has at least two non-zero v_t; without a table it is d_crit(v_n) for
 * every v_t. NaN only for NaN input or a model that is not ready. */
double sww_dcrit_oblique(const sww_model *m, double vn, double vt);
/* The slide length the oblique table was made with [m] (obliqueSlide; NaN
 * without a table or the key: test it with isnan(), never with an ordered
 * comparison, which raises FE_INVALID on a NaN). */
double sww_oblique_slide(const sww_model *m);
/* Check a slide length [m] that a case states for the oblique table (the
 * wrapper's tangentialGate slideLength) against the table's obliqueSlide:
 * SWW_OK when they agree to 1e-9 relative (exactly, for 0); SWW_EINVAL for a
 * slide that is not finite and >= 0, or one that differs; SWW_EMISSING without
 * an oblique table or without obliqueSlide in it. The message names both values
 * and the remedy. Forms no NaN and compares none. */
int sww_check_oblique_slide(sww_model *m, double slide);
/* 1 when the regime has an oblique table (sizes into *nvt, *nvn; may be NULL). */
int sww_oblique_table(const sww_model *m, size_t *nvt, size_t *nvn);
/* 1 when the regime has a stick-probability table (probabilityD, probabilityVn,
 * probabilityStick: a rough wall); its sizes M (diameters) and N (speeds)
 * into *nd, *nvn (may be NULL; 0 without a table). */
int sww_probability_table(const sww_model *m, size_t *nd, size_t *nvn);
/* The v_t nodes of that table (probabilityVt: a rough map over v_t, read at
 * the impact's v_t when the regime tangential gate is on, else at v_t = 0);
 * 0 without; *vt_max (may be NULL) the last node [m/s]. */
size_t sww_probability_vt(const sww_model *m, double *vt_max);
/* Normal rebound factor e_n(v_n) of the classic rebound (Thornton with
 * yieldVelocity, or the constant reboundNormal; 1 without either). */
double sww_rebound_normal(const sww_model *m, double vn);
/* The rebound factors a bounce of (d, v_n, v_t) leaves with under the model's
 * rebound choice (sww_set_rebound_model): the kernel's tables, interpolated
 * bilinearly in (ln d, ln v_n) on each v_t layer and linearly in ln v_t between
 * the non-zero layers (linearly in v_t between the layers 0 and 1 for e_n; e_t
 * takes layer 1 there), clamped to the end nodes in d and v_t and below the first
 * v_n node, continued above the last v_n node by Thornton's e_p(V_y/v_n) /
 * e_p(V_y/v_N) when the regime has yieldVelocity (else clamped); or the classic
 * rebound. In [0, 1], never NaN for finite d > 0, v_n >= 0, v_t >= 0 (NaN for
 * other input or a model that is not ready). */
void sww_rebound(const sww_model *m, double d, double vn, double vt, double *e_n, double *e_t);
/* 1 when the regime has the kernel's rebound tables; their sizes M (diameters),
 * N (normal speeds) and K (tangential speeds; 1 without reboundVt) into *nd,
 * *nvn, *nvt (may be NULL; 0 without tables). */
int sww_rebound_table(const sww_model *m, size_t *nd, size_t *nvn, size_t *nvt);
/* 1 when a bounce uses the tables (AUTO with tables, or TABLE). */
int sww_rebound_uses_table(const sww_model *m);
/* Tangential limit vtMax(d) [m/s] of the constant gate (INFINITY when that
 * gate is off, or the regime gate is on: see sww_dcrit_oblique); NaN for a d
 * that is not finite and > 0. */
double sww_vt_max(const sww_model *m, double d);
/* Critical wall shear stress tau_c(d) [Pa] (INFINITY when the gate is off);
 * NaN for a d outside [SWW_TAU_D_MIN, SWW_TAU_D_MAX] = [1e-12, 1e3] m (NaN and
 * infinities included), where the detachment formulas leave the doubles' range;
 * sww_decide then refuses a stick candidate that reaches the shear gate. */
#define SWW_TAU_D_MIN 1e-12
#define SWW_TAU_D_MAX 1e3
double sww_tau_crit(const sww_model *m, double d);
/* 1 when sww_decide may be called. */
int sww_ready(const sww_model *m);
int sww_tangential_on(const sww_model *m);   /* 0 off, 1 constant, 2 regime */
int sww_shear_on(const sww_model *m);
/* The fit range and the label of the map. */
double sww_vn_min(const sww_model *m);
double sww_vn_max(const sww_model *m);
const char *sww_label(const sww_model *m);
/* One-line description of the model for logs, into buf (always terminated). */
void sww_describe(const sww_model *m, char *buf, size_t n);
const char *sww_fate_name(sww_fate f);

#ifdef __cplusplus
}
#endif
#endif
