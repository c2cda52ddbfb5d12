#!/usr/bin/env bash
# rough-reference.sh - the reference study's rough wall of 1 um spheres (doc/kernel.md)
#
# Usage: validation/rough-reference.sh --out DIR [--force] [--points N] [--threads N] [--quick] [--help]
#
# With bin/snowregime on the embedded defaults (dry snow on ABS) it measures the
# critical normal speed v_crit of 10, 20, 50 and 100 um ice spheres hitting
#   flat      the flat ABS wall
#   default   today's default lattice: hemispheres r 1 um, square, spacing 2 um
#   touching  regime/configs/rough-spheres-touching.conf: whole spheres of
#             1 um diameter, touching, square lattice (spacing 1 um)
#   random    regime/configs/rough-spheres-random.conf: a random overlapping
#             layer of the same spheres (jitter 0.5, sinking up to 0.5 um,
#             wall_seed 1)
# each rough wall with every plastic treatment of an asperity contact
# (asperity_yield contact, particle, elastic; snowregime --help), at the stick
# fractions p = 0.9, 0.5 and 0.1 (v_crit: where the fraction of N impact points
# that stick falls below p; the same points at every speed, seed 1). It writes
# into DIR, only when the run succeeds:
#   reference.md   the v_crit table, the rough/flat ratio table, the run time
#   reference.csv  wall,asperity_yield,p,d_um,vcrit_m_s,ratio_to_flat
#                  (nan: no change of regime in the search range)
#   sensitivity.md the random layer's p = 0.5 v_crit at 10 and 50 um against
#                  its sinking depth asperity_dz and its seed (not with --quick)
#   times.txt      the run time and the load average before and after
#   logs/          every snowregime vcrit output (its # comments: brackets,
#                  non-monotone warnings)
# DIR missing: created (its parent must exist). DIR an empty folder or an
# earlier SnowWall output folder (it holds .snowwall-output): the files are
# written into it, what else it holds stays. Any other existing DIR is refused
# (exit 2) unless --force: then the files are written into it (regular files of
# the same names replaced), nothing deleted, no .snowwall-output added.
# Nothing is ever deleted from DIR.
# --points N: impact points per speed (default 256); --threads N: threads of
# snowregime vcrit, over the diameters (default 2); --quick: 8 points, speeds
# to 5 %, no sensitivity table (the test, tests/regime_cli/test_rough_reference.sh).
# Speeds are searched in [1e-4, 100] m/s to 1 % (the stick fraction of N points
# is a step function of v: finer is noise). Measured: 1 min on 2 cores shared
# with other work (doc/kernel.md); --quick 3 s (20 s in the sanitizer build).
# The snowregime used is bin/snowregime, or $SNOWREGIME if set.
# Exit status: 0 done, 1 a run failed, 2 usage error.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
sr=${SNOWREGIME:-$top/bin/snowregime}
me=rough-reference.sh
out=
quick=0
force=0
points=256
threads=2
usage_error() { echo "$me: $1 (see --help)" >&2; exit 2; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
        --out) [ -n "${2:-}" ] || usage_error "--out needs a folder"; out=$2; shift ;;
        --points) [ -n "${2:-}" ] || usage_error "--points needs a number"; points=$2; shift ;;
        --threads) [ -n "${2:-}" ] || usage_error "--threads needs a number"; threads=$2; shift ;;
        --quick) quick=1 ;;
        --force) force=1 ;;
        *) usage_error "unknown option '$1'" ;;
    esac
    shift
done
[ -n "$out" ] || usage_error "--out DIR is required"
[[ "$points" =~ ^[1-9][0-9]{0,4}$ ]] || usage_error "--points: '$points' is not a whole number in 1..99999"
[[ "$threads" =~ ^[1-9][0-9]?$ ]] || usage_error "--threads: '$threads' is not a whole number in 1..99"
[ "$quick" = 0 ] || points=8
for c in touching random; do
    [ -r "$top/regime/configs/rough-spheres-$c.conf" ] || { echo "$me: regime/configs/rough-spheres-$c.conf missing" >&2; exit 1; }
