#!/usr/bin/env python3
"""rough_compare.py - the rough-wall impacts of snowregime's 3-D multi-contact
integrator (regime/kernel/swr_rough.c) run again in LAMMPS (issue 24, item 1).

Called by validation/lammps-rough.sh, which checks the options; this script
writes its outputs into the folder given by --out (a temporary folder of the
driver) and exits 0, or 1 with a message when a run fails, or 3 with --check
when an impact is outside the tolerances.

The wall: the default lattice of snowregime (square, hemispherical asperities
of radius r at spacing s on the plane z = 0), in LAMMPS fixed (frozen) spheres
of radius r centred on z = 0 plus the base plane as fix wall/gran. The
material constants are read from snowregime's own settings printout
(snowregime vcrit prints every key), so both codes use the same numbers.
"""
import argparse
import math
import os
import subprocess
import sys
import time

os.environ.setdefault("OMPI_MCA_pml", "ob1")   # single process: skip UCX probing (halves start-up)
HERE = os.path.dirname(os.path.abspath(__file__))
LMP_IN = os.path.join(HERE, "impact.lmp")


class Fail(Exception):
    pass


def run(cmd, what):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise Fail("%s failed (exit %d): %s\n%s" % (what, p.returncode, " ".join(cmd),
                                                   (p.stderr or p.stdout)[-2000:]))
    return p.stdout


# ---------------------------------------------------------------- settings

def read_settings(sr, d):
    """Every setting of snowregime for the default lattice, from its printout."""
    out = run([sr, "vcrit", "--d", repr(d), "--set", "wall=lattice", "--points", "1",
               "--level", "0.5", "--vmin", "1e-3", "--vmax", "50", "--tol", "0.5"],
              "snowregime vcrit (settings printout)")
    s = {}
    for line in out.splitlines():
        if line.startswith("# setting "):
            k, v = line[len("# setting "):].split(None, 1)
            s[k] = v.strip()
    need = ["rho", "E", "nu", "E_wall", "nu_wall", "gamma", "mu", "xi_crit", "lattice",
            "asperity_r", "asperity_spacing", "asperity_jitter", "asperity_dz", "rough_hold",
            "accuracy"]
    miss = [k for k in need if k not in s]
    if miss:
        raise Fail("snowregime's settings printout lacks %s" % ", ".join(miss))
    if s["lattice"] != "square" or float(s["asperity_jitter"]) != 0 or float(s["asperity_dz"]) != 0:
        raise Fail("the default lattice is no longer a regular square lattice: %s" % s)
    return s


class Model:
    """Constants of both codes."""

    def __init__(self, s, d):
        f = lambda k: float(s[k])
        self.s = s
        self.R = 0.5 * d
        self.r = f("asperity_r")
        self.sp = f("asperity_spacing")
        self.rho = f("rho")
        self.mass = self.rho * 4.0 / 3.0 * math.pi * self.R ** 3
        E1, n1, E2, n2 = f("E"), f("nu"), f("E_wall"), f("nu_wall")
        self.Es = 1.0 / ((1 - n1 * n1) / E1 + (1 - n2 * n2) / E2)
        G1, G2 = E1 / (2 * (1 + n1)), E2 / (2 * (1 + n2))
        self.Gs = 1.0 / ((2 - n1) / G1 + (2 - n2) / G2)
        self.gamma = f("gamma")
        self.mu = f("mu")
        self.xic = f("xi_crit")
        self.hold = f("rough_hold")
        self.accuracy = f("accuracy")
        self.Ra = self.R * self.r / (self.R + self.r)   # R* of an asperity contact

    def tc(self, v, Rs=None):
        """Hertz contact time of the particle on a contact of R* (default R) at v."""
        Rs = self.R if Rs is None else Rs
        return 2.868 * (self.mass ** 2 / (Rs * self.Es ** 2 * v)) ** 0.2

    # JKR curve in the contact radius a (the kernel's law, doc/kernel.md)
    def jkr(self, a, Rs, gam):
        d = a * a / Rs - math.sqrt(2 * math.pi * gam * a / self.Es)
        F = 4 * self.Es * a ** 3 / (3 * Rs) - math.sqrt(8 * math.pi * gam * self.Es * a ** 3)
        return d, F

    def jkr_loss(self, Rs, gam, a_off):
        """Work lost from the jump-in (delta = 0) to a break at contact radius a_off."""
        aj = (2 * math.pi * gam * Rs * Rs / self.Es) ** (1 / 3)
        n = 20000
        w = 0.0
        d0, f0 = self.jkr(aj, Rs, gam)
        for i in range(1, n + 1):
            a = aj + (a_off - aj) * i / n
            d1, f1 = self.jkr(a, Rs, gam)
            w += 0.5 * (f0 + f1) * (d1 - d0)
            d0, f0 = d1, f1
        return w   # > 0: the tensile force over the negative overlap

    def jkr_af(self, Rs, gam):
        a0 = (9 * math.pi * gam * Rs * Rs / (2 * self.Es)) ** (1 / 3)
        return a0 / 6 ** (2 / 3)

    def lammps_pulloff(self, Rs, gam):
        """LAMMPS (pair granular jkr, 29 Sep 2021) keeps a contact while the
        overlap exceeds a^2/R* - 2 sqrt(pi coh a/E), a^3 = 9 pi coh R*^2/(4E), with
        coh = gam/2; measured: E = E* (the contact breaks at the step that passes this
        overlap; with E = 4E*/3, the value in its documentation's force law, it would
        break at -1.35 nm instead of the measured -1.63 nm for the default asperity)."""
        coh, E = 0.5 * gam, self.Es
        a = (9 * math.pi * coh * Rs * Rs / (4 * E)) ** (1 / 3)
        return a * a / Rs - 2 * math.sqrt(math.pi * coh * a / E)

    def a_at(self, delta, Rs, gam):
        """Contact radius on the stable branch (a >= a_f) at overlap delta."""
        lo, hi = self.jkr_af(Rs, gam), 1e3 * self.r
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if self.jkr(mid, Rs, gam)[0] > delta:
                hi = mid
            else:
                lo = mid
        return lo


