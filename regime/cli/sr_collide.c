/* sr_collide.c - snowregime collide: one impact, optional trajectory (CSV, VTK). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "sr.h"

typedef struct {
    double t, x, z, delta, vn, fn, a, vt, omega;
} sr_tp;

typedef struct {
    sr_tp *p;
    size_t n, cap;
    double R;
    int oom;
} sr_trace_buf;

static void trace_fn(void *ctx, double t, double delta, double vn, double fn, double a,
                     double vt, double omega)
{
    sr_trace_buf *b = ctx;
    if (b->oom) return;
    if (b->n == b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 1024;
        sr_tp *p = realloc(b->p, cap * sizeof *p);
        if (!p) { b->oom = 1; return; }
        b->p = p; b->cap = cap;
    }
    sr_tp *q = &b->p[b->n];
    /* centre: height R - delta above the wall (z), x integrated from vt (trapezoid) */
    q->x = 0.0;
    if (b->n > 0) {
        const sr_tp *o = &b->p[b->n - 1];
        q->x = o->x + 0.5 * (o->vt + vt) * (t - o->t);
    }
    q->t = t; q->z = b->R - delta; q->delta = delta; q->vn = vn; q->fn = fn;
    q->a = a; q->vt = vt; q->omega = omega;
    b->n++;
}

static void write_csv(FILE *f, const sr_trace_buf *b, const swr_impact *in)
{
    fprintf(f, "# snowregime collide trajectory: d %.9g m, vn %.9g m/s, vt %.9g m/s, omega %.9g rad/s\n",
            in->d, in->vn, in->vt, in->omega);
    fprintf(f, "# vn: normal velocity of the particle (kernel sign), fn: normal force (repulsive > 0)\n");
    fprintf(f, "t_s,x_m,z_m,delta_m,vn_m_s,fn_N,a_m,vt_m_s,omega_rad_s\n");
    for (size_t k = 0; k < b->n; k++) {
        const sr_tp *q = &b->p[k];
        fprintf(f, "%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", q->t, q->x, q->z, q->delta,
                q->vn, q->fn, q->a, q->vt, q->omega);
    }
}

static void vtk_scalar(FILE *f, const sr_trace_buf *b, const char *name, size_t off)
{
    fprintf(f, "SCALARS %s double 1\nLOOKUP_TABLE default\n", name);
    for (size_t k = 0; k < b->n; k++)
        fprintf(f, "%.9e\n", *(const double *)((const char *)&b->p[k] + off));
}

static void write_vtk(FILE *f, const sr_trace_buf *b, const swr_impact *in)
{
    fprintf(f, "# vtk DataFile Version 3.0\n");
    fprintf(f, "snowregime collide d %.6g m vn %.6g m/s vt %.6g m/s: particle centre (wall z=0)\n",
            in->d, in->vn, in->vt);
    fprintf(f, "ASCII\nDATASET POLYDATA\nPOINTS %zu double\n", b->n);
    for (size_t k = 0; k < b->n; k++) fprintf(f, "%.9e 0 %.9e\n", b->p[k].x, b->p[k].z);
    if (b->n > 0) {
        fprintf(f, "LINES 1 %zu\n%zu", b->n + 1, b->n);
        for (size_t k = 0; k < b->n; k++) fprintf(f, " %zu", k);
        fprintf(f, "\n");
    }
    fprintf(f, "POINT_DATA %zu\n", b->n);
    vtk_scalar(f, b, "time", offsetof(sr_tp, t));
    vtk_scalar(f, b, "overlap", offsetof(sr_tp, delta));
    vtk_scalar(f, b, "normal_velocity", offsetof(sr_tp, vn));
    vtk_scalar(f, b, "normal_force", offsetof(sr_tp, fn));
    vtk_scalar(f, b, "contact_radius", offsetof(sr_tp, a));
    vtk_scalar(f, b, "tangential_velocity", offsetof(sr_tp, vt));
    vtk_scalar(f, b, "angular_velocity", offsetof(sr_tp, omega));
}

