#!/usr/bin/env bash
# channel.sh - the deposition channel of validation/deposition.sh in Code_Saturne 6.0,
# the walls a SnowWall snow zone (wallmodel/CodeSaturne), every contact a deposit
# (doc/codesaturne.md)
#
# Usage: validation/codesaturne/channel.sh --out DIR [--force] [--tau-plus LIST]
#            [--treatments LIST] [--parcels N] [--warmup N] [--window N] [--help]
#
# The OpenFOAM benchmark's wall-function channel: two walls 2h = 12.7 mm apart,
# periodic along the flow and across it (6.35 mm each way; 2 x 10 x 2 uniform
# cells, the first cell centre at y+ about 30), air, held at Re_tau = 314 by the
# mean pressure gradient rho u_tau^2 / h; steady RANS, k-omega SST, Code_Saturne's
# wall function (3000 iterations). Then, on that flow frozen, per tau+ and per
# near-wall treatment, N ice spheres (920 kg/m3) released uniformly, gravity along
# the flow; every wall contact sticks (every-contact-sticks.coeffs through the
# binding), and
#   V+ = D h / (u_tau Int N dt)     over the window after the warm-up,
# D the deposits in the window (the binding's counts CSV), N the particles in the
# channel (lagrangian.log); standard error V+/sqrt(D). For nearwall, vplus.csv
# also has the closure's deposits in the window and their expected number (the
# listing's lines of swcs_nearwall).
#
# --tau-plus LIST   comma-separated (default 0.3,1,3,10,30; no empty item, no
#                   value twice; used in ascending order, with a note when given
#                   otherwise)
# --treatments LIST the near-wall treatments, comma-separated (no empty item, no
#                   name twice; default langevin,deposition,nearwall):
#                   langevin    Code_Saturne's Langevin model of the velocity seen
#                               (idistu 1)
#                   deposition  that with its deposition submodel (Guingo & Minier)
#                   nearwall    the C core's near-wall model with the sublayer
#                               closure of etc/deposition.coeffs (swcs_nearwall;
#                               Code_Saturne's own dispersion off), the treatment
#                               of the OpenFOAM benchmark's snowNearWall
#                   crw         the same without the closure
# --parcels N       particles per run (default 2000)
# --warmup N, --window N   time steps of 2 t+ (defaults 1000 and 4000: 2000 t+
#                   and 8000 t+); both multiples of 100
# Writes into DIR, only when the run succeeds: vplus.csv, vplus.md (with
# Wood's correlation), flow.md (u_tau, bulk velocity, y+ of the first cell,
# times). DIR missing: created (with its parents). DIR an empty folder or an
# earlier SnowWall output folder (it holds .snowwall-output): the files are
# written into it, what else it holds stays. Any other existing DIR is refused
# (exit 2) unless --force: then the files are written into it (regular files
# of the same names replaced), nothing deleted, no .snowwall-output added.
# Needs Code_Saturne (etc/setup.sh) and ./Allwmake.
# Exit status: 0 done, 1 a run failed, 2 a usage error.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
here=$top/validation/codesaturne/channel
out=
taus=0.3,1,3,10,30
treats=langevin,deposition,nearwall
parcels=2000
warmup=1000
window=4000
force=0
usage() { echo "channel.sh: $1 (see --help)" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --out) [ -n "${2:-}" ] || usage "--out needs a folder"; out=$2; shift ;;
        --tau-plus) [ -n "${2:-}" ] || usage "--tau-plus needs a list"; taus=$2; shift ;;
        --treatments) [ -n "${2:-}" ] || usage "--treatments needs a list"; treats=$2; shift ;;
        --parcels) [ -n "${2:-}" ] || usage "--parcels needs a number"; parcels=$2; shift ;;
        --warmup) [ -n "${2:-}" ] || usage "--warmup needs a number"; warmup=$2; shift ;;
        --window) [ -n "${2:-}" ] || usage "--window needs a number"; window=$2; shift ;;
        --force) force=1 ;;
        *) usage "unknown argument '$1'" ;;
    esac
    shift
done
[ -n "$out" ] || usage "no --out DIR"
# shellcheck source=../../etc/outdir.sh
. "$top/etc/outdir.sh"
outdir_list taus channel.sh --tau-plus "$taus" num
outdir_list treats channel.sh --treatments "$treats" name
for t in ${taus//,/ }; do
    awk -v t="$t" 'BEGIN { exit !(t ~ /^[0-9.eE+-]+$/ && t + 0 >= 0.01 && t + 0 <= 1000) }' \
        || usage "tau+ '$t' is not a number in [0.01, 1000]"
done
for t in ${treats//,/ }; do
    case "$t" in langevin|deposition|nearwall|crw) ;; *) usage "--treatments: '$t' is not langevin, deposition, nearwall or crw" ;; esac
