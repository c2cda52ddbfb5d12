/* swr_wall.c - wall geometry (see swr_wall.h). */
#include "swr_wall.h"

#include <math.h>

#include "swp_contact.h"

void swr_wall_init(swr_wall *w, const swr_params *p)
{
    w->type = p->wall == SWR_WALL_KIND_LATTICE ? SWR_WALL_LATTICE : SWR_WALL_FLAT;
    w->hex = p->lattice == SWR_LATTICE_HEX;
    w->r = p->asperity_r;
    w->s = p->asperity_spacing;
    w->row = w->hex ? 0.5 * sqrt(3.0) * w->s : w->s;
    w->jitter = p->asperity_jitter;
    w->dz = p->asperity_dz;
    w->zc = p->asperity_shape == SWR_ASPERITY_SPHERE ? p->asperity_r : 0.0;
    w->seed = (unsigned long long)p->wall_seed;
}

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
    return swp_effective_radius(R, w->type == SWR_WALL_LATTICE ? w->r : INFINITY);
}

/* SplitMix64 finaliser: the wall's random offsets are a hash of (seed, i, j),
 * so any asperity is found without storing the wall. */
static unsigned long long mix(unsigned long long z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* uniform in [0, 1) from the hash */
static double unit(unsigned long long h)
{
    return (double)(h >> 11) * 0x1.0p-53;
}

void swr_wall_asperity(const swr_wall *w, int i, int j, double c[3])
{
    c[0] = (i + (w->hex && (j & 1) ? 0.5 : 0.0)) * w->s;
    c[1] = j * w->row;
    c[2] = w->zc;
    if (w->jitter > 0.0 || w->dz > 0.0) {
        const unsigned long long h =
            mix(w->seed ^ mix((unsigned long long)(unsigned)i << 32 | (unsigned)j));
        c[0] += w->jitter * w->s * (2.0 * unit(h) - 1.0);
        c[1] += w->jitter * w->s * (2.0 * unit(mix(h)) - 1.0);
        c[2] -= w->dz * unit(mix(h ^ 0x5851f42d4c957f2dULL));
    }
}

/* floor / ceil clamped to the int range (the box comes from finite positions) */
static int ifloor(double x)
{
    return x < -2.0e9 ? -2000000000 : (x > 2.0e9 ? 2000000000 : (int)floor(x));
}

static int iceil(double x)
{
    return x < -2.0e9 ? -2000000000 : (x > 2.0e9 ? 2000000000 : (int)ceil(x));
}

void swr_wall_rows(const swr_wall *w, double ylo, double yhi, int *j0, int *j1)
{
    const double j = w->jitter * w->s;
    *j0 = ifloor((ylo - j) / w->row);
    *j1 = iceil((yhi + j) / w->row);
}

void swr_wall_row_range(const swr_wall *w, int j, double xlo, double xhi, int *i0, int *i1)
{
    const double o = w->hex && (j & 1) ? 0.5 * w->s : 0.0, jt = w->jitter * w->s;
    *i0 = ifloor((xlo - o - jt) / w->s);
    *i1 = iceil((xhi - o + jt) / w->s);
}

double swr_wall_top(const swr_wall *w)
{
    return w->type == SWR_WALL_LATTICE ? w->zc + w->r : 0.0;
}

void swr_wall_sample_area(const swr_wall *w, double *lx, double *ly)
{
    if (w->type != SWR_WALL_LATTICE) {
        *lx = *ly = 0.0;
        return;
    }
    const double k = w->jitter > 0.0 || w->dz > 0.0 ? SWR_WALL_RANDOM_CELLS : 1.0;
    *lx = k * w->s;
    *ly = k * w->row;
}
