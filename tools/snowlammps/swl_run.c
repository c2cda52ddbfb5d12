/* swl_run.c - snowlammps: impacts in LAMMPS (lmp, one process per batch, run by
 * posix_spawnp with OMPI_MCA_pml=ob1 as set by main) and in the kernel
 * (libswrkernel, in process). */
#include "swl_lammps.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

/* ------------------------------------------------------------ files */

/* the whole of a (small) text file, NUL-terminated; NULL on failure */
static char *slurp(const char *path, size_t max)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *b = malloc(cap);
    while (b) {
        if (n + 1 >= cap) {
            if (cap >= max) break;
            char *q = realloc(b, 2 * cap);
            if (!q) { free(b); b = NULL; break; }
            b = q;
            cap *= 2;
        }
        size_t k = fread(b + n, 1, cap - 1 - n, f);
        n += k;
        if (k == 0) break;
    }
    fclose(f);
    if (b) b[n] = '\0';
    return b;
}

/* text that LAMMPS would split or substitute: refused in paths given to it */
static int lammps_safe(const char *s)
{
    return strpbrk(s, " \t\n\r\"'$#&") == NULL;
}

/* Run argv with stdout and stderr to `log`; 0 when it exits 0, else -1 with a
 * message naming what, the command, the exit status and the log's tail. */
static int spawn(char *const argv[], const char *log, const char *what, char *err, size_t errlen)
{
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0) {
        snprintf(err, errlen, "%s: out of memory", what);
        return -1;
    }
    posix_spawn_file_actions_addopen(&fa, 1, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    pid_t pid;
    const int e = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (e != 0) {
        snprintf(err, errlen, "%s: cannot run '%s' (%s)", what, argv[0], strerror(e));
        return -1;
    }
    int st = 0;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            snprintf(err, errlen, "%s: waitpid failed (%s)", what, strerror(errno));
            return -1;
        }
    }
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0)
        return 0;
    char cmd[600] = "";
    for (int k = 0; argv[k]; k++) {
        size_t l = strlen(cmd);
        snprintf(cmd + l, sizeof cmd - l, "%s%s", k ? " " : "", argv[k]);
    }
    char *txt = slurp(log, 1 << 24);
    const char *tail = txt ? txt : "";
    size_t tl = strlen(tail);
    if (tl > 2000) tail += tl - 2000;
    if (WIFEXITED(st))
        snprintf(err, errlen, "%s failed (exit %d): %s\n%s", what, WEXITSTATUS(st), cmd, tail);
    else
        snprintf(err, errlen, "%s failed (signal %d): %s\n%s", what,
                 WIFSIGNALED(st) ? WTERMSIG(st) : 0, cmd, tail);
    free(txt);
    return -1;
}

int swl_lammps_version(const swl_lammps *L, char *ver, size_t n, char *err, size_t errlen)
{
    char log[4200];
    snprintf(log, sizeof log, "%s/lmp-h.txt", L->work);
    char *argv[] = { (char *)L->lmp, "-h", NULL };
    int rc = spawn(argv, log, "lmp -h", err, errlen);
    char *txt = rc == 0 ? slurp(log, 1 << 24) : NULL;
    remove(log);
    if (rc != 0)
        return -1;
    snprintf(ver, n, "unknown version");
    for (char *line = txt ? strtok(txt, "\n") : NULL; line; line = strtok(NULL, "\n")) {
        if (!strstr(line, "Simulator - "))
            continue;
        char *v = strstr(line, " - ") + 3;
        while (*v == ' ' || *v == '\t') v++;
        size_t l = strlen(v);
        while (l > 0 && (v[l - 1] == ' ' || v[l - 1] == '\t' || v[l - 1] == '\r')) l--;
        snprintf(ver, n, "%.*s", (int)l, v);
        break;
    }
    free(txt);
    return 0;
}

/* ------------------------------------------------------------ LAMMPS */

typedef struct {
    int jkr, flat;
    double gam, dt;
    char traj[4200], out[4200];
} spec_info;

static void put_num(FILE *f, const char *k, double v)
{
    char b[64];
    swl_shortest(v, b, sizeof b);
    fprintf(f, "variable %s string %s\n", k, b);
}