int sr_cmd_collide(int argc, char **argv)
{
    const char *cmd = "collide";
    sr_args a = { argc, argv, 1, cmd, "", NULL };
    sr_settings s = { 0 };
    swr_impact in = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
    int have_d = 0, have_vn = 0, have_xy = 0, have_stride = 0;
    long stride = 1;
    const char *csv = NULL, *vtk = NULL, *v;
    for (; a.i < argc; a.i++) {
        int r = sr_settings_opt(&a, &s);
        if (r < 0) return sr_usage_error(cmd, a.err);
        if (r > 0) continue;
        if (sr_flag(&a, "--help") || sr_flag(&a, "-h")) { sr_help(cmd); return 0; }
        if (sr_opt(&a, "--d", &v)) {
            if (!v || swt_parse_double("--d", v, SWR_D_MIN, SWR_D_MAX, &in.d, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
            have_d = 1;
        } else if (sr_opt(&a, "--vn", &v)) {
            if (!v || swt_parse_double("--vn", v, 1e-300, SWR_V_MAX, &in.vn, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
            have_vn = 1;
        } else if (sr_opt(&a, "--vt", &v)) {
            if (!v || swt_parse_double("--vt", v, 0.0, SWR_V_MAX, &in.vt, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
        } else if (sr_opt(&a, "--omega", &v)) {
            if (!v || swt_parse_double("--omega", v, -1e12, 1e12, &in.omega, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
        } else if (sr_opt(&a, "--x", &v)) {
            if (!v || swt_parse_double("--x", v, -1.0, 1.0, &in.x, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
            have_xy = 1;
        } else if (sr_opt(&a, "--y", &v)) {
            if (!v || swt_parse_double("--y", v, -1.0, 1.0, &in.y, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
            have_xy = 1;
        } else if (sr_opt(&a, "--stride", &v)) {
            if (!v || swt_parse_int("--stride", v, 1, 1000000000L, &stride, a.err, sizeof a.err))
                return sr_usage_error(cmd, a.err);
            have_stride = 1;
        } else if (sr_opt(&a, "--trace-csv", &v)) {
            if (!v || !*v) return sr_usage_error(cmd, "--trace-csv: missing file name");
            csv = v;
        } else if (sr_opt(&a, "--trace-vtk", &v)) {
            if (!v || !*v) return sr_usage_error(cmd, "--trace-vtk: missing file name");
            vtk = v;
        } else {
            snprintf(a.err, sizeof a.err, "unknown option '%s' (see snowregime collide --help)",
                     argv[a.i]);
            return sr_usage_error(cmd, a.err);
        }
    }
    if (!have_d) return sr_usage_error(cmd, "--d: missing (particle diameter in m)");
    if (!have_vn) return sr_usage_error(cmd, "--vn: missing (normal approach speed in m/s)");
    /* options this run would not use are refused, not dropped */
    if (have_stride && !csv && !vtk)
        return sr_usage_error(cmd, "--stride: only with --trace-csv or --trace-vtk (no trace is written)");
    if (csv && vtk && strcmp(csv, vtk) == 0) {
        snprintf(a.err, sizeof a.err, "--trace-csv and --trace-vtk: the same file '%s' for both traces", csv);
        return sr_usage_error(cmd, a.err);
    }

    swr_params p;
    char err[400];
    if (sr_settings_apply(&s, &p, err, sizeof err) != 0) return sr_usage_error(cmd, err);
    if (have_xy && p.wall != SWR_WALL_KIND_LATTICE)
        return sr_usage_error(cmd, "--x, --y: only for a rough wall (--set wall=lattice); this wall "
                                   "is flat, where every impact point gives the same outcome");
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m) return sr_usage_error(cmd, err);
    /* the trace files: each replaced only when absent or a regular file, in a
     * folder that takes files; checked before the run */
    swo_set *o = NULL;
    int rc = 0;
    if (csv || vtk) {
        o = sr_out_open(cmd, NULL, 0, &rc);
        if (o && csv && swo_check(o, csv, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, o, err);
        if (o && rc == 0 && vtk && swo_check(o, vtk, err, sizeof err) != SWO_OK)
            rc = sr_out_fail(cmd, o, err);
        if (rc) {
            swo_free(o);
            swr_model_free(m);
            return rc;
        }
    }

    sr_trace_buf buf = { NULL, 0, 0, 0.5 * in.d, 0 };
    swr_trace tr = { (int)stride, trace_fn, &buf };
    swr_result r;
    memset(&r, 0, sizeof r);
    swr_status st = swr_collide(m, &in, &r, (csv || vtk) ? &tr : NULL);
    int jkr_ok = 1;
    double tabor = swr_model_tabor(m, in.d, &jkr_ok);
    swr_model_free(m);
    if (st == SWR_EINVAL) {
        /* the kernel names the input (d, vn, vt, omega, x, y): the option is --NAME */
        char msg[200];
        snprintf(msg, sizeof msg, "--%s", r.msg);
        free(buf.p);
        swo_free(o);
        return sr_usage_error(cmd, msg);
    }
    if (o) {
        FILE *f;
        if (buf.oom) rc = sr_fail(cmd, "out of memory for the trajectory");
        if (rc == 0 && csv) {
            if (!(f = swo_open(o, csv, err, sizeof err))) rc = sr_out_fail(cmd, o, err);
            else write_csv(f, &buf, &in);
        }
        if (rc == 0 && vtk) {
            if (!(f = swo_open(o, vtk, err, sizeof err))) rc = sr_out_fail(cmd, o, err);
            else write_vtk(f, &buf, &in);
        }
        if (rc == 0 && swo_commit(o, err, sizeof err) != SWO_OK) rc = sr_out_fail(cmd, o, err);
        swo_free(o);
    }
    free(buf.p);
    if (rc) return rc;

    const char *outcome = r.stick ? "stick" : r.contact_kept ? "contact-kept-sliding" : "bounce";
    printf("outcome: %s\n", outcome);
    printf("d: %.9g\nvn: %.9g\nvt: %.9g\nomega: %.9g\n", in.d, in.vn, in.vt, in.omega);
    printf("contact_kept: %d\nstick: %d\n", r.contact_kept, r.stick);
    printf("e_n: %.9g\n", r.e_n);
    if (isfinite(r.e_t)) printf("e_t: %.9g\n", r.e_t);
    else printf("e_t: none (no tangential rebound: vt = 0 or contact kept)\n");
    printf("t_contact: %.9g\ndelta_max: %.9g\ne_target: %.9g\n", r.t_contact, r.delta_max, r.e_target);
    printf("t_rest: %.9g\ns_rest: %.9g\n", r.t_rest, r.s_rest);
    if (p.wall == SWR_WALL_KIND_LATTICE) {
        printf("x: %.9g\ny: %.9g\ncontacts: %ld\n", in.x, in.y, r.contacts);
        printf("v_out: %.9g %.9g %.9g\nw_out: %.9g %.9g %.9g\n", r.v_out[0], r.v_out[1], r.v_out[2],
               r.w_out[0], r.w_out[1], r.w_out[2]);
    }
    printf("dt: %.9g\nsteps: %ld\nmax_steps: %ld\n", r.dt, r.steps, r.max_steps);
    printf("status: %s\n", st == SWR_OK ? "ok (decided by a physical criterion)"
                                        : "step-bound (outcome is the best estimate)");
    printf("energy_err: %.3g\n", r.energy_err);
    printf("tabor: %.4g%s\n", tabor, jkr_ok ? "" : " (outside the JKR range > 5: DMT/Maugis regime)");
    if (r.msg[0]) printf("warning: %s\n", r.msg);
    if (!jkr_ok) fprintf(stderr, "snowregime collide: warning: Tabor parameter %.3g < 5 at d = %g m: "
                         "JKR is outside its range\n", tabor, in.d);
    if (csv) printf("trace_csv: %s\n", csv);
    if (vtk) printf("trace_vtk: %s\n", vtk);
    return 0;
}