# ---------------------------------------------------------------- LAMMPS

class Lammps:
    def __init__(self, lmp, m, work, steps, hold=100.0):
        self.lmp, self.m, self.work, self.steps, self.hold = lmp, m, work, steps, hold
        self.n = 0
        self.seconds = 0.0
        self.runs = 0

    def impact(self, x, y, vn, vt, case, dcoef, flat=0, hold=None, dt_factor=1.0, pjkr=0):
        """One impact. case: 'hertz' or 'jkr'. Returns a dict."""
        return self.impacts([(x, y, vn, vt, case, dcoef, flat, hold, dt_factor, pjkr)])[0]

    def spec(self, x, y, vn, vt, case, dcoef, flat=0, hold=None, dt_factor=1.0, pjkr=0):
        m = self.m
        jkr = case.startswith("jkr")
        gam = m.gamma if jkr else 0.0
        vref = max(vn, math.sqrt(2 * m.jkr_loss(m.R, gam, m.jkr_af(m.R, gam)) / m.mass) if jkr else 0.0)
        tc = m.tc(vref)                                    # stiffest contact: the plane, R* = R
        dt = tc / self.steps * dt_factor
        # LAMMPS has no energy criterion: a sphere that has not left after `hold` flat-wall
        # contact times counts as stuck; 100 (the kernel's rough_hold is 30, but it decides
        # most sticks earlier by energy): at 30, slow leavers were cut off (measured: one
        # impact left at 3.12 us against a bound of 3.07 us)
        hold = self.hold if hold is None else hold
        gap = 0.05 * m.r if not flat else 0.05 * m.R       # start this far above the first touch
        top = 0.0 if flat else m.r
        tfly = gap / vn
        tmax = tfly + hold * tc
        z0 = top + m.R + gap
        x0, y0 = x - vt * tfly, y
        ztop = top + m.R + 0.02 * (m.r if not flat else m.R)

        # rolling (adhesive contacts): the kernel's moment k_r xi with k_r = 4 F_c (a/a0)^1.5,
        # xi accumulating at R (w x n), up to xi_crit, matched at a = a0 and F_n = 0 by
        # LAMMPS's sds (moment R* k_roll xi_L, xi_L accumulating at R* (w x n), limit
        # R* mu_roll |F_ne + 2 F_pulloff|)
        def roll(Rs):
            if not jkr:
                return 0.0, 0.0
            Fc = 1.5 * math.pi * gam * Rs
            return 4 * Fc * m.R / (Rs * Rs), 2 * m.xic / Rs
        kroll, muroll = roll(m.Ra)
        krollp, murollp = roll(m.R)
        self.n += 1
        traj = os.path.join(self.work, "traj%d.txt" % self.n)
        out = os.path.join(self.work, "res%d.txt" % self.n)
        var = dict(flat=flat, R=m.R, r=m.r, s=m.sp, rho=m.rho, EL=2 * m.Es, kt=8 * m.Gs, mu=m.mu,
                   damp="tsuji" if dcoef < 1 else "velocity", dcoef=dcoef if dcoef < 1 else 0,
                   coh=0.5 * gam, kroll=kroll, muroll=muroll, krollp=krollp, murollp=murollp,
                   pjkr=pjkr, x0=x0, y0=y0, z0=z0, vx0=vt, vz0=-vn, dt=dt, nchunk=50, tmax=tmax,
                   ztop=ztop, traj=traj, out=out)
        return var, dict(jkr=jkr, flat=flat, gam=gam, dt=dt, traj=traj, out=out)

    def impacts(self, specs):
        """Several impacts in one LAMMPS process (its start-up costs 0.2-0.4 s):
        each after `clear`, its values as string variables."""
        batch = os.path.join(self.work, "batch%d.lmp" % (self.n + 1))
        info = []
        with open(batch, "w") as f:
            for sp in specs:
                var, inf = self.spec(*sp)
                info.append(inf)
                f.write("clear\n")
                for k, v in var.items():
                    f.write("variable %s string %s\n" % (k, repr(v) if isinstance(v, float) else str(v)))
                f.write("include %s\n" % LMP_IN)
        cmd = [self.lmp, "-log", "none", "-screen", "none", "-in", batch]
        t0 = time.time()
        run(cmd, "lmp")
        self.seconds += time.time() - t0
        self.runs += len(specs)
        os.remove(batch)
        res = []
        for inf in info:
            with open(inf["out"]) as f:
                w = f.read().split()
            if len(w) != 12 or w[0] != "result":
                raise Fail("lmp wrote no result (%s)" % inf["out"])
            vals = [float(q) for q in w[1:]]
            if any(math.isnan(q) for q in vals):
                raise Fail("lmp result is NaN (%s)" % inf["out"])
            r = dict(bounce=int(vals[0]), t=vals[1], x=vals[2:5], v=vals[5:8], w=vals[8:11], dt=inf["dt"])
            r.update(self.contacts(inf["traj"], inf["jkr"], inf["flat"], inf["gam"]))
            os.remove(inf["traj"])
            os.remove(inf["out"])
            res.append(r)
        return res

    def contacts(self, traj, jkr, flat, gam):
        """Contacts made (counted once per touch, as the kernel's `contacts`), from the
        centre's path: an asperity or the plane is touched when the overlap reaches 0;
        the contact lasts while the overlap stays above LAMMPS's pull-off overlap."""
        m = self.m
        off_a = m.lammps_pulloff(m.Ra, gam) if jkr else 0.0
        off_p = 0.0     # the plane is Hertz in every run (fix wall/gran jkr does not separate)
        alive = {}
        n_asp = n_pl = 0
        zmin = math.inf
        reach = m.R + m.r
        dmin_f = math.inf   # the most negative plane overlap at which a force acts
        sep = []            # asperity overlap at the last step with a force, and at the first without
        fprev = dprev = None
        with open(traj) as f:
            for line in f:
                if line.startswith("#"):
                    continue
                p = line.split()
                x, y, z = float(p[2]), float(p[3]), float(p[4])
                zmin = min(zmin, z - m.R)
                now = set()
                dpl = m.R - z
                fz = float(p[5])
                if not flat:
                    d00 = reach - math.sqrt(x * x + y * y + z * z)    # the asperity at (0, 0)
                    if fprev is not None and fprev != 0.0 and fz == 0.0 and d00 < 0.0:
                        sep.append((dprev, d00))
                    fprev, dprev = fz, d00
                if fz != 0.0 and dpl < 0.0:
                    dmin_f = min(dmin_f, dpl)
                if dpl >= 0 or (("P" in alive) and dpl > off_p):
                    now.add("P")
                if not flat:
                    i0, i1 = math.floor((x - reach) / m.sp), math.ceil((x + reach) / m.sp)
                    j0, j1 = math.floor((y - reach) / m.sp), math.ceil((y + reach) / m.sp)
                    for i in range(i0, i1 + 1):
                        for j in range(j0, j1 + 1):
                            dx, dy = x - i * m.sp, y - j * m.sp
                            dl = reach - math.sqrt(dx * dx + dy * dy + z * z)
                            if dl >= 0 or ((i, j) in alive and dl > off_a):
                                now.add((i, j))
                for k in now:
                    if k not in alive:
                        if k == "P":
                            n_pl += 1
                        else:
                            n_asp += 1
                alive = {k: 1 for k in now}
        return dict(contacts=n_asp + n_pl, plane_contacts=n_pl, gap_min=zmin, sep=sep, dmin_f=dmin_f)


