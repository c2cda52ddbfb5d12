/* swl_model.c - snowlammps: the constants of both codes and the JKR closed
 * forms of doc/kernel.md (the kernel's displacement-controlled break at
 * delta_c, LAMMPS's earlier pull-off); small text helpers. */
#include "swl_lammps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int swl_model_init(swl_model *m, double d, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    swr_params_default(&m->p);
    char e[300];
    if (swr_params_set(&m->p, "wall", "lattice", e, sizeof e) != 0 ||
        swr_params_validate(&m->p, e, sizeof e) != 0) {
        snprintf(err, errlen, "the kernel's default lattice: %s", e);
        return -1;
    }
    const swr_params *p = &m->p;
    if (p->lattice != SWR_LATTICE_SQUARE || p->asperity_jitter != 0.0 || p->asperity_dz != 0.0) {
        snprintf(err, errlen, "the default lattice is no longer a regular square lattice "
                 "(lattice %s, asperity_jitter %g, asperity_dz %g)",
                 p->lattice == SWR_LATTICE_HEX ? "hex" : "square", p->asperity_jitter,
                 p->asperity_dz);
        return -1;
    }
    m->d = d;
    m->R = 0.5 * d;
    m->r = p->asperity_r;
    m->sp = p->asperity_spacing;
    m->rho = p->rho;
    m->mass = m->rho * 4.0 / 3.0 * M_PI * pow(m->R, 3.0);
    const double E1 = p->E, n1 = p->nu, E2 = p->E_wall, n2 = p->nu_wall;
    m->Es = 1.0 / ((1 - n1 * n1) / E1 + (1 - n2 * n2) / E2);
    const double G1 = E1 / (2 * (1 + n1)), G2 = E2 / (2 * (1 + n2));
    m->Gs = 1.0 / ((2 - n1) / G1 + (2 - n2) / G2);
    m->gamma = p->gamma;
    m->mu = p->mu;
    m->xic = p->xi_crit;
    m->hold = p->rough_hold;
    m->accuracy = p->accuracy;
    m->Ra = m->R * m->r / (m->R + m->r);
    return 0;
}

double swl_tc(const swl_model *m, double v, double Rs)
{
    return 2.868 * pow(pow(m->mass, 2.0) / (Rs * pow(m->Es, 2.0) * v), 0.2);
}

void swl_jkr(const swl_model *m, double a, double Rs, double gam, double *delta, double *F)
{
    *delta = a * a / Rs - sqrt(2 * M_PI * gam * a / m->Es);
    *F = 4 * m->Es * pow(a, 3.0) / (3 * Rs) - sqrt(8 * M_PI * gam * m->Es * pow(a, 3.0));
}

double swl_jkr_af(const swl_model *m, double Rs, double gam)
{
    const double a0 = pow(9 * M_PI * gam * Rs * Rs / (2 * m->Es), 1.0 / 3.0);
    return a0 / pow(6.0, 2.0 / 3.0);
}

double swl_jkr_loss(const swl_model *m, double Rs, double gam, double a_off)
{
    const double aj = pow(2 * M_PI * gam * Rs * Rs / m->Es, 1.0 / 3.0);
    const int n = 20000;
    double w = 0.0, d0, f0;
    swl_jkr(m, aj, Rs, gam, &d0, &f0);
    for (int i = 1; i <= n; i++) {
        const double a = aj + (a_off - aj) * i / n;
        double d1, f1;
        swl_jkr(m, a, Rs, gam, &d1, &f1);
        w += 0.5 * (f0 + f1) * (d1 - d0);
        d0 = d1;
        f0 = f1;
    }
    return w; /* > 0: the tensile force over the negative overlap */
}

/* LAMMPS (pair granular jkr, 29 Sep 2021) keeps a contact while the overlap
 * exceeds a^2/R* - 2 sqrt(pi coh a/E), a^3 = 9 pi coh R*^2/(4E), with coh =
 * gam/2; measured: E = E* (the contact breaks at the step that passes this
 * overlap; with E = (4/3) E*, the value in its documentation's force law, it would
 * break at -1.35 nm instead of the measured -1.63 nm for the default asperity). */
double swl_lammps_pulloff(const swl_model *m, double Rs, double gam)
{
    const double coh = 0.5 * gam, E = m->Es;
    const double a = pow(9 * M_PI * coh * Rs * Rs / (4 * E), 1.0 / 3.0);
    return a * a / Rs - 2 * sqrt(M_PI * coh * a / E);
}

double swl_a_at(const swl_model *m, double delta, double Rs, double gam)
{
    double lo = swl_jkr_af(m, Rs, gam), hi = 1e3 * m->r;
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi);
        double dm, fm;
        swl_jkr(m, mid, Rs, gam, &dm, &fm);
        if (dm > delta)
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

/* the fewest significant digits p (1..17) whose %.(p-1)e text reads back as x */
static int shortest_digits(double x, char *buf, size_t n)
{
    int p;
    for (p = 1; p < 17; p++) {
        snprintf(buf, n, "%.*e", p - 1, x);
        if (strtod(buf, NULL) == x)
            return p;
    }
    snprintf(buf, n, "%.*e", 16, x);
    return 17;
}

void swl_repr(double x, char *buf, size_t n)
{
    if (!isfinite(x)) {
        snprintf(buf, n, "%s", isnan(x) ? "nan" : x > 0 ? "inf" : "-inf");
        return;
    }
    if (x == 0.0) {
        snprintf(buf, n, "%s", signbit(x) ? "-0.0" : "0.0");
        return;
    }
    char e[64];
    const int p = shortest_digits(x, e, sizeof e);
    const char *ep = strchr(e, 'e');
    const int ex = ep ? atoi(ep + 1) : 0;
    if (ex >= -4 && ex < 16) {
        const int dec = p - 1 - ex > 0 ? p - 1 - ex : 0;
        snprintf(buf, n, "%.*f%s", dec, x, dec == 0 ? ".0" : "");
    } else {
        snprintf(buf, n, "%s", e);
    }
}

void swl_shortest(double x, char *buf, size_t n)
{
    for (int p = 1; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, x);
        if (!isfinite(x) || strtod(buf, NULL) == x)
            return;
    }
}

double swl_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
