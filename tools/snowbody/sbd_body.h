/* sbd_body.h - the square-back Ahmed body as a closed triangulated surface.
 *
 * The body (Ahmed, Ramm & Faltin 1984, slant 0 degrees): a box of length L,
 * width W and height H standing at clearance h above the ground z = 0, its
 * four front edges rounded with radius R, its rear a flat vertical face; four
 * cylindrical stilts of radius rs hold it. Axes: x downstream from the nose
 * (x = 0) to the rear face (x = L), y to the left of the car (centreline
 * y = 0), z up from the ground.
 *
 * The front is the intersection of the side view's and the plan view's
 * rounded profiles: at a station x in [0, R] the cross-section is the
 * rectangle of half-width W/2 - R + r(x) and half-height H/2 - R + r(x),
 * r(x) = sqrt(R^2 - (R - x)^2); the long edges stay sharp. The surface is one
 * closed shell for the body and one per stilt (each stilt reaches below the
 * ground and into the body, so that a mesher cuts it with both).
 *
 * Regions (one STL solid each): nose (x < R), top, bottom, sides, rear (the
 * rear face less the sensor), sensor (a rectangle on the rear face), stilts.
 *
 * Lifecycle: sbd_params_default, sbd_params_set (key=value), sbd_params_check,
 * sbd_build -> sbd_surface, sbd_free. Errors are returned with a message. */
#ifndef SBD_BODY_H
#define SBD_BODY_H

#include <stddef.h>

typedef struct {
    double length;        /* L [m] */
    double width;         /* W [m] */
    double height;        /* H [m] */
    double clearance;     /* h, ground to the underside [m] */
    double radius;        /* R of the four front edges [m] */
    double stilt_radius;  /* [m] */
    double stilt_x1;      /* axis of the front pair, from the nose [m] */
    double stilt_x2;      /* axis of the rear pair, from the nose [m] */
    double stilt_y;       /* axis distance from the centreline [m] */
    double stilt_below;   /* how far a stilt reaches below the ground [m] */
    double stilt_into;    /* how far a stilt reaches into the body [m] */
    double sensor_width;  /* along y [m] */
    double sensor_height; /* along z [m] */
    double sensor_y;      /* centre, from the centreline [m] */
    double sensor_z;      /* centre, above the ground [m] */
    double cell;          /* target edge length of the flat faces [m] */
    int    arc_steps;     /* segments of each quarter arc of the front */
    int    stilt_sides;   /* sides of a stilt's polygon */
} sbd_params;

enum { SBD_NOSE, SBD_TOP, SBD_BOTTOM, SBD_SIDES, SBD_REAR, SBD_SENSOR, SBD_STILTS, SBD_NREGION };

typedef struct {
    size_t nv, nt;
    double (*v)[3];   /* vertices [m] */
    size_t (*t)[3];   /* triangles, counter-clockwise seen from outside */
    int *region;      /* region of each triangle */
} sbd_surface;

/* the published dimensions (1044 x 389 x 288 mm, clearance 50 mm, R 100 mm,
 * stilts of 30 mm diameter) and the default sensor and resolution */
void sbd_params_default(sbd_params *p);
/* one key=value: keys are the field names above; 0, or -1 with a message */
int sbd_params_set(sbd_params *p, const char *key_value, char *err, size_t errlen);
/* the geometry is possible (a front that fits, stilts under the body, the
 * sensor on the rear face, resolutions in range): 0, or -1 with a message */
int sbd_params_check(const sbd_params *p, char *err, size_t errlen);
/* the list of keys of sbd_params_set, for a help text */
const char *sbd_params_keys(void);

int sbd_build(const sbd_params *p, sbd_surface **out, char *err, size_t errlen);
void sbd_free(sbd_surface *s);

const char *sbd_region_name(int region);

/* closed-form volume of the body without its stilts [m^3] (the exact
 * rounded front, not its polygon) */
double sbd_body_volume_exact(const sbd_params *p);

/* measures of a surface */
typedef struct {
    size_t open_edges;       /* edges used once or by two triangles in the same direction */
    size_t nonmanifold;      /* edges used by more than two triangles */
    double volume;           /* enclosed volume of all shells, by the divergence theorem [m^3] */
    double body_volume;      /* the same over the triangles of the body's regions [m^3] */
    double frontal_area;     /* body's area projected along x: half the sum of |n_x| dA [m^2] */
    double area[SBD_NREGION];/* area of each region [m^2] */
} sbd_measure;

int sbd_measure_surface(const sbd_surface *s, sbd_measure *m, char *err, size_t errlen);

#endif
