/* swr_params.c - material and model settings: defaults, parsing, validation
 * (see swr_params.h). Every numeric key has a physical range; a value outside
 * it, NaN, inf, trailing text or an unknown key is rejected with a one-line
 * message naming the key and the value. */
#include "swr_params.h"
#include "swo_err.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* Numeric keys: name, place in the struct, accepted closed range [lo, hi].
 * The ranges accept the extreme validation grid (E 0.1-100 GPa, gamma
 * 0.01-10 J/m2, e 0.01-1) with room on both sides, and reject what is not a
 * physical material or a usable setting. */
typedef struct {
    const char *key;
    size_t off;
    double lo, hi;
    const char *what;
} num_key;

#define NK(k, lo, hi, what) { #k, offsetof(swr_params, k), lo, hi, what }
static const num_key num_keys[] = {
    NK(rho,      10.0,   3.0e4,  "particle density [kg/m3]"),
    NK(E,        1.0e6,  1.2e12, "particle Young's modulus [Pa]"),
    NK(nu,       0.0,    0.5,    "particle Poisson's ratio [-]"),
    NK(sigma_y,  1.0e3,  1.0e10, "particle yield stress [Pa]"),
    NK(E_wall,   1.0e6,  1.2e12, "wall Young's modulus [Pa]"),
    NK(nu_wall,  0.0,    0.5,    "wall Poisson's ratio [-]"),
    NK(rho_wall, 1.0,    3.0e4,  "wall density [kg/m3]"),
    NK(gamma,    0.0,    100.0,  "work of adhesion [J/m2]"),
    NK(z0,       1.0e-11, 1.0e-8, "equilibrium separation [m]"),
    NK(mu,       0.0,    10.0,   "sliding friction coefficient [-]"),
    NK(xi_crit,  1.0e-12, 1.0e-6, "critical rolling displacement [m]"),
    NK(accuracy, 10.0,   1.0e5,  "steps per Hertz contact time [-]"),
};
/* Largest asperity spacing [m] (its range below; the lower bound on a lattice
 * is 2 asperity_r, checked in swr_params_validate). */
#define ASPERITY_SPACING_MAX 10.0

/* The rough-wall keys: set and validated like the others, printed only for
 * wall lattice (a flat-wall output lists no wall keys, as before). */
static const num_key wall_keys[] = {
    NK(asperity_r,       1.0e-9, 1.0,  "asperity radius [m]"),
    NK(asperity_spacing, 1.0e-9, ASPERITY_SPACING_MAX, "asperity spacing [m]"),
    NK(asperity_jitter,  0.0,    0.5,  "random lateral offset of an asperity / spacing [-]"),
    NK(asperity_dz,      0.0,    1.0,  "random sinking depth of an asperity [m]"),
    NK(wall_seed,        0.0,    9.007199254740992e15, "seed of the random wall (integer)"),
    NK(rough_hold,       1.0,    1.0e5, "contact times in contact before a held sphere counts as stuck [-]"),
};
#undef NK
#define N_NUM (sizeof num_keys / sizeof num_keys[0])
#define N_WALL (sizeof wall_keys / sizeof wall_keys[0])

/* Accepted range of a constant coefficient of restitution. */
#define COR_MIN 1.0e-3
#define COR_MAX 1.0

/* The message names what it got; bytes that are not printable ASCII (binary
 * data given as a config file) are shown as '?', never echoed raw. */
#define fail(err, errlen, ...) swo_fail(-1, err, errlen, __VA_ARGS__)

void swr_params_default(swr_params *p)
{
    memset(p, 0, sizeof *p);
    p->rho = 920.0;
    p->E = 9.8e9;
    p->nu = 0.31;
    p->sigma_y = 1.0e6;
    p->E_wall = 2.0e9;
    p->nu_wall = 0.35;
    p->rho_wall = 1100.0;
    p->gamma = 0.2;
    p->adhesion = SWR_ADHESION_JKR;
    p->z0 = 0.3e-9;
    p->cor = SWR_COR_THORNTON;
    p->cor_value = 1.0;
    p->cor_pair = SWR_PAIR_WALL;
    p->mu = 0.05;
    p->xi_crit = 1.0e-9;
    p->accuracy = 60.0;
    p->wall = SWR_WALL_KIND_FLAT;
    p->lattice = SWR_LATTICE_SQUARE;
    p->asperity_r = 1.0e-6;
    p->asperity_spacing = 2.0e-6;
    p->asperity_jitter = 0.0;
    p->asperity_dz = 0.0;
    p->dashpot_given = 0;
    p->wall_seed = 1.0;
    p->rough_hold = 30.0;
    p->rough_step = SWR_ROUGH_STEP_ADAPTIVE;
    p->asperity_shape = SWR_ASPERITY_HEMISPHERE;
    p->asperity_yield = SWR_YIELD_CONTACT;
}