/* the variables of one impact (impact.lmp's header), written to f */
static void write_spec(swl_lammps *L, const swl_spec *s, spec_info *inf, FILE *f)
{
    const swl_model *m = L->m;
    const int jkr = s->jkr;
    const double gam = jkr ? m->gamma : 0.0;
    double vref = s->vn;
    if (jkr) {
        const double vs = sqrt(2 * swl_jkr_loss(m, m->R, gam, swl_jkr_af(m, m->R, gam)) / m->mass);
        if (vs > vref) vref = vs;
    }
    const double tc = swl_tc(m, vref, m->R); /* stiffest contact: the plane, R* = R */
    const double dt = tc / L->steps * s->dt_factor;
    /* LAMMPS has no energy criterion: a sphere that has not left after `hold`
     * flat-wall contact times counts as stuck; 100 (the kernel's rough_hold is 30,
     * but it decides most sticks earlier by energy): at 30, slow leavers were cut
     * off (measured: one impact left at 3.12 us against a bound of 3.07 us) */
    const double hold = s->hold > 0 ? s->hold : L->hold;
    const double gap = !s->flat ? 0.05 * m->r : 0.05 * m->R; /* start above the first touch */
    const double top = s->flat ? 0.0 : m->r;
    const double tfly = gap / s->vn;
    const double tmax = tfly + hold * tc;
    const double z0 = top + m->R + gap;
    const double x0 = s->x - s->vt * tfly, y0 = s->y;
    const double ztop = top + m->R + 0.02 * (!s->flat ? m->r : m->R);
    /* rolling (adhesive contacts): the kernel's moment k_r xi with k_r = 4 F_c
     * (a/a0)^1.5, xi accumulating at R (w x n), up to xi_crit, matched at a = a0
     * and F_n = 0 by LAMMPS's sds (moment R* k_roll xi_L, xi_L accumulating at
     * R* (w x n), limit R* mu_roll |F_ne + 2 F_pulloff|) */
    double kroll = 0.0, muroll = 0.0, krollp = 0.0, murollp = 0.0;
    if (jkr) {
        double Fc = 1.5 * M_PI * gam * m->Ra;
        kroll = 4 * Fc * m->R / (m->Ra * m->Ra);
        muroll = 2 * m->xic / m->Ra;
        Fc = 1.5 * M_PI * gam * m->R;
        krollp = 4 * Fc * m->R / (m->R * m->R);
        murollp = 2 * m->xic / m->R;
    }
    L->n++;
    snprintf(inf->traj, sizeof inf->traj, "%s/traj%ld.txt", L->work, L->n);
    snprintf(inf->out, sizeof inf->out, "%s/res%ld.txt", L->work, L->n);
    inf->jkr = jkr;
    inf->flat = s->flat;
    inf->gam = gam;
    inf->dt = dt;
    fprintf(f, "clear\n");
    fprintf(f, "variable flat string %d\n", s->flat);
    put_num(f, "R", m->R);
    put_num(f, "r", m->r);
    put_num(f, "s", m->sp);
    put_num(f, "rho", m->rho);
    put_num(f, "EL", 2 * m->Es);
    put_num(f, "kt", 8 * m->Gs);
    put_num(f, "mu", m->mu);
    fprintf(f, "variable damp string %s\n", s->dcoef < 1 ? "tsuji" : "velocity");
    put_num(f, "dcoef", s->dcoef < 1 ? s->dcoef : 0.0);
    put_num(f, "coh", 0.5 * gam);
    put_num(f, "kroll", kroll);
    put_num(f, "muroll", muroll);
    put_num(f, "krollp", krollp);
    put_num(f, "murollp", murollp);
    fprintf(f, "variable pjkr string %d\n", s->pjkr);
    put_num(f, "x0", x0);
    put_num(f, "y0", y0);
    put_num(f, "z0", z0);
    put_num(f, "vx0", s->vt);
    put_num(f, "vz0", -s->vn);
    put_num(f, "dt", dt);
    fprintf(f, "variable nchunk string 50\n");
    put_num(f, "tmax", tmax);
    put_num(f, "ztop", ztop);
    fprintf(f, "variable traj string %s\n", inf->traj);
    fprintf(f, "variable out string %s\n", inf->out);
    fprintf(f, "include %s\n", L->deck);
}

typedef struct { long i, j; } ij;

static int ij_cmp(const void *a, const void *b)
{
    const ij *p = a, *q = b;
    if (p->i != q->i) return p->i < q->i ? -1 : 1;
    return p->j < q->j ? -1 : p->j > q->j;
}

