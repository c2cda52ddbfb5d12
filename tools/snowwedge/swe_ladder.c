/* swe_ladder.c - a run's rung of the resolution ladder, the change between
 * two resolutions, the numbers of the error plots (swe_ladder.h). */
#include "swe_ladder.h"

#include "swe_spray.h"
#include "swe_stats.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

double swe_ladder_st_error(double w0, double w1)
{
    return SWE_LADDER_H_M / SWE_LADDER_U_MS / ((w1 - w0) * sqrt(12));
}

double swe_ladder_cp_scale(void)
{
    return 1 / (0.5 * pow(SWE_LADDER_U_MS, 2));
}

int swe_ladder_key(const char *text, const char *key, char *out, size_t outlen)
{
    const size_t kl = strlen(key);
    for (const char *s = text; *s;) {
        const char *eol = strchr(s, '\n');
        const size_t len = eol ? (size_t)(eol - s) : strlen(s);
        const char *p = s;
        while (p < s + len && isblank((unsigned char)*p))
            p++;
        if ((size_t)(s + len - p) >= kl && !strncmp(p, key, kl) &&
            (p + kl == s + len || isblank((unsigned char)p[kl]))) {
            /* the fields after the key joined by one blank */
            size_t o = 0;
            for (p += kl; p < s + len;) {
                while (p < s + len && isblank((unsigned char)*p))
                    p++;
                if (p == s + len)
                    break;
                if (o && o + 1 < outlen)
                    out[o++] = ' ';
                while (p < s + len && !isblank((unsigned char)*p)) {
                    if (o + 1 < outlen)
                        out[o++] = *p;
                    p++;
                }
            }
            if (outlen)
                out[o] = 0;
            return 0;
        }
        s += len + (eol != NULL);
    }
    return SWE_EINVAL;
}

void swe_ladder_field(const char *line, char sep, int k, char *out, size_t outlen)
{
    const char *s = line;
    for (int i = 0; i < k && s; i++) {
        s = strchr(s, sep);
        if (s)
            s++;
    }
    if (!outlen)
        return;
    out[0] = 0;
    if (!s)
        return;
    const char *e = strchr(s, sep);
    const size_t len = e ? (size_t)(e - s) : strlen(s);
    snprintf(out, outlen, "%.*s", (int)len, s);
}

static int whole(const char *s, int sign)
{
    if (sign && *s == '-')
        s++;
    if (!*s)
        return 0;
    for (; *s; s++)
        if (!isdigit((unsigned char)*s))
            return 0;
    return 1;
}

int swe_ladder_row_ok(const char *line)
{
    int nf = 1;
    for (const char *s = line; *s; s++)
        nf += (*s == ',');
    if (nf != 10)
        return 0;
    char level[128], cells[128];
    swe_ladder_field(line, ',', 3, level, sizeof level);
    swe_ladder_field(line, ',', 4, cells, sizeof cells);
    return whole(level, 1) && whole(cells, 0);
}

void swe_ladder_change(double b, double sb, double r, double sr, swe_change *out)
{
    *out = (swe_change){SWE_CHANGE_NONE, 0, 0, 0, 0};
    if (b <= 0 && r <= 0)
        return;
    const double s = sqrt(sb * sb + sr * sr);
    out->kind = SWE_CHANGE_ONE;
    if (b <= 0 || s <= 0)
        return;
    out->z = swe_ztest(b, sb * sb, r, sr * sr, NULL);
    out->change = r / b - 1;
    out->se_change = (r / b) * sqrt(pow(sb / b, 2) + ((r > 0) ? pow(sr / r, 2) : 0));
    out->kind = (out->z > 2 || out->z < -2) ? SWE_CHANGE_DIFFERS : SWE_CHANGE_AGREES;
    out->bound = fabs(out->change) + 2 * out->se_change;
}

void swe_ladder_awknum(double v, char *out, size_t outlen)
{
    if (isfinite(v) && v == floor(v) && fabs(v) < 1e15)
        snprintf(out, outlen, "%.0f", v);
    else
        snprintf(out, outlen, "%.6g", v);
}

int swe_ladder_plot_range(const double *x, const double *y, size_t n, const double *targets,
                          size_t nt, double range[4], char *err, size_t errlen)
{
    if (n == 0) {
        if (err && errlen)
            snprintf(err, errlen, "no point to plot");
        return SWE_EINVAL;
    }
    double a = x[0], b = x[0], c = y[0], d = y[0];
    for (size_t i = 1; i < n; i++) {
        a = fmin(a, x[i]);
        b = fmax(b, x[i]);
        c = fmin(c, y[i]);
        d = fmax(d, y[i]);
    }
    for (size_t i = 0; i < nt; i++) {
        c = fmin(c, targets[i]);
        d = fmax(d, targets[i]);
    }
    if (a <= 0)
        a = 1e-3;
    if (c <= 0)
        c = 1e-3;
    range[0] = a / 2;
    range[1] = b * 2;
    range[2] = c / 1.5;
    range[3] = d * 1.5;
    return 0;
}
