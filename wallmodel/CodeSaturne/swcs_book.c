/* swcs_book.c - host-neutral bookkeeping of a SnowWall host binding (swcs_book.h). */
#include "swcs_book.h"
#include "swo_out.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct swcs_book {
    size_t n_zones, n_faces;
    swcs_zone_counts *zone;
    unsigned char *set;   /* zone given by swcs_book_set_zone */
    double *deposit;      /* [kg] per face */
    char err[512];
};

static int fail(swcs_book *b, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(b->err, sizeof b->err, fmt, ap);
    va_end(ap);
    return code;
}

const char *swcs_type_name(swcs_type t)
{
    switch (t) {
    case SWCS_SNOW: return "snow";
    case SWCS_ESCAPE: return "escape";
    default: return "none";
    }
}

swcs_book *swcs_book_alloc(size_t n_zones, size_t n_faces)
{
    if (n_zones == 0 || n_zones > 1000000000u || n_faces == 0 || n_faces > 1000000000u)
        return NULL;
    swcs_book *b = calloc(1, sizeof *b);
    if (!b) return NULL;
    b->zone = calloc(n_zones, sizeof *b->zone);
    b->set = calloc(n_zones, 1);
    b->deposit = calloc(n_faces, sizeof *b->deposit);
    if (!b->zone || !b->set || !b->deposit) {
        swcs_book_free(b);
        return NULL;
    }
    b->n_zones = n_zones;
    b->n_faces = n_faces;
    for (size_t z = 0; z < n_zones; ++z) b->zone[z].type = SWCS_NONE;
    return b;
}

void swcs_book_free(swcs_book *b)
{
    if (!b) return;
    free(b->zone);
    free(b->set);
    free(b->deposit);
    free(b);
}

const char *swcs_book_errmsg(const swcs_book *b) { return b ? b->err : "no book"; }

int swcs_book_set_zone(swcs_book *b, int zone, const char *name, const char *type)
{
    if (zone < 0 || (size_t)zone >= b->n_zones)
        return fail(b, SWW_EINVAL, "zone id %d is outside [0, %zu)", zone, b->n_zones);
    if (!name || !name[0])
        return fail(b, SWW_EINVAL, "zone id %d: the zone has no name", zone);
    if (strlen(name) >= SWCS_NAME_MAX)
        return fail(b, SWW_EINVAL, "zone name '%.40s...' is longer than %d characters",
                    name, SWCS_NAME_MAX - 1);
    swcs_type t;
    if (type && strcmp(type, "snow") == 0) t = SWCS_SNOW;
    else if (type && strcmp(type, "escape") == 0) t = SWCS_ESCAPE;
    else if (type && strcmp(type, "none") == 0) t = SWCS_NONE;
    else
        return fail(b, SWW_EINVAL, "zone %s: type '%s' is not one of snow, escape, none",
                    name, type ? type : "(null)");
    if (b->set[zone])
        return fail(b, SWW_EINVAL, "zone %s is given twice (first as %s, now as %s)",
                    name, swcs_type_name(b->zone[zone].type), type);
    swcs_zone_counts *z = &b->zone[zone];
    memset(z, 0, sizeof *z);
    snprintf(z->name, sizeof z->name, "%s", name);
    z->type = t;
    b->set[zone] = 1;
    b->err[0] = '\0';
    return SWW_OK;
}

swcs_type swcs_book_zone_type(const swcs_book *b, int zone)
{
    if (zone < 0 || (size_t)zone >= b->n_zones) return SWCS_NONE;
    return b->zone[zone].type;
}

const swcs_zone_counts *swcs_book_zone(const swcs_book *b, int zone)
{
    if (zone < 0 || (size_t)zone >= b->n_zones) return NULL;
    return &b->zone[zone];
}

size_t swcs_book_n_zones(const swcs_book *b) { return b->n_zones; }
size_t swcs_book_n_faces(const swcs_book *b) { return b->n_faces; }
const double *swcs_book_deposit(const swcs_book *b) { return b->deposit; }

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