# ---------------------------------------------------------------- snowregime

class Ours:
    def __init__(self, sr, m, work, cor, accuracy):
        self.sr, self.m, self.work, self.cor, self.accuracy = sr, m, work, cor, accuracy
        self.seconds = 0.0
        self.runs = 0

    def sets(self, case, cor=None, lattice=True, accuracy=None):
        cor = self.cor if cor is None else cor
        s = []
        if lattice:
            s += ["--set", "wall=lattice"]
        s += ["--set", "adhesion=" + ("jkr" if case.startswith("jkr") else "none")]
        if cor >= 1:
            s += ["--set", "cor=elastic"]
        else:
            s += ["--set", "cor=%r" % cor, "--set", "dashpot=both"]
        s += ["--set", "accuracy=%r" % (accuracy or self.accuracy)]
        return s

    def impact(self, x, y, vn, vt, case, cor=None, lattice=True, accuracy=None):
        m = self.m
        tr = os.path.join(self.work, "ours.csv")
        cmd = [self.sr, "collide", "--d", repr(2 * m.R), "--vn", repr(vn), "--vt", repr(vt),
               "--trace-csv", tr] + self.sets(case, cor, lattice, accuracy)
        if lattice:
            cmd += ["--x", repr(x), "--y", repr(y)]
        t0 = time.time()
        out = run(cmd, "snowregime collide")
        self.seconds += time.time() - t0
        self.runs += 1
        kv = {}
        for line in out.splitlines():
            if ":" in line:
                k, v = line.split(":", 1)
                kv[k.strip()] = v.strip()
        last = None
        with open(tr) as f:
            for line in f:
                if line[:1].isdigit() or line[:1] == "-":
                    last = line
        os.remove(tr)
        bounce = kv.get("outcome") == "bounce"
        en = float(kv["e_n"])
        et = float(kv["e_t"]) if vt > 0 and bounce else 0.0
        p = last.split(",") if last else None
        # trace: vt_m_s = v_x, omega_rad_s = the kernel's spin, -w_y
        vx = et * vt if vt > 0 else (float(p[7]) if p else 0.0)
        wy = -float(p[8]) if p else 0.0
        return dict(bounce=1 if bounce else 0, v=[vx if bounce else 0.0, None, en * vn], wy=wy,
                    contacts=int(kv.get("contacts", "1")), status=kv.get("status", ""),
                    steps=int(kv.get("steps", "0")), dt=float(kv.get("dt", "0")),
                    energy_err=float(kv.get("energy_err", "0")))