/* Contacts made (counted once per touch, as the kernel's `contacts`), from the
 * centre's path: an asperity or the plane is touched when the overlap reaches 0;
 * the contact lasts while the overlap stays above LAMMPS's pull-off overlap. */
static int count_contacts(const swl_lammps *L, const spec_info *inf, swl_lres *r, char *err,
                          size_t errlen)
{
    const swl_model *m = L->m;
    const double off_a = inf->jkr ? swl_lammps_pulloff(m, m->Ra, inf->gam) : 0.0;
    const double off_p = 0.0; /* the plane is Hertz in every run (fix wall/gran jkr does not separate) */
    FILE *f = fopen(inf->traj, "r");
    if (!f) {
        snprintf(err, errlen, "lmp wrote no trajectory (%s)", inf->traj);
        return -1;
    }
    ij *alive = NULL, *now = NULL;
    size_t na = 0, nn = 0, cap = 0;
    int alive_p = 0;
    long n_asp = 0, n_pl = 0;
    double zmin = INFINITY, dmin_f = INFINITY;
    const double reach = m->R + m->r;
    int have_prev = 0, rc = 0;
    double fprev = 0.0, dprev = 0.0;
    r->nsep = 0;
    char line[1024];
    long ln = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        if (line[0] == '#')
            continue;
        double step, t, x, y, z, fz;
        char extra;
        if (sscanf(line, "%lf %lf %lf %lf %lf %lf %c", &step, &t, &x, &y, &z, &fz, &extra) != 6 ||
            !isfinite(x) || !isfinite(y) || !isfinite(z) || !isfinite(fz) ||
            fabs(x) > 1.0 || fabs(y) > 1.0 || fabs(z) > 1.0) {
            snprintf(err, errlen, "%s:%ld: not a trajectory line 'step t x y z fz' with a finite "
                     "position within 1 m", inf->traj, ln);
            rc = -1;
            break;
        }
        (void)step;
        (void)t;
        if (z - m->R < zmin) zmin = z - m->R;
        const double dpl = m->R - z;
        if (!inf->flat) {
            const double d00 = reach - sqrt(x * x + y * y + z * z); /* the asperity at (0, 0) */
            if (have_prev && fprev != 0.0 && fz == 0.0 && d00 < 0.0) {
                if (r->nsep == 0) {
                    r->sep[0] = dprev;
                    r->sep[1] = d00;
                }
                r->nsep++;
            }
            have_prev = 1;
            fprev = fz;
            dprev = d00;
        }
        if (fz != 0.0 && dpl < 0.0 && dpl < dmin_f)
            dmin_f = dpl;
        const int now_p = dpl >= 0 || (alive_p && dpl > off_p);
        nn = 0;
        if (!inf->flat) {
            const long i0 = (long)floor((x - reach) / m->sp), i1 = (long)ceil((x + reach) / m->sp);
            const long j0 = (long)floor((y - reach) / m->sp), j1 = (long)ceil((y + reach) / m->sp);
            const size_t need = (size_t)(i1 - i0 + 1) * (size_t)(j1 - j0 + 1);
            if (need > cap) {
                ij *a = realloc(alive, need * sizeof *a), *b = a ? realloc(now, need * sizeof *b) : NULL;
                if (a) alive = a;
                if (!a || !b) {
                    snprintf(err, errlen, "out of memory counting contacts");
                    rc = -1;
                    break;
                }
                now = b;
                cap = need;
            }
            for (long i = i0; i <= i1; i++)
                for (long j = j0; j <= j1; j++) {
                    const double dx = x - (double)i * m->sp, dy = y - (double)j * m->sp;
                    const double dl = reach - sqrt(dx * dx + dy * dy + z * z);
                    const ij key = { i, j };
                    const int was = na > 0 && bsearch(&key, alive, na, sizeof *alive, ij_cmp) != NULL;
                    if (dl >= 0 || (was && dl > off_a)) {
                        now[nn++] = key;
                        if (!was) n_asp++;
                    }
                }
        }
        if (now_p && !alive_p) n_pl++;
        alive_p = now_p;
        ij *tmp = alive;
        alive = now;
        now = tmp;
        na = nn;
    }
    if (rc == 0 && ferror(f)) {
        snprintf(err, errlen, "%s: read error", inf->traj);
        rc = -1;
    }
    fclose(f);
    free(alive);
    free(now);
    r->contacts = n_asp + n_pl;
    r->plane_contacts = n_pl;
    r->gap_min = zmin;
    r->dmin_f = dmin_f;
    return rc;
}

