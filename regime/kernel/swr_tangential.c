/* swr_tangential.c - arrest of sliding and rolling (see swr_tangential.h). */
#include "swr_tangential.h"

static double sgn(double v)
{
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

int swr_tangential_rest(double m, double R, double I, double fs, double ml, double vt,
                        double omega, double *t_rest, double *s_rest)
{
    double t = 0.0, s = 0.0;
    /* velocities below this fraction of the initial scale count as zero */
    const double v0 = fabs(vt) + fabs(R * omega);
    const double tol = 1e-12 * v0;
    for (int phase = 0; phase < 8; phase++) {
        const double vc = vt + R * omega, vr = -R * omega;
        const int slide = fabs(vc) > tol, roll = fabs(vr) > tol;
        if (!slide && !roll) {
            *t_rest = t;
            *s_rest = s;
            return 1;
        }
        double ft, mr;
        if (slide) {
            ft = -fs * sgn(vc);
            if (roll) {
                mr = ml * sgn(vr);
            } else { /* rolling held while the moment needed stays below ml */
                mr = -R * ft;
                if (fabs(mr) > ml)
                    mr = ml * sgn(mr);
            }
        } else { /* pure rolling: friction keeps v_c = 0 */
            mr = ml * sgn(vr);
            ft = -R * mr * m / (I + m * R * R);
            if (fabs(ft) > fs)
                ft = fs * sgn(ft);
        }
        const double at = ft / m, aw = (R * ft + mr) / I;
        const double dvc = at + R * aw, dvr = -R * aw;
        double tau = INFINITY;
        if (slide && vc * dvc < 0.0)
            tau = -vc / dvc;
        if (roll && vr * dvr < 0.0 && -vr / dvr < tau)
            tau = -vr / dvr;
        if (!(tau < INFINITY)) {
            *t_rest = *s_rest = INFINITY;
            return 0;
        }
        s += vt * tau + 0.5 * at * tau * tau;
        t += tau;
        vt += at * tau;
        omega += aw * tau;
        /* land exactly on the event that ended the phase */
        if (slide && fabs(vt + R * omega) <= 1e-9 * v0)
            vt = -R * omega;
        if (roll && fabs(R * omega) <= 1e-9 * v0) {
            omega = 0.0;
        }
    }
    *t_rest = t;
    *s_rest = s;
    return 1;
}