# ---------------------------------------------------------------- calibration

def calibrate(L, O, m, e, speeds, log):
    """LAMMPS's tsuji input restitution coefficient that gives the COR e on the
    flat base plane (its polynomial alpha(e) does not give e for this dashpot:
    measured), by bisection; then the single-asperity COR of both codes."""
    v = speeds[0]

    def cor(eL, flat=1, v=v):
        r = L.impact(0.0, 0.0, v, 0.0, "hertz", eL, flat=flat)
        return r["v"][2] / v

    # secant on the input (the measured COR is smooth and monotonic in it)
    x0, x1 = e, e - 0.1
    f0, f1 = cor(x0) - e, cor(x1) - e
    for _ in range(20):
        if abs(f1) < 1e-5 or f1 == f0:
            break
        x0, x1, f0 = x1, min(0.999, max(0.05, x1 - f1 * (x1 - x0) / (f1 - f0))), f1
        f1 = cor(x1) - e
    if abs(f1) > 1e-4:
        raise Fail("LAMMPS's COR could not be calibrated to %g (input %g gives %g)" % (e, x1, f1 + e))
    eL = x1
    log.append("| LAMMPS tsuji input e = %.3g (its polynomial alpha(e)) gives, flat base plane, %.3g m/s | COR %.5f |"
               % (e, v, cor(e)))
    log.append("| LAMMPS tsuji input e for COR %.3g (flat base plane, %.3g m/s; secant) | %.6f |" % (e, v, eL))
    for vv in speeds:
        log.append("| COR on the flat base plane at %.3g m/s: LAMMPS (fix wall/gran) | %.5f |" % (vv, cor(eL, 1, vv)))
        log.append("| COR on the flat base plane at %.3g m/s: snowregime (flat wall) | %.5f |"
                   % (vv, O.impact(0, 0, vv, 0, "hertz", lattice=False)["v"][2] / vv))
        log.append("| COR head-on on one asperity (x = y = 0) at %.3g m/s: LAMMPS (pair granular) | %.5f |"
                   % (vv, cor(eL, 0, vv)))
        log.append("| COR head-on on one asperity (x = y = 0) at %.3g m/s: snowregime | %.5f |"
                   % (vv, O.impact(0, 0, vv, 0, "hertz")["v"][2] / vv))
    return eL


