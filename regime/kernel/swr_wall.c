/* swr_wall.c - wall geometry (see swr_wall.h). */
#include "swr_wall.h"

#include <math.h>

#include "swp_contact.h"

void swr_wall_contact_at(const swr_wall *w, const double pos[3], double R, swr_wall_contact *c)
{
    (void)w; /* SWR_WALL_FLAT: plane z = 0 */
    c->delta = R - pos[2];
    c->n[0] = 0.0;
    c->n[1] = 0.0;
    c->n[2] = 1.0;
    c->Rstar = swp_effective_radius(R, INFINITY);
}

double swr_wall_rstar(const swr_wall *w, double R)
{
    (void)w;
    return swp_effective_radius(R, INFINITY);
}
