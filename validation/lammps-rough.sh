#!/usr/bin/env bash
# NAME
#     lammps-rough.sh - the rough-wall impacts of snowregime checked against LAMMPS
#
# SYNOPSIS
#     validation/lammps-rough.sh --out DIR [--force] [--quick] [--grid K] [--angles LIST]
#                                [--speeds-hertz LIST] [--speeds-jkr LIST] [--cases LIST]
#                                [--d D] [--cor E] [--lmp-steps N] [--halve] [--check]
#     validation/lammps-rough.sh --help
#
# DESCRIPTION
#     Runs the same impacts of one ice sphere on snowregime's default rough wall
#     (wall lattice: a square lattice of hemispherical ABS asperities, radius and
#     spacing as in `snowregime --help`) in snowregime's 3-D multi-contact
#     integrator (regime/kernel/swr_rough.c) and in LAMMPS (Debian's `lmp`,
#     pair_style granular, one process), and compares the rebound velocity
#     (v_x, v_y, v_z), the spin (w_x, w_y, w_z), the number of contacts made and
#     stick/bounce.
#     The work is done by bin/snowlammps (tools/snowlammps/swl_*.c, C11, the
#     kernel linked in; `snowlammps --help`); this script checks the options and
#     makes the output folder appear whole or not at all.
#     In LAMMPS the asperities are frozen spheres of radius r centred on z = 0,
#     the base plane is fix wall/gran, the sphere is integrated by nve/sphere.
#     Both codes use the kernel's default material constants.
#
#     Cases (--cases, comma list):
#       hertz        Hertz without adhesion, constant COR E on both branches
#                    (snowregime: cor E, dashpot both; LAMMPS: damping tsuji,
#                    its input calibrated until the flat-wall COR is E), Mindlin
#                    friction (mu), no rolling resistance (none without adhesion)
#       jkr-elastic  JKR (gamma) without damping, Mindlin friction, rolling
#                    resistance (LAMMPS: rolling sds matched at a = a0); LAMMPS's
#                    contacts break at its own pull-off overlap, so each loses less
#                    energy at separation: accounted for per contact (dU)
#       jkr          JKR with the COR dashpot of `hertz` (LAMMPS's tsuji dashpot
#                    also acts in tension: v_z reported, not gated)
#     Before the impacts: the COR calibration on the flat plane and one asperity,
#     and (with a jkr case) the separation overlap and the sticking velocity of a
#     head-on impact on one asperity in both codes against the closed forms.
#
# OPTIONS
#     --out DIR            output folder (required): summary.md (the tables),
#                          impacts.csv (every impact in both codes), report.txt,
#                          times.txt, written only when the run succeeds. DIR
#                          missing: created (its parent must exist). DIR an empty
#                          folder or an earlier SnowWall output folder (it holds
#                          .snowwall-output): the files are written into it, what
#                          else it holds stays. Any other existing DIR is refused
#                          (exit 2) unless --force. Nothing is deleted from DIR.
#     --force              write into an existing DIR that is not a SnowWall
#                          output folder: regular files of the same names are
#                          replaced, nothing deleted, no .snowwall-output added
#     --quick              the test subset: --grid 2 --angles 0,30,60 --speeds-hertz 0.5,2
#                          --speeds-jkr 1 --cases hertz,jkr-elastic, no single-contact
#                          sticking velocities (about 5 s)
#     --grid K             K x K impact points over the lattice's unit cell,
#                          x, y = 0, s/K, ..., (K-1)s/K (default 5: 25 points; 1..20)
#     --angles LIST        impact angles from the normal [deg] (default 0,30,60; each
#                          in [0, 80]): v_n = V cos, v_t = V sin (along +x). The
#                          number lists take no empty item and no value twice;
#                          they are used in ascending order (a note when given
#                          otherwise); --cases takes no empty item or name twice
#     --speeds-hertz LIST  impact speeds V of the hertz case [m/s] (default 0.5,2)
#     --speeds-jkr LIST    impact speeds V of the jkr cases [m/s] (default 0.3,1);
#                          each speed in (0, 20]
#     --cases LIST         hertz, jkr-elastic, jkr (default all three)
#     --d D                particle diameter [m] (default 10e-6; 2e-6 .. 1e-4)
#     --cor E              the constant COR of the damped cases (default 0.7; 0.3 .. 0.95)
#     --lmp-steps N        LAMMPS steps per flat-wall Hertz contact time (default 100;
#                          20 .. 2000); snowregime keeps its own `accuracy` (60)
#     --halve              also run every impact at half the step in both codes
#                          (LAMMPS dt/2, snowregime accuracy x 2): the step error
#     --check              exit 3 when an impact is outside the tolerances
#     -h, --help           this text
#
# TOLERANCES (justified in doc/kernel.md, "Cross-check against LAMMPS")
#     On bounces in both codes: |dv_x|, |dv_y| <= 0.03 V, R |dw_x|, R |dw_y|,
#     R |dw_z| <= 0.05 V, the same number of contacts. hertz: also |dv_z| <= 0.03 V
#     and the same outcome. jkr-elastic: |E_L - E_s - n dU| <= 0.05 E_in instead of
#     dv_z; a kernel stick against a LAMMPS bounce is allowed when LAMMPS's
#     v_z^2/2 - n dU <= 0.05 E_in. jkr: |dv_z| <= 0.1 V; the outcome may differ
#     when the code that bounces leaves with v_z <= 0.1 V.
#     LAMMPS's sphere counts as stuck when it has not left after 100 flat-wall
#     contact times.
#
# ENVIRONMENT
#     LMP          the LAMMPS binary (default lmp on PATH)
#     SNOWLAMMPS   the snowlammps binary (default bin/snowlammps)
#
# EXIT STATUS
#     0 done; 1 a run failed; 2 usage error; 3 (--check) an impact outside the
#     tolerances; 77 LAMMPS (lmp) is not installed (etc/setup.sh --lammps).
#
# EXAMPLES
#     validation/lammps-rough.sh --out results/lammps-rough --halve
#     validation/lammps-rough.sh --out /tmp/lr --quick --check
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
sl=${SNOWLAMMPS:-$top/bin/snowlammps}
lmp=${LMP:-lmp}
me=lammps-rough.sh
usage() { echo "$me: $1 (see --help)" >&2; exit 2; }
out= ; grid=5; angles=0,30,60; sh=0.5,2; sj=0.3,1; cases=hertz,jkr-elastic,jkr
d=10e-6; cor=0.7; steps=100; halve=(); check=0; single=(); force=0
need() { [ $# -ge 2 ] && [ -n "$2" ] || usage "$1 needs a value"; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --out) need "$@"; out=$2; shift ;;
        --grid) need "$@"; grid=$2; shift ;;
        --angles) need "$@"; angles=$2; shift ;;
        --speeds-hertz) need "$@"; sh=$2; shift ;;
        --speeds-jkr) need "$@"; sj=$2; shift ;;
        --cases) need "$@"; cases=$2; shift ;;
        --d) need "$@"; d=$2; shift ;;
        --cor) need "$@"; cor=$2; shift ;;
        --lmp-steps) need "$@"; steps=$2; shift ;;
        --halve) halve=(--halve) ;;
        --force) force=1 ;;
        --check) check=1 ;;
        --quick) grid=2; angles=0,30,60; sh=0.5,2; sj=1; cases=hertz,jkr-elastic; single=(--no-single) ;;
        *) usage "unknown option '$1'" ;;
    esac
    shift
