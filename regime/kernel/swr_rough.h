/* swr_rough.h - the rough wall's integrator state (swr_rough.c) and its
 * contact detection (swr_rough_contacts.c): the contacts, the neighbour list,
 * their geometry in the scaled units of the impact (not installed). */
#ifndef SWR_ROUGH_H
#define SWR_ROUGH_H

#include <limits.h>
#include <math.h>

#include "swr_internal.h"
#include "swr_normal.h"
#include "swr_spring.h"
#include "swr_wall.h"

/* contacts held at once (a 100 um sphere pressed into 1 um asperities holds a few tens) */
#define RC_MAX 256
/* marks the base plane in a contact's index */
#define PLANE_ID INT_MIN
/* swr_rough_free_flight: no event within the part of the path it scanned; fly on */
#define FLY_ON (INT_MIN + 1)

typedef struct {
    int i, j;             /* asperity index, or i = PLANE_ID */
    double a[3];          /* asperity centre (scaled) */
    const swr_normal *nm; /* normal law of this contact */
    double kd;            /* dashpot stiffness factor sqrt(2 E* sqrt(R*)) */
    double alpha;         /* dashpot alpha from this contact's approach speed */
    double x;             /* sqrt of the contact radius */
    double delta, phi;    /* overlap and dashpot potential at the last step */
    double dnew;          /* overlap after this step's drift */
    double fd;            /* dashpot force at the end of the last step */
    double fne;           /* elastic normal force */
    double n[3];          /* unit normal (wall into sphere) */
    double xi[3];         /* tangential spring displacement */
    double xr[3];         /* rolling displacement */
    double ft[3];         /* tangential force */
    double mr[3];         /* rolling moment */
    double kr;            /* rolling stiffness at the last step (0 before it) */
} rc_contact;

/* an asperity on the neighbour list */
typedef struct {
    int i, j;
    double a[3];          /* centre (scaled) */
    double due;           /* check it again once s->built reaches this */
} rc_near;
/* longest neighbour list kept (a 100 um sphere on 1 um asperities lists about 150) */
#define RC_NEAR_MAX 1024

typedef struct {
    const swr_model *m;
    const swr_wall *w;
    double R, r, L;         /* particle radius, asperity radius (scaled), length unit [m] */
    double invL;            /* 1 / L */
    double zc;              /* asperity centre height (scaled; swr_wall.h) */
    double reach_a;         /* R + r: centre distance at first touch of an asperity */
    swr_normal na, npl;     /* asperity and plane normal laws */
    double kda, kdp;        /* dashpot factors */
    double Is, invIs;       /* moment of inertia, its inverse */
    double invR;            /* 1 / R */
    double Gs, mu, xic;     /* scaled G*, friction, critical rolling displacement */
    double V, T, mass;      /* speed unit [m/s], time unit [s], particle mass [kg] */
    double w2_ref;          /* squared frequency of the reference contact (step_size) */
    int both;               /* dashpot both: the dashpots act while unloading too */
    double margin;          /* extra search distance of swr_rough_new_contacts */
    double guard;           /* no new contact before the sphere has moved this far */
    double moved;           /* distance moved since the last search */
    double built;           /* distance moved since the neighbour list was made */
    int nnear;              /* asperities on the neighbour list */
    int nc;                 /* contacts held: c[0 .. nc-1] */
    rc_contact c[RC_MAX];   /* not cleared at the start (swr_rough_open_contact sets one) */
    rc_near near[RC_NEAR_MAX]; /* the neighbour list of swr_rough_new_contacts */
} rc_state;

/* Asperity centre in scaled units. */
static inline void rc_asp(const rc_state *s, int i, int j, double a[3])
{
    swr_wall_asperity(s->w, i, j, a);
    a[0] *= s->invL;
    a[1] *= s->invL;
    a[2] *= s->invL;
}

/* Overlap and normal of the contact with the asperity centred at a (NULL:
 * the base plane) for the sphere at C. */
static inline double rc_geometry(const rc_state *s, const double *a, const double C[3],
                                 double n[3])
{
    if (!a) {
        n[0] = n[1] = 0.0;
        n[2] = 1.0;
        return s->R - C[2];
    }
    const double d[3] = { C[0] - a[0], C[1] - a[1], C[2] - a[2] };
    const double D = sqrt(swr_dot3(d, d));
    if (D > 0.0) {
        const double inv = 1.0 / D;
        n[0] = d[0] * inv;
        n[1] = d[1] * inv;
        n[2] = d[2] * inv;
    } else {
        n[0] = n[1] = 0.0;
        n[2] = 1.0;
    }
    return s->reach_a - D;
}

static inline int rc_find(const rc_state *s, int i, int j)
{
    for (int k = 0; k < s->nc; k++)
        if (s->c[k].i == i && s->c[k].j == j)
            return k;
    return -1;
}

/* Elastic energy of a contact relative to its jump-in, and what it takes to
 * break it (U_c - U). */
static inline double rc_contact_energy(const rc_contact *c)
{
    return swr_normal_energy(c->nm, c->x);
}

/* Plastic COR of a contact of R* Rc_si [m] at the approach speed vi_si [m/s]
 * (swr_rough_contacts.c). */
double swr_rough_contact_target(const rc_state *s, double Rc_si, double vi_si);
/* Opens a contact at its first touch; -1 past RC_MAX. */
int swr_rough_open_contact(rc_state *s, int i, int j, const double *a, const double v[3],
                           double delta, const double n[3]);
/* The free flight from C with velocity v to the next event (swr_rough_contacts.c). */
double swr_rough_free_flight(const rc_state *s, const double C[3], const double v[3], int *hit_i,
                             int *hit_j);
/* Opens every contact that forms at C; -1 past RC_MAX (swr_rough_contacts.c). */
int swr_rough_new_contacts(rc_state *s, const double C[3], const double v[3]);

#endif
