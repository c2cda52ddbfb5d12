/* swr_wall.h - wall geometry, kept apart from the contact laws.
 *
 * A wall answers one question: for a sphere of radius R at position pos,
 * what is the overlap, the unit normal (from the wall into the sphere) and the
 * effective radius R* of the contact. The flat wall (plane z = 0, normal +z)
 * gives delta = R - z and R* = R, and its normal does not depend on where the
 * sphere touches, which is what lets swr_collide.c integrate the normal motion
 * in one dimension. A rough wall (a lattice of asperity spheres of radius r,
 * ../shared/snow-physics.md section 7) would add a type here that returns
 * the nearest asperity's overlap, normal and R* = R r/(R + r); the collision
 * integrator would then move the sphere in 3-D with that normal.
 */
#ifndef SWR_WALL_H
#define SWR_WALL_H

typedef enum { SWR_WALL_FLAT = 0 } swr_wall_type;

typedef struct {
    swr_wall_type type;
} swr_wall;

typedef struct {
    double delta;     /* overlap, > 0 in compression */
    double n[3];      /* unit normal, from the wall into the sphere */
    double Rstar;     /* effective radius of the contact */
} swr_wall_contact;

/* Contact of a sphere of radius R centred at pos with the wall. */
void swr_wall_contact_at(const swr_wall *w, const double pos[3], double R, swr_wall_contact *c);

/* Effective radius of a first contact of a sphere of radius R. */
double swr_wall_rstar(const swr_wall *w, double R);

#endif