done
[ -x "$sr" ] || { echo "$me: $sr missing: run ./Allwmake" >&2; exit 1; }
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
outdir_begin rough-reference.sh "$out" "$force"
mkdir "$tmp/logs"

dtab=10e-6,20e-6,50e-6,100e-6
search=(--vmin 1e-4 --vmax 100 --tol 1e-2 --scan-ratio 1.5 --threads "$threads")
[ "$quick" = 0 ] || search=(--vmin 1e-4 --vmax 100 --tol 5e-2 --scan-ratio 3 --threads "$threads")
walls=(default touching random)
yields=(contact particle elastic)
levels=(0.9 0.5 0.1)
wall_sets() {
    case "$1" in
        default) echo "--set wall=lattice --set asperity_r=1e-6 --set asperity_spacing=2e-6" ;;
        touching|random) echo "--config $top/regime/configs/rough-spheres-$1.conf" ;;
    esac
}
wall_name() {
    case "$1" in
        flat) echo "flat" ;;
        default) echo "default: hemispheres r 1 um, s 2 um" ;;
        touching) echo "1 um spheres, touching" ;;
        random) echo "1 um spheres, random layer" ;;
    esac
}

# vcrit LABEL DLIST ARGS... -> "v1 v2 ..." (nan when not bracketed); the output in logs/LABEL.txt
vcrit() {
    local label=$1 dl=$2; shift 2
    "$sr" vcrit --d "$dl" "${search[@]}" "$@" >"$tmp/logs/$label.txt" 2>"$tmp/logs/$label.err" || true
    grep -q '^[0-9]' "$tmp/logs/$label.txt" \
        || { cat "$tmp/logs/$label.err" >&2; echo "$me: snowregime vcrit $label failed" >&2; exit 1; }
    awk '!/^#/ { printf "%s%s", (n++ ? " " : ""), $2 }' "$tmp/logs/$label.txt"
}
fmt() { awk '{ for (i = 1; i <= NF; i++) printf " %s |", ($i == "nan" ? "-" : sprintf("%.3g", $i)); }'; }

load0=$(cut -d' ' -f1-3 /proc/loadavg)
t0=$(date +%s.%N)
read -r -a flat <<<"$(vcrit flat "$dtab")"
csv="$tmp/reference.csv"
echo "wall,asperity_yield,p,d_um,vcrit_m_s,ratio_to_flat" >"$csv"
ds=(10 20 50 100)
for i in 0 1 2 3; do echo "flat,-,-,${ds[$i]},${flat[$i]},1" >>"$csv"; done
declare -A v
for w in "${walls[@]}"; do
    for y in "${yields[@]}"; do
        for p in "${levels[@]}"; do
            # shellcheck disable=SC2046
            v[$w,$y,$p]=$(vcrit "$w-$y-$p" "$dtab" $(wall_sets "$w") --set asperity_yield="$y" \
                --points "$points" --level "$p")
            read -r -a r <<<"${v[$w,$y,$p]}"
            for i in 0 1 2 3; do
                echo "$w,$y,$p,${ds[$i]},${r[$i]},$(awk -v a="${r[$i]}" -v b="${flat[$i]}" \
                    'BEGIN { print (a == "nan" || b == "nan") ? "nan" : sprintf("%.4g", a / b) }')" >>"$csv"
            done
        done
    done