def jkr_single(L, O, m, eL, log):
    """Adhesion on a single contact, head-on on one asperity (the pair style; fix
    wall/gran jkr of this LAMMPS does not separate, see doc/kernel.md): the
    separation overlap and the sticking velocity of both codes against closed forms."""
    g = m.gamma
    Rs = m.Ra
    af = m.jkr_af(Rs, g)
    dc = m.jkr(af, Rs, g)[0]
    dL = m.lammps_pulloff(Rs, g)
    Uc = m.jkr_loss(Rs, g, af)
    UL = m.jkr_loss(Rs, g, m.a_at(dL, Rs, g))
    vs_c = math.sqrt(2 * Uc / m.mass)
    vs_L = math.sqrt(2 * UL / m.mass)
    log.append("| asperity contact R* [m] | %.4g |" % Rs)
    log.append("| separation overlap: the kernel's delta_c = -3 a_f^2/R* [m] | %.4g |" % dc)
    log.append("| separation overlap: LAMMPS's criterion (pair granular jkr, with E = E*) [m] | %.4g |" % dL)
    for st in (1.0, 0.25):
        r = L.impact(0, 0, 0.3, 0, "jkr", 1.0, dt_factor=st)
        if r["sep"]:
            log.append("| separation overlap: LAMMPS measured (elastic, 0.3 m/s, dt x %g): last step with a force / first without [m] | %.4g / %.4g |"
                       % (st, r["sep"][0][0], r["sep"][0][1]))
    # the base plane with JKR (fix wall/gran jkr), elastic, head-on: does it separate?
    dcp = m.jkr(m.jkr_af(m.R, g), m.R, g)[0]
    for v in (0.35, 0.5):
        try:
            r = L.impact(0, 0, v, 0, "jkr", 1.0, flat=1, pjkr=1)
            what = ("left, v_z %.4g m/s" % r["v"][2]) if r["bounce"] else (
                "still attached after %.3g s, down to overlap %.4g m (the kernel's delta_c: %.4g m)"
                % (r["t"], r["dmin_f"], dcp))
        except Fail:
            what = "NaN (LAMMPS's result)"
        log.append("| flat base plane with fix wall/gran jkr, elastic, head-on %.3g m/s (flat V_s %.4g m/s) | %s |"
                   % (v, math.sqrt(2 * m.jkr_loss(m.R, g, m.jkr_af(m.R, g)) / m.mass), what))
    log.append("| energy lost at separation (closed form): kernel U_c / LAMMPS [J] | %.4g / %.4g (ratio %.3f) |" % (Uc, UL, UL / Uc))
    out = {}
    for name, cor, eLx in (("elastic", 1.0, 1.0), ("COR %.3g" % O.cor, None, eL)):
        def ours_st(v):
            return O.impact(0, 0, v, 0, "jkr", cor=cor)["bounce"] == 0

        def lmp_st(v):
            return L.impact(0, 0, v, 0, "jkr", eLx)["bounce"] == 0

        vals = []
        for f in (ours_st, lmp_st):
            lo, hi = 1e-3, 5.0
            for _ in range(40):
                mid = math.sqrt(lo * hi)
                if f(mid):
                    lo = mid
                else:
                    hi = mid
                if hi / lo < 1.002:
                    break
            vals.append(math.sqrt(lo * hi))
        out[name] = vals
        extra = (" (closed form sqrt(2 U/m): kernel %.4g, LAMMPS %.4g)" % (vs_c, vs_L)) if cor == 1.0 else ""
        log.append("| sticking velocity on one asperity, %s: snowregime / LAMMPS [m/s] | %.4g / %.4g%s |"
                   % (name, vals[0], vals[1], extra))
    return dict(Uc=Uc, UL=UL, vs=out)


# ---------------------------------------------------------------- comparison

def grid(k, sp):
    return [(i * sp / k, j * sp / k) for i in range(k) for j in range(k)]


def compare(L, O, m, case, eL, pts, angles, speeds, halve):
    """Every impact of one case in both codes (and at half the step in both)."""
    rows = []
    specs = []
    cor = 1.0 if case.endswith("elastic") else None
    eL = 1.0 if case.endswith("elastic") else eL
    for V in speeds:
        for th in angles:
            vn = V * math.cos(math.radians(th))
            vt = V * math.sin(math.radians(th))
            if vt < 1e-12 * V:
                vt = 0.0
            for (x, y) in pts:
                o = O.impact(x, y, vn, vt, case, cor=cor)
                row = dict(case=case, V=V, th=th, x=x, y=y, vn=vn, vt=vt, o=o)
                specs.append((x, y, vn, vt, case, eL))
                if halve:
                    row["o2"] = O.impact(x, y, vn, vt, case, cor=cor, accuracy=2 * O.accuracy)
                    specs.append((x, y, vn, vt, case, eL, 0, None, 0.5))
                rows.append(row)
    res = L.impacts(specs)
    k = 0
    for row in rows:
        row["l"] = res[k]
        k += 1
        if halve:
            row["l2"] = res[k]
            k += 1
    return rows