static int read_result(const spec_info *inf, swl_lres *r, char *err, size_t errlen)
{
    char *txt = slurp(inf->out, 1 << 16);
    if (!txt) {
        snprintf(err, errlen, "lmp wrote no result (%s)", inf->out);
        return -1;
    }
    char *w[13];
    int nw = 0;
    for (char *q = strtok(txt, " \t\r\n"); q; q = strtok(NULL, " \t\r\n")) {
        if (nw < 13) w[nw] = q;
        nw++;
    }
    double vals[11];
    int ok = nw == 12 && strcmp(w[0], "result") == 0;
    int nan = 0;
    for (int k = 1; ok && k < 12; k++) {
        char *end;
        vals[k - 1] = strtod(w[k], &end);
        if (end == w[k] || *end) ok = 0;
        else if (isnan(vals[k - 1])) nan = 1;
    }
    free(txt);
    if (!ok) {
        snprintf(err, errlen, "lmp wrote no result (%s)", inf->out);
        return -1;
    }
    if (nan || !isfinite(vals[0])) {
        snprintf(err, errlen, "lmp result is NaN (%s)", inf->out);
        return -1;
    }
    r->bounce = (int)vals[0];
    r->t = vals[1];
    for (int q = 0; q < 3; q++) {
        r->x[q] = vals[2 + q];
        r->v[q] = vals[5 + q];
        r->w[q] = vals[8 + q];
    }
    r->dt = inf->dt;
    return 0;
}

int swl_lammps_run(swl_lammps *L, const swl_spec *s, size_t n, swl_lres *res, char *err,
                   size_t errlen)
{
    if (!lammps_safe(L->work) || !lammps_safe(L->deck)) {
        snprintf(err, errlen, "LAMMPS cannot read a path with blanks, quotes, '$', '#' or '&': "
                 "'%s' or '%s'", L->work, L->deck);
        return -1;
    }
    char batch[4200], log[4200];
    snprintf(batch, sizeof batch, "%s/batch%ld.lmp", L->work, L->n + 1);
    snprintf(log, sizeof log, "%s/lmp.log", L->work);
    spec_info *info = calloc(n ? n : 1, sizeof *info);
    FILE *f = info ? fopen(batch, "w") : NULL;
    if (!f) {
        snprintf(err, errlen, "%s: %s", batch, info ? strerror(errno) : "out of memory");
        free(info);
        return -1;
    }
    for (size_t k = 0; k < n; k++)
        write_spec(L, &s[k], &info[k], f);
    int rc = 0;
    if (ferror(f) | (fclose(f) != 0)) {
        snprintf(err, errlen, "%s: write error", batch);
        rc = -1;
    }
    if (rc == 0) {
        char *argv[] = { (char *)L->lmp, "-log", "none", "-screen", "none", "-in", batch, NULL };
        const double t0 = swl_now();
        rc = spawn(argv, log, "lmp", err, errlen);
        L->seconds += swl_now() - t0;
        L->runs += (long)n;
    }
    remove(batch);
    remove(log);
    for (size_t k = 0; k < n; k++) {
        if (rc == 0) rc = read_result(&info[k], &res[k], err, errlen);
        if (rc == 0) rc = count_contacts(L, &info[k], &res[k], err, errlen);
        remove(info[k].traj);
        remove(info[k].out);
    }
    free(info);
    return rc;
}

int swl_lammps_one(swl_lammps *L, const swl_spec *s, swl_lres *res, char *err, size_t errlen)
{
    return swl_lammps_run(L, s, 1, res, err, errlen);
}

/* ------------------------------------------------------------ the kernel */

typedef struct {
    int n;
    double vt, omega;
} last_state;

/* the trace: the kernel steps through the whole contact (as with snowregime
 * collide --trace-csv); the last step's tangential velocity and spin are kept */
static void trace_last(void *ctx, double t, double delta, double vn, double fn, double a,
                       double vt, double omega)
{
    (void)t; (void)delta; (void)vn; (void)fn; (void)a;
    last_state *s = ctx;
    s->n++;
    s->vt = vt;
    s->omega = omega;
}