/* Strict number: the whole text (surrounding blanks allowed), finite. */
static int parse_number(const char *s, double *out)
{
    if (strpbrk(s, "xX"))   /* decimal only: strtod also reads hexadecimal */
        return -1;
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s)
        return -1;
    while (isspace((unsigned char)*end))
        end++;
    if (*end != '\0' || errno == ERANGE || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

static double *field(swr_params *p, const num_key *k)
{
    return (double *)((char *)p + k->off);
}

static const num_key *find_in(const num_key *t, size_t n, const char *key)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(t[i].key, key) == 0)
            return &t[i];
    return NULL;
}

static const num_key *find_num(const char *key)
{
    const num_key *k = find_in(num_keys, N_NUM, key);
    return k ? k : find_in(wall_keys, N_WALL, key);
}

static double value_of(const swr_params *p, const num_key *k)
{
    return *(const double *)((const char *)p + k->off);
}

/* v in [lo, hi], false for NaN without comparing it: an ordered comparison of a
 * NaN raises FE_INVALID, which OpenFOAM and the tests trap. */
static int in_range(double v, double lo, double hi)
{
    return !isnan(v) && v >= lo && v <= hi;
}

/* Every key of table t within its range: 0, or -1 naming the first that is not. */
static int check_ranges(const swr_params *p, const num_key *t, size_t n, char *err, size_t errlen)
{
    for (size_t i = 0; i < n; i++) {
        const double v = value_of(p, &t[i]);
        if (!in_range(v, t[i].lo, t[i].hi))
            return fail(err, errlen, "%s: %g is out of range [%g, %g] (%s)", t[i].key, v, t[i].lo,
                        t[i].hi, t[i].what);
    }
    return 0;
}

static void print_keys(const swr_params *p, const num_key *t, size_t n, const char *pre, FILE *stream)
{
    for (size_t i = 0; i < n; i++)
        fprintf(stream, "%s%s %.17g\n", pre, t[i].key, value_of(p, &t[i]));
}

/* The keys that take one of a few names: the names in the order of the
 * enum's values (the first is the default), and how each sets its field. */
static const char *const wall_names[] = { "flat", "lattice" };
static const char *const lattice_names[] = { "square", "hex" };
static const char *const yield_names[] = { "contact", "particle", "elastic" };
static const char *const shape_names[] = { "hemisphere", "sphere" };
static const char *const step_names[] = { "adaptive", "fixed" };
static const char *const pair_names[] = { "wall", "particle" };
static const char *const dashpot_names[] = { "loading", "both" };
static const char *const adhesion_names[] = { "jkr", "none" };
static void set_wall(swr_params *p, int v) { p->wall = (swr_wall_kind)v; }
static void set_lattice(swr_params *p, int v) { p->lattice = (swr_lattice)v; }
static void set_yield(swr_params *p, int v) { p->asperity_yield = (swr_asperity_yield)v; }
static void set_shape(swr_params *p, int v) { p->asperity_shape = (swr_asperity_shape)v; }
static void set_step(swr_params *p, int v) { p->rough_step = (swr_rough_step)v; }
static void set_pair(swr_params *p, int v) { p->cor_pair = (swr_pair)v; }
static void set_dashpot(swr_params *p, int v)
{
    p->dashpot = (swr_dashpot)v;
    p->dashpot_given = 1;
}
static void set_adhesion(swr_params *p, int v) { p->adhesion = (swr_adhesion)v; }
typedef struct {
    const char *key;
    const char *const *names;
    int n;
    void (*set)(swr_params *p, int v);
} enum_key;
#define EK(K, NAMES, SET) { K, NAMES, (int)(sizeof NAMES / sizeof NAMES[0]), SET }
static const enum_key enum_keys[] = {
    EK("wall", wall_names, set_wall),
    EK("asperity_yield", yield_names, set_yield),
    EK("asperity_shape", shape_names, set_shape),
    EK("rough_step", step_names, set_step),
    EK("lattice", lattice_names, set_lattice),
    EK("cor_pair", pair_names, set_pair),
    EK("dashpot", dashpot_names, set_dashpot),
    EK("adhesion", adhesion_names, set_adhesion),
};
#undef EK
#define N_ENUM (sizeof enum_keys / sizeof enum_keys[0])