done
t1=$(date +%s.%N)
if [ "$quick" = 0 ]; then
    {
        echo "The random layer (rough-spheres-random.conf, asperity_yield contact): p = 0.5 speed [m/s]"
        echo "at 10 / 50 um against the sinking depth asperity_dz and the seed ($points impact points)."
        echo
        echo "| asperity_dz [um] | wall_seed | 10 um | 50 um |"
        echo "|---:|---:|---:|---:|"
        R="--config $top/regime/configs/rough-spheres-random.conf --points $points --level 0.5"
        for dz in 0 0.25 0.5 0.75 0.95; do
            # shellcheck disable=SC2086
            echo "| $dz | 1 |$(vcrit "dz$dz" 10e-6,50e-6 $R --set asperity_dz=${dz}e-6 | fmt)"
        done
        for s in 2 3; do
            # shellcheck disable=SC2086
            echo "| 0.5 | $s |$(vcrit "seed$s" 10e-6,50e-6 $R --set wall_seed=$s | fmt)"
        done
    } >"$tmp/sensitivity.md"
fi
t2=$(date +%s.%N)
load1=$(cut -d' ' -f1-3 /proc/loadavg)
tt=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
ts=$(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.1f", b - a }')
nonmono=$(grep -l -i 'non-monotone' "$tmp"/logs/*.txt 2>/dev/null | sed 's|.*/||; s|\.txt$||' | tr '\n' ' ' || true)
{
    echo "$me: table $tt s, sensitivity $ts s ($points impact points, --threads $threads,"
    echo "$(nproc) cores, load average $load0 before, $load1 after)"
} >"$tmp/times.txt"

{
    echo "# v_crit on the reference study's rough wall (1 um spheres)"
    echo
    echo "Critical normal speeds [m/s] of ice spheres (dry snow on ABS, embedded defaults)."
    echo "Rough walls: the speed where the stick fraction over $points impact points"
    echo "(seed 1, the same at every speed) falls below p. '-': no change of regime in"
    echo "[1e-4, 100] m/s. asperity_yield: the plastic COR of an asperity contact"
    echo "(contact: Thornton's e_p with the yield velocity of the contact's R*; particle:"
    echo "the flat wall's yield velocity; elastic: none, only the JKR hysteresis)."
    echo
    echo "| wall | asperity_yield | p | 10 um | 20 um | 50 um | 100 um |"
    echo "|---|---|---|---:|---:|---:|---:|"
    echo "| flat | - | - |$(echo "${flat[*]}" | fmt)"
    for w in "${walls[@]}"; do
        for y in "${yields[@]}"; do
            for p in "${levels[@]}"; do
                echo "| $(wall_name "$w") | $y | $p |$(echo "${v[$w,$y,$p]}" | fmt)"
            done
        done
    done
    echo
    echo "Rough / flat ratio of v_crit at p = 0.5 (in brackets: p = 0.9 - 0.1)."
    echo
    echo "| wall | asperity_yield | 10 um | 20 um | 50 um | 100 um |"
    echo "|---|---|---:|---:|---:|---:|"
    for w in "${walls[@]}"; do
        for y in "${yields[@]}"; do
            printf "| %s | %s |" "$(wall_name "$w")" "$y"
            awk -v a="${v[$w,$y,0.9]}" -v b="${v[$w,$y,0.5]}" -v c="${v[$w,$y,0.1]}" -v f="${flat[*]}" 'BEGIN {
                split(a, A); split(b, B); split(c, C); split(f, F)
                for (i = 1; i <= 4; i++) {
                    q = (B[i] == "nan") ? "-" : sprintf("%.3g", B[i] / F[i])
                    lo = (A[i] == "nan") ? "-" : sprintf("%.3g", A[i] / F[i])
                    hi = (C[i] == "nan") ? "-" : sprintf("%.3g", C[i] / F[i])
                    printf " %s (%s - %s) |", q, lo, hi
                }
                print "" }'
        done
    done
    echo
    echo "Measured: $(tr '\n' ' ' <"$tmp/times.txt")"
    [ -z "$nonmono" ] || { echo; echo "Non-monotone stick fraction reported by snowregime vcrit in: $nonmono(logs/)."; }
} >"$tmp/reference.md"
rm -f "$tmp"/logs/*.err
outdir_commit
cat "$out/reference.md"
[ "$quick" = 1 ] || { echo; cat "$out/sensitivity.md"; }