static swr_model *ours_model(swl_ours *O, int jkr, double cor, int lattice, double acc, char *err,
                             size_t errlen)
{
    for (int k = 0; k < O->ncache; k++)
        if (O->cache[k].jkr == jkr && O->cache[k].lattice == lattice && O->cache[k].cor == cor &&
            O->cache[k].acc == acc)
            return O->cache[k].k;
    swr_params p = O->m->p;
    char e[400], v[64];
    int rc = 0;
    if (!lattice) rc |= swr_params_set(&p, "wall", "flat", e, sizeof e);
    rc |= swr_params_set(&p, "adhesion", jkr ? "jkr" : "none", e, sizeof e);
    if (cor >= 1) {
        rc |= swr_params_set(&p, "cor", "elastic", e, sizeof e);
    } else {
        swl_shortest(cor, v, sizeof v);
        rc |= swr_params_set(&p, "cor", v, e, sizeof e);
        rc |= swr_params_set(&p, "dashpot", "both", e, sizeof e);
    }
    swl_shortest(acc, v, sizeof v);
    rc |= swr_params_set(&p, "accuracy", v, e, sizeof e);
    if (rc != 0) {
        snprintf(err, errlen, "the kernel's settings: %s", e);
        return NULL;
    }
    swr_model *k = swr_model_alloc(&p, e, sizeof e);
    if (!k) {
        snprintf(err, errlen, "the kernel's model: %s", e);
        return NULL;
    }
    if (O->ncache == SWL_NMODELS) { /* full: drop the oldest */
        swr_model_free(O->cache[0].k);
        memmove(&O->cache[0], &O->cache[1], (SWL_NMODELS - 1) * sizeof O->cache[0]);
        O->ncache--;
    }
    O->cache[O->ncache].jkr = jkr;
    O->cache[O->ncache].lattice = lattice;
    O->cache[O->ncache].cor = cor;
    O->cache[O->ncache].acc = acc;
    O->cache[O->ncache].k = k;
    O->ncache++;
    return k;
}

int swl_ours_impact(swl_ours *O, double x, double y, double vn, double vt, int jkr, double cor,
                    int lattice, double accuracy, swl_ores *r, char *err, size_t errlen)
{
    const double t0 = swl_now();
    if (cor <= 0) cor = O->cor;
    if (cor >= 1) cor = 1.0;
    if (accuracy <= 0) accuracy = O->accuracy;
    swr_model *k = ours_model(O, jkr, cor, lattice, accuracy, err, errlen);
    if (!k)
        return -1;
    swr_impact in = { 2 * O->m->R, vn, vt, 0.0, lattice ? x : 0.0, lattice ? y : 0.0 };
    last_state ls = { 0, 0.0, 0.0 };
    swr_trace tr = { 1, trace_last, &ls };
    swr_result res;
    memset(&res, 0, sizeof res);
    const swr_status st = swr_collide(k, &in, &res, &tr);
    O->seconds += swl_now() - t0;
    O->runs++;
    if (st == SWR_EINVAL) {
        snprintf(err, errlen, "the kernel refused the impact (x %g, y %g, vn %g, vt %g): %s", x, y,
                 vn, vt, res.msg);
        return -1;
    }
    memset(r, 0, sizeof *r);
    r->bounce = !res.contact_kept;
    /* v_x: e_t v_t (snowregime collide's e_t), or the last step's when v_t = 0 */
    const double vx = vt > 0 ? (isfinite(res.e_t) ? res.e_t : 0.0) * vt : (ls.n ? ls.vt : 0.0);
    r->v[0] = r->bounce ? vx : 0.0;
    r->v[1] = r->bounce ? res.v_out[1] : 0.0;
    r->v[2] = res.e_n * vn;
    r->wy = ls.n ? -ls.omega : 0.0; /* the trace's spin is the kernel's, -w_y */
    for (int q = 0; q < 3; q++)
        r->w[q] = r->bounce ? res.w_out[q] : 0.0;
    r->contacts = res.contacts;
    r->steps = res.steps;
    r->dt = res.dt;
    r->energy_err = res.energy_err;
    snprintf(r->status, sizeof r->status, "%s", st == SWR_OK ? "ok" : "step-bound");
    return 0;
}

void swl_ours_free(swl_ours *O)
{
    for (int k = 0; k < O->ncache; k++)
        swr_model_free(O->cache[k].k);
    O->ncache = 0;
}