int swcs_book_impact(swcs_book *b, const sww_model *m, int zone, size_t face,
                     double d, double mass, const double u[3], const double uw[3],
                     const double n[3], double tau_w, double rnd,
                     sww_outcome *out, double u_new[3])
{
    if (swcs_book_zone_type(b, zone) != SWCS_SNOW)
        return fail(b, SWW_EINVAL, "impact on zone id %d (%s), which is not a snow zone",
                    zone, (zone >= 0 && (size_t)zone < b->n_zones && b->set[zone])
                              ? b->zone[zone].name : "not named");
    swcs_zone_counts *z = &b->zone[zone];
    if (face >= b->n_faces)
        return fail(b, SWW_EINVAL, "zone %s: impact on face %zu, outside [0, %zu)",
                    z->name, face, b->n_faces);
    if (!(isfinite(mass) && mass >= 0))
        return fail(b, SWW_EINVAL, "zone %s face %zu: particle mass %g is not finite and >= 0",
                    z->name, face, mass);
    if (!finite3(u) || (uw && !finite3(uw)) || !finite3(n))
        return fail(b, SWW_EINVAL, "zone %s face %zu: a velocity or the normal is not finite",
                    z->name, face);
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (!(fabs(sqrt(nn) - 1) <= 1e-6))
        return fail(b, SWW_EINVAL, "zone %s face %zu: the normal (%g %g %g) is not a unit vector",
                    z->name, face, n[0], n[1], n[2]);
    const double w[3] = {uw ? uw[0] : 0, uw ? uw[1] : 0, uw ? uw[2] : 0};
    const double r[3] = {u[0] - w[0], u[1] - w[1], u[2] - w[2]};
    const double un = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];   /* > 0: towards the wall */
    const double rt[3] = {r[0] - un * n[0], r[1] - un * n[1], r[2] - un * n[2]};
    sww_impact in;
    in.d = d;
    in.vn = un > 0 ? un : 0;
    in.vt = sqrt(rt[0] * rt[0] + rt[1] * rt[1] + rt[2] * rt[2]);
    in.tau_w = tau_w;
    in.u = rnd;
    const int rc = sww_decide(m, &in, out);
    if (rc == SWW_ENOTREADY)
        return fail(b, rc, "zone %s: the regime map is not loaded", z->name);
    if (rc != SWW_OK)
        return fail(b, rc, "zone %s face %zu: the core refused the impact d %g m, v_n %g m/s, "
                    "v_t %g m/s, tau_w %g Pa, rnd %g", z->name, face, in.d, in.vn, in.vt,
                    in.tau_w, in.u);
    ++z->impacts;
    if (out->range != 0) ++z->outside;
    if (out->fate == SWW_STICK) {
        ++z->sticks;
        z->mass_deposited += mass;
        b->deposit[face] += mass;
        u_new[0] = u_new[1] = u_new[2] = 0;
    } else {
        if (out->fate == SWW_BOUNCE) ++z->bounces; else ++z->ripoffs;
        const double un_new = un > 0 ? -out->e_n * un : un;
        for (int k = 0; k < 3; ++k) u_new[k] = w[k] + out->e_t * rt[k] + un_new * n[k];
    }
    b->err[0] = '\0';
    return SWW_OK;
}

int swcs_book_escape(swcs_book *b, int zone, double mass)
{
    if (swcs_book_zone_type(b, zone) != SWCS_ESCAPE)
        return fail(b, SWW_EINVAL, "escape through zone id %d, which is not an escape zone", zone);
    if (!(isfinite(mass) && mass >= 0))
        return fail(b, SWW_EINVAL, "zone %s: escaping mass %g is not finite and >= 0",
                    b->zone[zone].name, mass);
    ++b->zone[zone].escapes;
    b->zone[zone].mass_escaped += mass;
    return SWW_OK;
}

void swcs_book_pack(const swcs_book *b, double *v)
{
    for (size_t i = 0; i < b->n_zones; ++i) {
        const swcs_zone_counts *z = &b->zone[i];
        double *p = v + SWCS_PACK_PER_ZONE * i;
        p[0] = (double)z->impacts;
        p[1] = (double)z->sticks;
        p[2] = (double)z->bounces;
        p[3] = (double)z->ripoffs;
        p[4] = (double)z->escapes;
        p[5] = (double)z->outside;
        p[6] = z->mass_deposited;
        p[7] = z->mass_escaped;
        p[8] = 0;
    }
}

void swcs_book_unpack(swcs_book *b, const double *v)
{
    for (size_t i = 0; i < b->n_zones; ++i) {
        swcs_zone_counts *z = &b->zone[i];
        const double *p = v + SWCS_PACK_PER_ZONE * i;
        z->impacts = llround(p[0]);
        z->sticks = llround(p[1]);
        z->bounces = llround(p[2]);
        z->ripoffs = llround(p[3]);
        z->escapes = llround(p[4]);
        z->outside = llround(p[5]);
        z->mass_deposited = p[6];
        z->mass_escaped = p[7];
    }
}