/* The name of an enum value (an invalid one prints as the default). */
static const char *name_of(const char *const *names, int n, int v)
{
    return v >= 0 && v < n ? names[v] : names[0];
}
#define NAME_OF(NAMES, V) name_of(NAMES, (int)(sizeof NAMES / sizeof NAMES[0]), (int)(V))

int swr_params_set(swr_params *p, const char *key, const char *value, char *err, size_t errlen)
{
    if (!key || !value)
        return fail(err, errlen, "missing key or value");
    const num_key *k = find_num(key);
    if (k) {
        double v;
        if (parse_number(value, &v) != 0)
            return fail(err, errlen, "%s: '%s' is not a finite decimal number (%s)", key, value, k->what);
        if (!in_range(v, k->lo, k->hi))
            return fail(err, errlen, "%s: %s is out of range [%g, %g] (%s)", key, value,
                        k->lo, k->hi, k->what);
        if (k->off == offsetof(swr_params, wall_seed) && v != floor(v))
            return fail(err, errlen, "%s: %s is not an integer (%s)", key, value, k->what);
        *field(p, k) = v;
        return 0;
    }
    /* the keys that take one of a few names */
    for (size_t i = 0; i < N_ENUM; i++) {
        const enum_key *k = &enum_keys[i];
        if (strcmp(key, k->key) != 0)
            continue;
        for (int v = 0; v < k->n; v++)
            if (strcmp(value, k->names[v]) == 0) {
                k->set(p, v);
                return 0;
            }
        /* "KEY: 'VALUE' is neither A, B nor C" */
        char list[160] = "";
        for (int v = 0; v < k->n; v++) {
            const size_t len = strlen(list);
            snprintf(list + len, sizeof list - len, "%s%s", v == 0 ? "" : v == k->n - 1 ? " nor " : ", ",
                     k->names[v]);
        }
        return fail(err, errlen, "%s: '%s' is neither %s", key, value, list);
    }
    if (strcmp(key, "cor") == 0) {
        if (strcmp(value, "elastic") == 0) {
            p->cor = SWR_COR_ELASTIC;
            p->cor_value = 1.0;
        } else if (strcmp(value, "thornton") == 0) {
            p->cor = SWR_COR_THORNTON;
        } else if (strcmp(value, "thornton-asymptote") == 0) {
            p->cor = SWR_COR_THORNTON_ASYMPTOTE;
        } else if (strcmp(value, "thornton-ning") == 0) {
            p->cor = SWR_COR_THORNTON_NING;
        } else {
            double v;
            if (parse_number(value, &v) != 0)
                return fail(err, errlen,
                            "cor: '%s' is neither elastic, thornton, thornton-asymptote, "
                            "thornton-ning nor a number", value);
            if (!in_range(v, COR_MIN, COR_MAX))
                return fail(err, errlen, "cor: %s is out of range [%g, %g] (constant restitution)",
                            value, COR_MIN, COR_MAX);
            p->cor = SWR_COR_CONSTANT;
            p->cor_value = v;
        }
        return 0;
    }
    return fail(err, errlen, "unknown key '%s' (value '%s')", key, value);
}

/* Copy [b, e) into buf without surrounding blanks. */
static void trimmed(char *buf, size_t n, const char *b, const char *e)
{
    while (b < e && isspace((unsigned char)*b))
        b++;
    while (e > b && isspace((unsigned char)e[-1]))
        e--;
    size_t len = (size_t)(e - b);
    if (len >= n)
        len = n - 1;
    memcpy(buf, b, len);
    buf[len] = '\0';
}

int swr_params_set_kv(swr_params *p, const char *kv, char *err, size_t errlen)
{
    const char *eq = kv ? strchr(kv, '=') : NULL;
    if (!eq)
        return fail(err, errlen, "'%s' is not of the form key=value", kv ? kv : "(null)");
    char key[64], val[256];
    trimmed(key, sizeof key, kv, eq);
    trimmed(val, sizeof val, eq + 1, eq + strlen(eq));
    if (key[0] == '\0' || val[0] == '\0')
        return fail(err, errlen, "'%s' is not of the form key=value", kv);
    return swr_params_set(p, key, val, err, errlen);
}