done
[[ $parcels =~ ^[1-9][0-9]{0,6}$ ]] || usage "--parcels '$parcels' is not a whole number in [1, 9999999]"
for v in "$warmup" "$window"; do
    [[ $v =~ ^[1-9][0-9]{0,5}00$ ]] || usage "--warmup / --window '$v' is not a multiple of 100 in [100, 99999900]"
done
command -v code_saturne > /dev/null || { echo "channel.sh: code_saturne not installed (etc/setup.sh)" >&2; exit 1; }
export USER=${USER:-$(id -un 2> /dev/null || echo snowwall)}
# the output folder checked before any work; its work folder $tmp gets the
# three results, the study runs in a folder of its own under /tmp
outdir_begin channel.sh "$out" "$force" parents
outwork=$tmp
tmp=$(mktemp -d /tmp/sw-channel-XXXXXX)
trap 'rm -rf -- "$tmp"; outdir_cleanup' EXIT
t0=$(date +%s)

# the flow
(cd "$tmp" && code_saturne create -s study -c flow > /dev/null && cd study && code_saturne create -c lagr > /dev/null) \
    || { echo "channel.sh: code_saturne create failed" >&2; exit 1; }
"$top/tests/codesaturne/gmsh-box.sh" 2 10 2 0.00635 0.0127 0.00635 "$tmp/study/MESH/channel.msh"
cp "$here"/flow/*.c "$tmp/study/flow/SRC/"
cp /usr/share/code_saturne/user/cs_user_boundary_conditions.f90 "$tmp/study/flow/SRC/"
printf "def define_domain_parameters(domain):\n    if domain.param == None:\n        domain.meshes = ['channel.msh']\n" \
    > "$tmp/study/flow/DATA/cs_user_scripts.py"
echo "channel.sh: flow (k-omega SST, 3000 iterations)"
(cd "$tmp/study/flow" && code_saturne run --id run > log.run 2>&1) \
    || { tail -20 "$tmp/study/flow/RESU/run/listing" "$tmp/study/flow/RESU/run/error" >&2 2> /dev/null; echo "channel.sh: the flow run failed" >&2; exit 1; }
flow=$tmp/study/flow/RESU/run
t1=$(date +%s)
utau=$(awk 'BEGIN { printf "%.6g", 314 * 1.5e-5 / 0.00635 }')
ubulk=$(grep '^v  Velocity\[X\]' "$flow/listing" | tail -1 | awk '{ print $5 }')
yplus=$(grep 'Dimensionless distance *yplus' "$flow/listing" | tail -1 | awk '{ print $NF }')
res=$(tail -1 "$flow/residuals.csv" | cut -d, -f2 | tr -d ' ')

# the particles: compiled once, run per treatment and tau+
lagr=$tmp/study/lagr
cp "$here"/flow/*.c "$lagr/SRC/"
cp "$here"/lagr/*.c "$lagr/SRC/"
cp "$here/every-contact-sticks.coeffs" "$lagr/DATA/regime.coeffs"
cp "$top/etc/deposition.coeffs" "$lagr/DATA/deposition.coeffs"
"$top/wallmodel/CodeSaturne/swcs-case" --mesh channel.msh "$lagr" > /dev/null
echo "        domain.restart_input = '$flow/checkpoint'" >> "$lagr/DATA/cs_user_scripts.py"
(cd "$lagr" && code_saturne run --initialize --id base > log.init 2>&1) \
    || { tail -20 "$lagr/RESU/base/compile.log" >&2 2> /dev/null; echo "channel.sh: compiling the particle case failed" >&2; exit 1; }
steps=$((warmup + window))
w0=$((3000 + warmup)); w1=$((3000 + steps))
dt=$(awk -v u="$utau" 'BEGIN { printf "%.10g", 2 * 1.5e-5 / (u * u) }')
echo "treatment,tau_plus,d_m,parcels,deposits,int_N_dt_s,vplus,vplus_err,vplus_wood,closure_drawn,closure_expected" > "$tmp/vplus.csv"
for treat in ${treats//,/ }; do
    for tau in ${taus//,/ }; do
        r=$lagr/RESU/${treat}_t$tau
        cp -r "$lagr/RESU/base" "$r"
        s=$(date +%s)
        (cd "$r" && CH_STEPS=$steps CH_TAU=$tau CH_TREAT=$treat CH_N=$parcels CH_EVERY=100 OMP_NUM_THREADS=1 \
            ./cs_solver > log.solver 2>&1) \
            || { { tail -20 "$r/listing" "$r/error" || true; } >&2 2> /dev/null; echo "channel.sh: particle run $treat tau+ $tau failed" >&2; exit 1; }
        c0=$(printf '%s/snowwall-counts-%06d.csv' "$r" "$w0"); c1=$(printf '%s/snowwall-counts-%06d.csv' "$r" "$w1")
        [ -f "$c0" ] && [ -f "$c1" ] || { echo "channel.sh: no counts CSV at steps $w0 and $w1 in $r" >&2; exit 1; }
        row=$(awk -v w0="$w0" -v w1="$w1" -v h=0.00635 -v u="$utau" -v dt="$dt" '
            FNR == 1 { f++ }
            f == 1 && FNR > 1 { split($0, a, ","); s0 = a[6] }
            f == 2 && FNR > 1 { split($0, a, ","); s1 = a[6] }
            f == 3 && !/^#/ && $1 > w0 && $1 <= w1 { integ += $3 * dt }
            END { D = s1 - s0; v = (integ > 0 ? D * h / (u * integ) : 0)
                  printf "%d,%.6g,%.4g,%.2g", D, integ, v, (D > 0 ? v / sqrt(D) : 0) }' \
            "$c0" "$c1" "$r/lagrangian.log")
        d=$(awk -v t="$tau" -v u="$utau" 'BEGIN { printf "%.4g", sqrt(18 * 1.8e-5 * t * 1.5e-5 / (920 * u * u)) }')
        wood=$(awk -v t="$tau" 'BEGIN { v = 4.5e-4 * t * t; printf "%.3g", (v > 0.13 ? 0.13 : v) }')
        # the near-wall closure's deposits in the window (listing, cumulative at every output step)
        cl=$(awk -v w0="$w0" -v w1="$w1" '
            /^SnowWall near-wall closure, step / { st = $5 + 0; n = 0; e = 0
                for (i = 6; i <= NF; i++) if ($i == "(expected") { n += $(i - 1); v = $(i + 1); sub(/\)$/, "", v); e += v }
                if (st == w0) { n0 = n; e0 = e } if (st == w1) { n1 = n; e1 = e } }
            END { printf "%d,%.6g", n1 - n0, e1 - e0 }' "$r/listing")
        echo "$treat,$tau,$d,$parcels,$row,$wood,$cl" >> "$tmp/vplus.csv"
        echo "channel.sh: $treat tau+ $tau: $(echo "$row" | cut -d, -f1) deposits, V+ $(echo "$row" | cut -d, -f3) (Wood $wood), $(( $(date +%s) - s )) s"
    done
done
t2=$(date +%s)
{
    echo "# Deposition velocity in the channel, Code_Saturne 6.0 (validation/codesaturne/channel.sh)"
    echo
    echo "$parcels particles per run; window of $window steps of 2 t+ after $warmup; every wall contact sticks."
    echo "V+ (deposits in the window; Wood's correlation V+ = 4.5e-4 tau+^2, at most 0.13)."
    echo
    echo "| treatment | tau+ | d [um] | deposits | V+ | error | Wood | V+ / Wood |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
    awk -F, 'NR > 1 { printf "| %s | %s | %.3g | %s | %s | %s | %s | %.3g |\n",
        ($1 == "deposition" ? "Langevin + deposition model" : $1 == "langevin" ? "Langevin" : $1 == "nearwall" ? "SnowWall near-wall model" : "SnowWall near-wall walk, no closure"), $2, $3 * 1e6, $5, $7, $8, $9, ($9 > 0 ? $7 / $9 : 0) }' "$tmp/vplus.csv"
} > "$tmp/vplus.md"
{
    echo "# The channel flow in Code_Saturne (validation/codesaturne/channel.sh)"
    echo
    echo "| cells across | first cell y+ (wall function) | u_tau [m/s] (imposed) | Re_tau | bulk U [m/s] | last residual | flow run [s] | particle runs [s] |"
    echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
    echo "| 10 | $yplus | $utau | 314 | $ubulk | $res | $((t1 - t0)) | $((t2 - t1)) |"
} > "$tmp/flow.md"
cp "$tmp/vplus.csv" "$tmp/vplus.md" "$tmp/flow.md" "$outwork/"
rm -rf -- "$tmp"
outdir_commit
cat "$out/flow.md" "$out/vplus.md"
echo "channel.sh: written $out/ ($((t2 - t0)) s)"