size_t swcs_book_summary(const swcs_book *b, const char *prefix, char *buf, size_t n)
{
    size_t len = 0;
    if (n) buf[0] = '\0';
    for (size_t i = 0; i < b->n_zones; ++i) {
        const swcs_zone_counts *z = &b->zone[i];
        char line[512];
        int k;
        if (z->type == SWCS_SNOW)
            k = snprintf(line, sizeof line,
                         "%szone %s (snow): impacts %lld, sticks %lld, bounces %lld, ripoffs %lld, "
                         "deposited mass %.12g kg (%lld impacts outside the fitted v_n range)\n",
                         prefix ? prefix : "", z->name, z->impacts, z->sticks, z->bounces,
                         z->ripoffs, z->mass_deposited, z->outside);
        else if (z->type == SWCS_ESCAPE)
            k = snprintf(line, sizeof line, "%szone %s (escape): escapes %lld, mass %.12g kg\n",
                         prefix ? prefix : "", z->name, z->escapes, z->mass_escaped);
        else
            continue;
        if (k < 0) continue;
        if (len + (size_t)k < n) memcpy(buf + len, line, (size_t)k + 1);
        else if (len < n) buf[len] = '\0';
        len += (size_t)k;
    }
    return len;
}

/* One CSV file through the common output writer (swo_out.h): a temporary in
 * its folder, every write error checked, renamed over path only when path is
 * absent or a regular file; no signal handler (this runs inside the host). */
static FILE *open_out(swcs_book *b, const char *path, swo_set **set)
{
    char err[600];
    *set = NULL;
    if (!path || !path[0]) {
        fail(b, SWW_EIO, "no output path given");
        return NULL;
    }
    const swo_spec spec = { "Code_Saturne SnowWall binding", "output", NULL, 0, 0 };
    FILE *f = NULL;
    if (swo_alloc(&spec, set, err, sizeof err) == SWO_OK)
        f = swo_open(*set, path, err, sizeof err);
    if (!f) {
        fail(b, SWW_EIO, "%s", err);
        swo_free(*set);
        *set = NULL;
    }
    return f;
}

static int close_out(swcs_book *b, swo_set *set)
{
    char err[600];
    const int rc = swo_commit(set, err, sizeof err);
    swo_free(set);
    return rc == SWO_OK ? SWW_OK : fail(b, SWW_EIO, "%s", err);
}

int swcs_book_write_counts(swcs_book *b, const char *path, double time, long step)
{
    swo_set *set;
    FILE *f = open_out(b, path, &set);
    if (!f) return SWW_EIO;
    fprintf(f, "time,step,zone,type,impacts,sticks,bounces,ripoffs,escapes,outside,"
               "deposited_kg,escaped_kg\n");
    for (size_t i = 0; i < b->n_zones; ++i) {
        const swcs_zone_counts *z = &b->zone[i];
        if (z->type == SWCS_NONE) continue;
        fprintf(f, "%.12g,%ld,%s,%s,%lld,%lld,%lld,%lld,%lld,%lld,%.12g,%.12g\n", time, step,
                z->name, swcs_type_name(z->type), z->impacts, z->sticks, z->bounces, z->ripoffs,
                z->escapes, z->outside, z->mass_deposited, z->mass_escaped);
    }
    return close_out(b, set);
}

int swcs_book_write_deposit(swcs_book *b, const char *path, const long long *face_num,
                            const double *cog, const double *area, const int *face_zone)
{
    swo_set *set;
    FILE *f = open_out(b, path, &set);
    if (!f) return SWW_EIO;
    fprintf(f, "face,zone,x,y,z,area_m2,deposit_kg,deposit_kg_m2\n");
    for (size_t i = 0; i < b->n_faces; ++i) {
        const int zi = face_zone[i];
        if (swcs_book_zone_type(b, zi) != SWCS_SNOW) continue;
        const double a = area[i];
        fprintf(f, "%lld,%s,%.9g,%.9g,%.9g,%.9g,%.12g,%.12g\n",
                face_num ? face_num[i] : (long long)i, b->zone[zi].name, cog[3 * i],
                cog[3 * i + 1], cog[3 * i + 2], a, b->deposit[i],
                a > 0 ? b->deposit[i] / a : 0.0);
    }
    return close_out(b, set);
}