int swr_params_load(swr_params *p, const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return fail(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    char line[1024], key[64], val[256], msg[320];
    int lineno = 0, rc = 0;
    /* the keys set so far and their lines: a key given twice in one file is an
     * error, naming both lines (a later value must not silently win) */
    struct { char key[64]; int line; } seen[64];
    int nseen = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        /* a NUL byte ends the string early: found before the line's length
         * is judged (it was called "line too long") */
        const size_t got = strlen(line);
        if (got + 1 < sizeof line && !strchr(line, '\n') && !feof(f)) {
            rc = fail(err, errlen, "%s:%d: the line holds a NUL byte (not a text file?)", path,
                      lineno);
            break;
        }
        if (!strchr(line, '\n') && !feof(f)) {
            rc = fail(err, errlen, "%s:%d: line too long", path, lineno);
            break;
        }
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        const char *b = line;
        while (isspace((unsigned char)*b))
            b++;
        if (*b == '\0')
            continue;
        const char *ke = b;
        while (*ke && !isspace((unsigned char)*ke) && *ke != '=')
            ke++;
        trimmed(key, sizeof key, b, ke);
        const char *v = ke;
        while (isspace((unsigned char)*v))
            v++;
        if (*v == '=')
            v++;
        trimmed(val, sizeof val, v, v + strlen(v));
        if (val[0] == '\0') {
            rc = fail(err, errlen, "%s:%d: key '%s' has no value", path, lineno, key);
            break;
        }
        if (swr_params_set(p, key, val, msg, sizeof msg) != 0) {
            rc = fail(err, errlen, "%s:%d: %s", path, lineno, msg);
            break;
        }
        int first = 0;
        for (int k = 0; k < nseen && !first; k++)
            if (strcmp(seen[k].key, key) == 0)
                first = seen[k].line;
        if (first) {
            rc = fail(err, errlen, "%s:%d: key '%s' is given twice (first at line %d)", path,
                      lineno, key, first);
            break;
        }
        if (nseen < (int)(sizeof seen / sizeof seen[0])) {
            snprintf(seen[nseen].key, sizeof seen[nseen].key, "%s", key);
            seen[nseen++].line = lineno;
        }
    }
    if (rc == 0 && ferror(f))
        rc = fail(err, errlen, "%s: read error", path);
    fclose(f);
    return rc;
}

