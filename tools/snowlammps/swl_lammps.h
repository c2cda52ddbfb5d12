/* swl_lammps.h - snowlammps: the rough-wall impacts of the kernel's 3-D
 * multi-contact integrator (regime/kernel/swr_rough.c) run again in LAMMPS
 * (doc/kernel.md, "Cross-check against LAMMPS").
 *
 * The wall: the kernel's default lattice (square, hemispherical asperities of
 * radius r at spacing s on the plane z = 0), in LAMMPS frozen spheres of radius r
 * centred on z = 0 plus the base plane as fix wall/gran (tools/snowlammps/
 * impact.lmp). The material constants are the kernel's defaults
 * (swr_params_default with wall lattice), so both codes use the same numbers.
 *
 * Modules: swl_model.c (constants and the JKR closed forms), swl_run.c (one
 * batch of LAMMPS impacts in one lmp process, the contacts counted from its
 * trajectory; the kernel's impacts through libswrkernel), swl_compare.c (the
 * calibrations, the comparison, the tables). Every function returns an error
 * (0 / -1 with a message in err); none exits.
 */
#ifndef SWL_LAMMPS_H
#define SWL_LAMMPS_H

#include "swo_out.h"
#include <stddef.h>
#include <stdio.h>

#include "swr_collide.h"

#define SWL_ERRLEN 2600

/* ------------------------------------------------------------ model */

typedef struct {
    swr_params p;       /* the kernel's defaults with wall lattice */
    double d, R;        /* particle diameter and radius [m] */
    double r, sp;       /* asperity radius, lattice spacing [m] */
    double rho, mass;   /* particle density [kg/m3], mass [kg] */
    double Es, Gs;      /* effective Young's and shear modulus [Pa] */
    double gamma, mu, xic, hold, accuracy;
    double Ra;          /* R* of an asperity contact [m] */
} swl_model;

/* The constants of both codes for diameter d. 0, or -1 with a message when the
 * kernel's default lattice is not a regular square lattice. */
int swl_model_init(swl_model *m, double d, char *err, size_t errlen);
/* Hertz contact time of the particle on a contact of R* = Rs at speed v. */
double swl_tc(const swl_model *m, double v, double Rs);
/* JKR curve in the contact radius a: overlap *delta and force *F. */
void swl_jkr(const swl_model *m, double a, double Rs, double gam, double *delta, double *F);
/* Work lost from the jump-in (delta = 0) to a break at contact radius a_off. */
double swl_jkr_loss(const swl_model *m, double Rs, double gam, double a_off);
/* Contact radius a_f at the kernel's break (delta_c). */
double swl_jkr_af(const swl_model *m, double Rs, double gam);
/* The overlap at which LAMMPS's pair granular jkr breaks a contact. */
double swl_lammps_pulloff(const swl_model *m, double Rs, double gam);
/* Contact radius on the stable branch (a >= a_f) at overlap delta. */
double swl_a_at(const swl_model *m, double delta, double Rs, double gam);

/* Python's repr of a double (shortest round trip, ".0" on integral values,
 * exponent below 1e-4 and from 1e16): the text of impacts.csv's plain columns. */
void swl_repr(double x, char *buf, size_t n);
/* Shortest text that reads back as x (printf %g style). */
void swl_shortest(double x, char *buf, size_t n);
/* Seconds on a monotonic clock. */
double swl_now(void);

/* ------------------------------------------------------------ LAMMPS */

typedef struct {
    double x, y, vn, vt;  /* impact point [m], normal and tangential speed [m/s] */
    int jkr;              /* 1: JKR (coh = gamma/2, rolling sds), 0: Hertz */
    double dcoef;         /* tsuji input COR; >= 1: no damping */
    int flat;             /* 1: the base plane alone */
    double hold;          /* time bound in flat-wall contact times; <= 0: the default */
    double dt_factor;     /* time step factor (1; 0.5 halving) */
    int pjkr;             /* 1: the base plane JKR too */
} swl_spec;

