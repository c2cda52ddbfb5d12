/* swr_plastic.h - normal contact sub-model: adhesive elastic-plastic contact
 * after Thornton & Ning (1998), with its loading history.
 *
 * The law (formulas and references in regime/physics/swp_plastic.h, the
 * derivation in doc/kernel.md): elastic JKR loading about R* until the
 * centre pressure reaches p_y; then a linear branch F = F_y + pi p_y R*
 * (delta - delta_y); from the largest overlap delta* on, elastic JKR about a
 * flattened contact (radius R_p >= R*, offset delta_p), which breaks at that
 * curve's displacement-controlled separation. No dashpot: the plastic loss is
 * the area between the loading and the unloading curves.
 *
 * Unit-free like swr_normal.h (the integrator passes scaled constants). The
 * state of the contact is x = sqrt(a) and the branch; the loading energy
 * W(delta) (work done on the contact since the jump-in) is exact, so the
 * turning point of an impact of energy E, W(delta*) = E, is closed form and
 * so is the whole normal outcome (swr_plastic_outcome).
 */
#ifndef SWR_PLASTIC_H
#define SWR_PLASTIC_H

#include "swr_normal.h"

typedef enum { SWR_PL_ELASTIC = 0, SWR_PL_YIELD, SWR_PL_UNLOAD } swr_plastic_branch;

typedef struct {
    swr_normal el;        /* JKR (or Hertz) loading curve about R* */
    swr_normal un;        /* unloading curve about R_p (set by swr_plastic_unload) */
    double py, k;         /* limiting pressure, yield slope pi p_y R* */
    double xy, ay2;       /* sqrt(a_y), a_y^2 on the loading curve (a_y >= a_jump) */
    double dy, Fy, Wy;    /* overlap, force and loading work at yield */
    swr_plastic_branch branch;
    double dstar, Fstar, xstar, Wstar; /* turning point: overlap, force, sqrt(a), work */
    double dp;            /* unloading offset delta_p */
    double Ustar;         /* energy of the unloading curve at x* (its own reference) */
} swr_plastic;

/* Constants from R*, E*, Gamma (0: no adhesion), p_y (> 0); loading branch. */
void swr_plastic_init(swr_plastic *s, double R, double Es, double gamma, double py);

/* Work done on the contact from the jump-in to overlap delta >= 0 along the
 * loading curve (elastic JKR, then the yield branch); sets *x = sqrt(a). */
double swr_plastic_load_work(const swr_plastic *s, double delta, double *x);

/* Largest overlap of an impact that brings energy E (> 0) to the contact
 * (relative to the jump-in): the root of W(delta*) = E, closed form on the
 * yield branch, safeguarded Newton on the elastic curve. */
double swr_plastic_turning(const swr_plastic *s, double E);

/* Start unloading from the turning point at delta*: R_p and delta_p of the
 * curve through (delta*, F*, a*); branch becomes SWR_PL_UNLOAD. */
void swr_plastic_unload(swr_plastic *s, double dstar);

/* Contact force at overlap delta on the current branch; updates *x (warm
 * start on the elastic curves). The caller switches to unloading with
 * swr_plastic_unload at the turning point; on loading branches the yield
 * branch is entered when a reaches a_y. */
double swr_plastic_force(swr_plastic *s, double delta, double *x);

/* Mechanical energy stored or spent so far, at overlap delta / x on the
 * current branch: W(delta) while loading, W* - (U_p(x*) - U_p(x)) while
 * unloading; with the kinetic energy it is conserved (= the impact energy). */
double swr_plastic_energy(const swr_plastic *s, double delta, double x);

/* While unloading: the energy (same reference) at the separation point, and
 * the overlap there (delta_p + the curve's delta_c). A particle with energy
 * above it leaves; at or below it the contact is kept. */
double swr_plastic_separation_energy(const swr_plastic *s);
double swr_plastic_separation_overlap(const swr_plastic *s);

/* The normal curve in use (loading: about R*, unloading: about R_p): its
 * pull-off force, a0 and energy primitive serve the tangential and rolling
 * sub-models. */
static inline const swr_normal *swr_plastic_curve(const swr_plastic *s)
{
    return s->branch == SWR_PL_UNLOAD ? &s->un : &s->el;
}

#endif