int swr_params_validate(const swr_params *p, char *err, size_t errlen)
{
    if (check_ranges(p, num_keys, N_NUM, err, errlen) != 0)
        return -1;
    if (p->cor < SWR_COR_ELASTIC || p->cor > SWR_COR_THORNTON_NING)
        return fail(err, errlen, "cor: invalid mode %d", (int)p->cor);
    if (p->cor == SWR_COR_CONSTANT && !in_range(p->cor_value, COR_MIN, COR_MAX))
        return fail(err, errlen, "cor: %g is out of range [%g, %g] (constant restitution)",
                    p->cor_value, COR_MIN, COR_MAX);
    if (p->cor_pair != SWR_PAIR_WALL && p->cor_pair != SWR_PAIR_PARTICLE)
        return fail(err, errlen, "cor_pair: invalid value %d", (int)p->cor_pair);
    if (p->dashpot != SWR_DASHPOT_LOADING && p->dashpot != SWR_DASHPOT_BOTH)
        return fail(err, errlen, "dashpot: invalid value %d", (int)p->dashpot);
    if (p->adhesion != SWR_ADHESION_JKR && p->adhesion != SWR_ADHESION_NONE)
        return fail(err, errlen, "adhesion: invalid value %d", (int)p->adhesion);
    if (p->wall != SWR_WALL_KIND_FLAT && p->wall != SWR_WALL_KIND_LATTICE)
        return fail(err, errlen, "wall: invalid value %d", (int)p->wall);
    if (p->lattice != SWR_LATTICE_SQUARE && p->lattice != SWR_LATTICE_HEX)
        return fail(err, errlen, "lattice: invalid value %d", (int)p->lattice);
    if (p->asperity_yield != SWR_YIELD_CONTACT && p->asperity_yield != SWR_YIELD_PARTICLE
        && p->asperity_yield != SWR_YIELD_ELASTIC)
        return fail(err, errlen, "asperity_yield: invalid value %d", (int)p->asperity_yield);
    if (p->asperity_shape != SWR_ASPERITY_HEMISPHERE && p->asperity_shape != SWR_ASPERITY_SPHERE)
        return fail(err, errlen, "asperity_shape: invalid value %d", (int)p->asperity_shape);
    if (p->rough_step != SWR_ROUGH_STEP_ADAPTIVE && p->rough_step != SWR_ROUGH_STEP_FIXED)
        return fail(err, errlen, "rough_step: invalid value %d", (int)p->rough_step);
    if (check_ranges(p, wall_keys, N_WALL, err, errlen) != 0)
        return -1;
    /* Overlapping asperities (spacing below 2 r) put ever more asperities
     * under one contact patch as the spacing shrinks, and the contact search of
     * one impact grows as (R/s)^2 without bound (hours for one impact); the
     * lattice is defined for asperities that at most touch. */
    if (p->wall == SWR_WALL_KIND_LATTICE && p->asperity_spacing < 2.0 * p->asperity_r)
        return fail(err, errlen, "asperity_spacing: %g m is below 2 asperity_r = %g m: the "
                    "asperities would overlap (accepted on a lattice: 2 asperity_r <= "
                    "asperity_spacing <= %g m)", p->asperity_spacing, 2.0 * p->asperity_r,
                    ASPERITY_SPACING_MAX);
    /* Settings the chosen law or wall does not use are refused, not ignored:
     * accepted, they would change nothing without a word. */
    if (p->dashpot_given && (p->cor == SWR_COR_ELASTIC || p->cor == SWR_COR_THORNTON_NING))
        return fail(err, errlen, "dashpot: %s is not used by cor %s, which has no dashpot "
                    "(it acts with cor thornton, thornton-asymptote or a constant COR)",
                    p->dashpot == SWR_DASHPOT_BOTH ? "both" : "loading",
                    p->cor == SWR_COR_ELASTIC ? "elastic" : "thornton-ning");
    /* an asperity sunk by its height or more (a hemisphere's radius, a whole
     * sphere's diameter) is level with the base plane or below it: the impact
     * would see the flat wall without a word */
    const int sph = p->asperity_shape == SWR_ASPERITY_SPHERE;
    if (p->wall == SWR_WALL_KIND_LATTICE && p->asperity_dz >= (sph ? 2.0 : 1.0) * p->asperity_r)
        return fail(err, errlen, "asperity_dz: %g m is not below the asperity's height %g m "
                    "(asperity_shape %s, asperity_r %g m): asperities sunk that deep are level "
                    "with the base plane or below it (accepted: 0 <= asperity_dz < %s)",
                    p->asperity_dz, (sph ? 2.0 : 1.0) * p->asperity_r,
                    sph ? "sphere" : "hemisphere", p->asperity_r,
                    sph ? "2 asperity_r" : "asperity_r");
    if (p->wall == SWR_WALL_KIND_LATTICE && p->cor == SWR_COR_THORNTON_NING)
        return fail(err, errlen, "cor: thornton-ning is not available on a rough wall (wall lattice): "
                                 "its contact history is kept for one contact only; use thornton");
    return 0;
}

void swr_params_print(const swr_params *p, const char *prefix, FILE *stream)
{
    const char *pre = prefix ? prefix : "";
    print_keys(p, num_keys, N_NUM, pre, stream);
    fprintf(stream, "%sadhesion %s\n", pre, NAME_OF(adhesion_names, p->adhesion));
    switch (p->cor) {
    case SWR_COR_ELASTIC: fprintf(stream, "%scor elastic\n", pre); break;
    case SWR_COR_CONSTANT: fprintf(stream, "%scor %.17g\n", pre, p->cor_value); break;
    case SWR_COR_THORNTON: fprintf(stream, "%scor thornton\n", pre); break;
    case SWR_COR_THORNTON_ASYMPTOTE: fprintf(stream, "%scor thornton-asymptote\n", pre); break;
    case SWR_COR_THORNTON_NING: fprintf(stream, "%scor thornton-ning\n", pre); break;
    }
    fprintf(stream, "%scor_pair %s\n", pre, NAME_OF(pair_names, p->cor_pair));
    /* only where the law has a dashpot: printed settings load back unchanged */
    if (p->cor != SWR_COR_ELASTIC && p->cor != SWR_COR_THORNTON_NING)
        fprintf(stream, "%sdashpot %s\n", pre, NAME_OF(dashpot_names, p->dashpot));
    if (p->wall == SWR_WALL_KIND_LATTICE) {
        fprintf(stream, "%swall lattice\n%slattice %s\n", pre, pre, NAME_OF(lattice_names, p->lattice));
        print_keys(p, wall_keys, N_WALL, pre, stream);
        fprintf(stream, "%sasperity_yield %s\n", pre, NAME_OF(yield_names, p->asperity_yield));
        fprintf(stream, "%sasperity_shape %s\n", pre, NAME_OF(shape_names, p->asperity_shape));
        fprintf(stream, "%srough_step %s\n", pre, NAME_OF(step_names, p->rough_step));
    }
}