def wy(d):
    return d["wy"] if "wy" in d else d["w"][1]


def dev(row, key_o="o", key_l="l"):
    """Deviations in units of the impact speed V: v_x, v_z, R w_y (bounces only)."""
    o, l, V, R = row[key_o], row[key_l], row["V"], row.get("R", 0)
    if not (o["bounce"] and l["bounce"]):
        return None
    return (abs(o["v"][0] - l["v"][0]) / V, abs(o["v"][2] - l["v"][2]) / V,
            abs(wy(o) - wy(l)) * R / V)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--sr", required=True)
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--d", type=float, default=10e-6)
    ap.add_argument("--grid", type=int, default=5)
    ap.add_argument("--angles", default="0,30,60")
    ap.add_argument("--speeds-hertz", default="0.5,2")
    ap.add_argument("--speeds-jkr", default="0.3,1")
    ap.add_argument("--cases", default="hertz,jkr")
    ap.add_argument("--cor", type=float, default=0.7)
    ap.add_argument("--lmp-steps", type=float, default=100.0)
    ap.add_argument("--halve", action="store_true")
    ap.add_argument("--no-single", action="store_true")
    ap.add_argument("--tol-v", type=float, default=0.03)
    ap.add_argument("--tol-w", type=float, default=0.05)
    ap.add_argument("--tol-e", type=float, default=0.05)
    ap.add_argument("--tol-vz-jkr", type=float, default=0.1)
    a = ap.parse_args()
    work = os.path.join(a.out, ".work")
    os.makedirs(work, exist_ok=True)
    t_start = time.time()
    s = read_settings(a.sr, a.d)
    m = Model(s, a.d)
    L = Lammps(a.lmp, m, work, a.lmp_steps)
    O = Ours(a.sr, m, work, a.cor, m.accuracy)
    ver = run([a.lmp, "-h"], "lmp -h").splitlines()
    ver = next((q.split(" - ", 1)[1].strip() for q in ver if "Simulator - " in q), "unknown version")
    angles = [float(q) for q in a.angles.split(",")]
    cases = a.cases.split(",")
    pts = grid(a.grid, m.sp)
    cal = ["| quantity | value |", "|---|---|"]
    cal.append("| LAMMPS (Debian package lammps) | %s |" % ver)
    cal.append("| d [m], R* of an asperity contact [m], particle mass [kg] | %.4g, %.4g, %.4g |" % (a.d, m.Ra, m.mass))
    cal.append("| E* [Pa], G* [Pa] (LAMMPS: E = 2E* with nu = 0, Mindlin k_t = 8G*) | %.6g, %.6g |" % (m.Es, m.Gs))
    speeds_h = [float(q) for q in a.speeds_hertz.split(",")]
    eL = calibrate(L, O, m, a.cor, speeds_h, cal)
    single = None
    if any(c.startswith("jkr") for c in cases) and not a.no_single:
        single = jkr_single(L, O, m, eL, cal)
    rows = []
    for c in cases:
        sp = [float(q) for q in (a.speeds_hertz if c == "hertz" else a.speeds_jkr).split(",")]
        rows += compare(L, O, m, c, eL, pts, angles, sp, a.halve)
    for r in rows:
        r["R"] = m.R
    # per asperity contact: separation energy the kernel loses and LAMMPS does not
    dUa = m.jkr_loss(m.Ra, m.gamma, m.jkr_af(m.Ra, m.gamma)) - m.jkr_loss(m.Ra, m.gamma, m.a_at(m.lammps_pulloff(m.Ra, m.gamma), m.Ra, m.gamma))

    # per-impact table
    with open(os.path.join(a.out, "impacts.csv"), "w") as f:
        f.write("case,V_m_s,angle_deg,x_m,y_m,vn_m_s,vt_m_s,ours_outcome,lmp_outcome,ours_vx,lmp_vx,ours_vz,lmp_vz,"
                "lmp_vy,ours_wy,lmp_wy,lmp_wx,lmp_wz,ours_contacts,lmp_contacts,lmp_plane_contacts,"
                "ours_status,ours_energy_err,ours2_vx,ours2_vz,ours2_wy,lmp2_vx,lmp2_vz,lmp2_wy\n")
        for r in rows:
            o, l = r["o"], r["l"]
            h = []
            if "o2" in r:
                h = [r["o2"]["v"][0], r["o2"]["v"][2], r["o2"]["wy"], r["l2"]["v"][0], r["l2"]["v"][2], r["l2"]["w"][1]]
            f.write(",".join(str(q) for q in [
                r["case"], r["V"], r["th"], "%.4g" % r["x"], "%.4g" % r["y"], "%.6g" % r["vn"], "%.6g" % r["vt"],
                "bounce" if o["bounce"] else "stick", "bounce" if l["bounce"] else "stick",
                "%.6g" % o["v"][0], "%.6g" % l["v"][0], "%.6g" % o["v"][2], "%.6g" % l["v"][2],
                "%.4g" % l["v"][1], "%.6g" % o["wy"], "%.6g" % l["w"][1], "%.4g" % l["w"][0], "%.4g" % l["w"][2],
                o["contacts"], l["contacts"], l["plane_contacts"], o["status"].split()[0], o["energy_err"]]
                + ["%.6g" % q for q in h]) + "\n")

    # summary per case, speed and angle
    I = 0.4 * m.R * m.R

    def ekin(d):
        """Rebound energy per unit mass from v_x, v_z, w_y (what both codes report)."""
        return 0.5 * (d["v"][0] ** 2 + d["v"][2] ** 2) + 0.5 * I * wy(d) ** 2

    bad = []
    summ = ["| case | V [m/s] | angle | impacts | bounces (s / L) | same outcome | same contacts (all / bounces) | max dv_x/V | max dv_z/V | max R dw_y/V | "
            "halving: snowregime | halving: LAMMPS | energy: (E_L - E_s - n dU)/E_in | within tolerance |",
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    groups = {}
    for r in rows:
        groups.setdefault((r["case"], r["V"], r["th"]), []).append(r)
    for (c, V, th), g in groups.items():
        same_o = sum(1 for r in g if r["o"]["bounce"] == r["l"]["bounce"])
        same_c = sum(1 for r in g if r["o"]["contacts"] == r["l"]["contacts"])
        nb = sum(1 for r in g if r["o"]["bounce"] and r["l"]["bounce"])
        same_cb = sum(1 for r in g if r["o"]["bounce"] and r["l"]["bounce"] and r["o"]["contacts"] == r["l"]["contacts"])
        ds = [q for q in (dev(r) for r in g) if q]
        mx = [max((q[i] for q in ds), default=0.0) for i in range(3)]
        hal = []
        for kk in (("o", "o2"), ("l", "l2")):
            qs = [dev(r, *kk) for r in g if kk[1] in r]
            qs = [q for q in qs if q]
            hal.append("%.2g, %.2g" % (max((max(q[0], q[1]) for q in qs), default=0.0),
                                       max((q[2] for q in qs), default=0.0)) if any(kk[1] in r for r in g) else "-")
        # the separation criterion accounted for: a LAMMPS contact breaks with dU less lost
        ens = []
        for r in g:
            if c == "jkr-elastic" and r["o"]["bounce"] and r["l"]["bounce"]:
                ens.append(abs(ekin(r["l"]) - ekin(r["o"]) - r["l"]["contacts"] * dUa / m.mass) / (0.5 * V * V))
        ok = 0
        for r in g:
            q = dev(r)
            both = r["o"]["bounce"] and r["l"]["bounce"]
            # contacts: on bounces (a stick is decided by energy in the kernel, which stops
            # counting there, while LAMMPS's sphere rolls on to the time bound)
            same_c_b = r["o"]["contacts"] == r["l"]["contacts"] or not both
            if c == "hertz":
                good = (r["o"]["bounce"] == r["l"]["bounce"] and same_c_b
                        and (q is None or (q[0] <= a.tol_v and q[1] <= a.tol_v and q[2] <= a.tol_w)))
            elif c == "jkr-elastic":
                # the separation criterion accounted for: LAMMPS's rebound energy less n dU is the
                # kernel's (a LAMMPS bounce whose energy less n dU is below tol_e E_in may stick in
                # the kernel: it is within the difference of the criteria)
                e = ekin(r["l"]) * r["l"]["bounce"] - ekin(r["o"]) - r["l"]["contacts"] * dUa / m.mass
                e /= 0.5 * V * V
                good = same_c_b
                if both:
                    good = good and abs(e) <= a.tol_e and q[0] <= a.tol_v and q[2] <= a.tol_w
                elif r["o"]["bounce"] != r["l"]["bounce"]:
                    # a kernel stick against a LAMMPS bounce: allowed when LAMMPS's normal
                    # rebound energy does not exceed what its n contacts did not lose at
                    # separation (capture is decided by the normal motion; the tangential
                    # motion of a captured sphere goes on along the wall)
                    en = 0.5 * r["l"]["v"][2] ** 2 - r["l"]["contacts"] * dUa / m.mass
                    good = r["l"]["bounce"] == 1 and en <= a.tol_e * 0.5 * V * V
            else:
                # JKR with the COR dashpot: LAMMPS's tsuji dashpot acts on the JKR contact radius
                # and in tension too (the kernel's only at delta > 0, on sqrt(R delta)): v_z within
                # tol_vz_jkr V (the single-contact difference), and the outcome may differ when the
                # bouncing one leaves slower than that
                good = same_c_b
                if both:
                    good = good and q[0] <= a.tol_v and q[1] <= a.tol_vz_jkr and q[2] <= a.tol_w
                elif r["o"]["bounce"] != r["l"]["bounce"]:
                    vz = r["o"]["v"][2] if r["o"]["bounce"] else r["l"]["v"][2]
                    good = vz <= a.tol_vz_jkr * V
            ok += good
            if not good:
                bad.append(r)
        summ.append("| %s | %g | %g | %d | %d / %d | %d | %d / %d of %d | %.2g | %.2g | %.2g | %s | %s | %s | %s |" % (
            c, V, th, len(g), sum(r["o"]["bounce"] for r in g), sum(r["l"]["bounce"] for r in g),
            same_o, same_c, same_cb, nb, mx[0], mx[1], mx[2], hal[0], hal[1],
            ("%.2g" % max(ens)) if ens else "-", "%d of %d" % (ok, len(g))))

    secs = time.time() - t_start
    with open(os.path.join(a.out, "summary.md"), "w") as f:
        f.write("Rough wall, snowregime against LAMMPS (issue 24): d = %g m ice sphere on the default\n"
                "square lattice (asperity r = %g m, spacing %g m), %d impact points (a %d x %d grid over\n"
                "the unit cell) x angles %s deg x speeds |v| (hertz %s, jkr %s m/s); constant COR %g\n"
                "(dashpot on both branches, LAMMPS tsuji calibrated to it).\n"
                "Tolerances (bounces in both codes): |dv_x|, |dv_z| <= %g V, R |dw_y| <= %g V and the same\n"
                "number of contacts; hertz: the same outcome; jkr-elastic: |E_L - E_s - n dU| <= %g E_in\n"
                "instead of dv_z (dU: the separation energy a LAMMPS contact does not lose), a kernel stick\n"
                "against a LAMMPS bounce allowed when its v_z^2/2 - n dU <= %g E_in; jkr: |dv_z| <= %g V, the\n"
                "outcome may differ when the bouncing code leaves with v_z <= %g V.\n\n"
                % (a.d, m.r, m.sp, len(pts), a.grid, a.grid, a.angles, a.speeds_hertz, a.speeds_jkr, a.cor,
                   a.tol_v, a.tol_w, a.tol_e, a.tol_e, a.tol_vz_jkr, a.tol_vz_jkr))
        f.write("\n".join(cal) + "\n\n")
        f.write("\n".join(summ) + "\n\n")
        f.write("Runs: snowregime %d impacts in %.1f s, LAMMPS %d runs in %.1f s; total %.0f s.\n"
                % (O.runs, O.seconds, L.runs, L.seconds, secs))
        f.write("impacts outside the tolerances: %d of %d\n" % (len(bad), len(rows)))
    with open(os.path.join(a.out, "summary.md")) as f:
        sys.stdout.write(f.read())
    for r in bad:
        sys.stdout.write("outside: %s V %g angle %g x %.3g y %.3g: outcome %d/%d contacts %d/%d v_x %.4g/%.4g v_z %.4g/%.4g w_y %.4g/%.4g\n" % (
            r["case"], r["V"], r["th"], r["x"], r["y"], r["o"]["bounce"], r["l"]["bounce"],
            r["o"]["contacts"], r["l"]["contacts"], r["o"]["v"][0], r["l"]["v"][0],
            r["o"]["v"][2], r["l"]["v"][2], r["o"]["wy"], r["l"]["w"][1]))
    try:
        os.rmdir(work)
    except OSError:
        pass
    return 3 if bad else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Fail as e:
        sys.stderr.write("lammps-rough: %s\n" % e)
        sys.exit(1)