typedef struct {
    int bounce;           /* 1: left the wall */
    double t, x[3], v[3], w[3], dt;
    long contacts, plane_contacts;
    double gap_min, dmin_f;
    int nsep;             /* separations seen on the asperity at (0, 0) */
    double sep[2];        /* the first: overlap at the last step with a force, the first without */
} swl_lres;

typedef struct {
    const char *lmp;      /* the LAMMPS binary (a path, or a name on PATH) */
    const char *deck;     /* tools/snowlammps/impact.lmp */
    const char *work;     /* work folder */
    const swl_model *m;
    double steps;         /* steps per flat-wall contact time */
    double hold;          /* default time bound (100 contact times) */
    long n;               /* impacts written so far (file numbering) */
    double seconds;       /* wall time in lmp */
    long runs;            /* impacts run */
} swl_lammps;

/* Run n impacts in one lmp process. 0, or -1 with a message (lmp failed, no
 * result, a NaN result, an unreadable trajectory). */
int swl_lammps_run(swl_lammps *L, const swl_spec *s, size_t n, swl_lres *res, char *err,
                   size_t errlen);
int swl_lammps_one(swl_lammps *L, const swl_spec *s, swl_lres *res, char *err, size_t errlen);
/* The version of lmp ("29 Sep 2021 - Update 2"; "unknown version"). 0 or -1. */
int swl_lammps_version(const swl_lammps *L, char *ver, size_t n, char *err, size_t errlen);

/* ------------------------------------------------------------ the kernel */

typedef struct {
    int bounce;
    double v[3];          /* v_x, v_y, v_z of the rebound (0 on a stick; v_y 0 on a flat wall) */
    double wy;            /* spin about y at the last step (also on a stick) */
    double w[3];          /* the rebound spin (0 on a stick and on a flat wall) */
    long contacts, steps;
    char status[16];      /* ok | step-bound */
    double dt, energy_err;
} swl_ores;

#define SWL_NMODELS 16
typedef struct {
    const swl_model *m;
    double cor;           /* the COR of the damped cases */
    double accuracy;      /* the kernel's accuracy */
    double seconds;
    long runs;
    struct { int jkr, lattice; double cor, acc; swr_model *k; } cache[SWL_NMODELS];
    int ncache;
} swl_ours;

/* One impact of the kernel: jkr adhesion or none, cor (>= 1: elastic, <= 0: the
 * default O->cor), lattice or the flat wall, accuracy (<= 0: the default). */
int swl_ours_impact(swl_ours *O, double x, double y, double vn, double vt, int jkr, double cor,
                    int lattice, double accuracy, swl_ores *r, char *err, size_t errlen);
void swl_ours_free(swl_ours *O);

/* ------------------------------------------------------------ comparison */

enum { SWL_HERTZ = 0, SWL_JKR_ELASTIC, SWL_JKR };
#define SWL_MAXLIST 16

typedef struct {
    const char *out;      /* output folder */
    swo_set *set;         /* its output set (swo_out.h), opened by the caller */
    int force;            /* --force: write into a foreign folder */
    const char *lmp, *deck;
    double d;
    int grid;
    const char *angles_s, *speeds_h_s, *speeds_j_s;
    double angles[SWL_MAXLIST], speeds_h[SWL_MAXLIST], speeds_j[SWL_MAXLIST];
    int nangles, nspeeds_h, nspeeds_j;
    int cases[SWL_MAXLIST], ncases;
    double cor, lmp_steps;
    int halve, no_single;
    double tol_v, tol_w, tol_e, tol_vz_jkr;
} swl_opts;

/* The whole comparison: outputs summary.md and impacts.csv in o->out (through
 * o->set, committed here; the work files of LAMMPS in a folder .work-XXXXXX of
 * its own there, removed at the end), the
 * summary and the impacts outside the tolerances on `report`. Returns 0 (all
 * within), 3 (some outside), or -1 with a message (a run failed). */
int swl_compare_run(const swl_opts *o, FILE *report, char *err, size_t errlen);

#endif