done
[ -n "$out" ] || usage "--out DIR is required"
num='^[0-9]+([.][0-9]*)?([eE][-+]?[0-9]+)?$'
# inrange NAME VALUE LO HI: a plain number in [LO, HI]
inrange() {
    [[ "$2" =~ $num ]] && awk -v x="$2" -v lo="$3" -v hi="$4" 'BEGIN { exit !(x >= lo && x <= hi) }' \
        || usage "$1 '$2' is not a number in [$3, $4]"
}
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
inlist() {    # inlist VAR NAME LO HI LO_OPEN: VAR's comma list checked, in ascending order
    local v vals
    outdir_list "$1" "$me" "$2" "${!1}" num
    IFS=, read -r -a vals <<< "${!1}"
    for v in "${vals[@]}"; do
        inrange "$2 (in '${!1}')" "$v" "$3" "$4"
        [ "$5" = 0 ] || awk -v x="$v" 'BEGIN { exit !(x > 0) }' || usage "$2 (in '${!1}') '$v' must be > 0"
    done
}
[[ "$grid" =~ ^[1-9][0-9]?$ ]] && [ "$grid" -le 20 ] || usage "--grid '$grid' is not a whole number in 1..20"
inlist angles --angles 0 80 0
inlist sh --speeds-hertz 0 20 1
inlist sj --speeds-jkr 0 20 1
inrange --d "$d" 2e-6 1e-4
inrange --cor "$cor" 0.3 0.95
inrange --lmp-steps "$steps" 20 2000
outdir_list cases "$me" --cases "$cases" name
IFS=, read -r -a cl <<< "$cases"
[ ${#cl[@]} -gt 0 ] || usage "--cases is empty"
for c in "${cl[@]}"; do
    case "$c" in hertz|jkr-elastic|jkr) ;; *) usage "--cases: unknown case '$c' (hertz, jkr-elastic, jkr)" ;; esac
done
outdir_begin "$me" "$out" "$force"   # --out checked first: a refused folder is said before anything else
command -v "$lmp" >/dev/null 2>&1 || { echo "$me: LAMMPS ('$lmp') is not installed: run etc/setup.sh --lammps (skipped)" >&2; exit 77; }
[ -x "$sl" ] || { echo "$me: $sl missing: run ./Allwmake" >&2; exit 1; }
t0=$(date +%s)
rc=0
"$sl" --out "$tmp" --lmp "$(command -v "$lmp")" --deck "$top/tools/snowlammps/impact.lmp" \
    --grid "$grid" --angles "$angles" --speeds-hertz "$sh" --speeds-jkr "$sj" --cases "$cases" \
    --d "$d" --cor "$cor" --lmp-steps "$steps" "${halve[@]}" "${single[@]}" >"$tmp/report.txt" || rc=$?
[ "$rc" != 2 ] || exit 2    # snowlammps named the bad value
[ "$rc" = 0 ] || [ "$rc" = 3 ] || { cat "$tmp/report.txt" >&2; echo "$me: the comparison failed (exit $rc)" >&2; exit 1; }
t1=$(date +%s)
echo "$me: $((t1 - t0)) s wall time (grid $grid, angles $angles, cases $cases${halve:+, step halving})" >"$tmp/times.txt"
outdir_commit
cat "$out/report.txt"
cat "$out/times.txt"
if [ "$check" = 1 ] && [ "$rc" = 3 ]; then
    echo "$me: impacts outside the tolerances (see $out/report.txt)" >&2
    exit 3
fi
exit 0
