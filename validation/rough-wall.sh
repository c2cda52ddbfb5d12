#!/usr/bin/env bash
# rough-wall.sh - sticking on a rough wall against the flat wall (doc/snowregime.md)
#
# Usage: validation/rough-wall.sh --out DIR [--force] [--points N] [--nd N --nv N] [--quick]
#                                 [--config FILE] [--set KEY=VALUE]... [--help]
#
# With bin/snowregime on the embedded defaults (dry snow on ABS), or on the
# settings given (--config/--set, as for snowregime), it measures
#   vcrit.md     the critical speeds at d = 10, 20, 50, 100 um on the flat wall
#                and on lattices of 1 um asperities (square at spacing 2 um,
#                i.e. touching; hexagonal; square with random offsets 0.3 s
#                and random sinking up to 0.5 um): the speeds where the stick
#                fraction over N impact points falls below 0.9, 0.5 and 0.1
#   geometry.md  the p = 0.5 speed at d = 10 and 50 um over the asperity
#                radius (0.25-5 um, touching) and the spacing (2-8 um at r = 1 um)
#   map/         snowregime map of the square lattice (N points per cell;
#                map.png, contours.csv, regime.coeffs with the probability table)
#   rough-map.png  the map's picture
#   times.txt, logs/  the run times and every snowregime output
# into DIR, only when the run succeeds. DIR missing: created (its parent must
# exist). DIR an empty folder or an earlier SnowWall output folder (it holds
# .snowwall-output): the files are written into it, what else it holds stays.
# Any other existing DIR is refused (exit 2) unless --force: then the files are
# written into it (regular files of the same names replaced), nothing deleted,
# no .snowwall-output added. Nothing is ever deleted from DIR.
# --points N: impact points per (d, v_n) (default 64); --nd/--nv: the map's
# grid (default 46 x 50); --quick: 8 points, speeds to 5 %, an 8 x 8 map (the test).
# Speeds are searched in [1e-3, 50] m/s to 1 % (the stick fraction of N points
# is a step function of v: finer is noise). The snowregime used is
# bin/snowregime, or $SNOWREGIME if set (the tests).
# Exit status: 0 done, 1 a run failed, 2 usage error or a rejected setting.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
sr=${SNOWREGIME:-$top/bin/snowregime}
out=
quick=0
force=0
points=64
nd=46
nv=50
sets=()
missing_value() { echo "rough-wall.sh: $1 (see --help)" >&2; exit 2; }   # a usage error: exit 2
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --out) [ -n "${2:-}" ] || missing_value "--out needs a folder"; out=$2; shift ;;
        --points) [ -n "${2:-}" ] || missing_value "--points needs a number"; points=$2; shift ;;
        --nd) [ -n "${2:-}" ] || missing_value "--nd needs a number"; nd=$2; shift ;;
        --nv) [ -n "${2:-}" ] || missing_value "--nv needs a number"; nv=$2; shift ;;
        --force) force=1 ;;
        --quick) points=8; nd=8; nv=8; quick=1 ;;
        --config) [ -n "${2:-}" ] || missing_value "--config needs a file"; sets+=(--config "$2"); shift ;;
        --set) [ -n "${2:-}" ] || missing_value "--set needs KEY=VALUE"; sets+=(--set "$2"); shift ;;
        *) echo "rough-wall.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[ -n "$out" ] || { echo "rough-wall.sh: --out DIR is required (see --help)" >&2; exit 2; }
for n in "$points" "$nd" "$nv"; do
    [[ "$n" =~ ^[1-9][0-9]{0,4}$ ]] || { echo "rough-wall.sh: '$n' is not a whole number in 1..99999" >&2; exit 2; }
done
[ -x "$sr" ] || { echo "rough-wall.sh: $sr missing: run ./Allwmake" >&2; exit 1; }
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
outdir_begin rough-wall.sh "$out" "$force"

dtab=10e-6,20e-6,50e-6,100e-6
search=(--vmin 1e-3 --vmax 50 --tol 1e-2 --scan-ratio 1.5)
[ "$quick" = 0 ] || search=(--vmin 1e-3 --vmax 50 --tol 5e-2 --scan-ratio 3)
# the settings are checked once, with a message of snowregime's own
"$sr" collide --d 1e-5 --vn 1 "${sets[@]}" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 2; }

# vcrit LABEL LEVEL DLIST SETTINGS... -> "v1 v2 ..." (nan when not bracketed)
vcrit() {
    local label=$1 level=$2 dl=$3; shift 3
    local lv=()
    [ "$level" = - ] || lv=(--level "$level" --points "$points")
    "$sr" vcrit --d "$dl" "${search[@]}" "${sets[@]}" "$@" "${lv[@]}" >"$tmp/$label.txt" 2>"$tmp/$label.err" || true
    grep -q . "$tmp/$label.txt" || { cat "$tmp/$label.err" >&2; echo "rough-wall.sh: vcrit $label failed" >&2; exit 1; }
    awk '!/^#/ { printf "%s%s", (n++ ? " " : ""), $2 }' "$tmp/$label.txt"
}
fmt() { awk '{ for (i = 1; i <= NF; i++) printf " %s |", ($i == "nan" ? "-" : sprintf("%.3g", $i)); }'; }

L1="--set wall=lattice --set asperity_r=1e-6 --set asperity_spacing=2e-6"
t0=$(date +%s)
{
    echo "Critical normal speeds [m/s] at d = 10 / 20 / 50 / 100 um; on a rough wall the speed"
    echo "where the stick fraction over $points impact points falls below p (seed 1)."
    echo
    echo "| wall | p | 10 um | 20 um | 50 um | 100 um |"
    echo "|---|---|---:|---:|---:|---:|"
    echo "| flat | - |$(vcrit flat - "$dtab" | fmt)"
    for p in 0.9 0.5 0.1; do
        # shellcheck disable=SC2086
        echo "| square, r 1 um, s 2 um | $p |$(vcrit sq$p $p "$dtab" $L1 | fmt)"
    done
    # shellcheck disable=SC2086
    echo "| hexagonal, r 1 um, s 2 um | 0.5 |$(vcrit hex 0.5 "$dtab" $L1 --set lattice=hex | fmt)"
    # shellcheck disable=SC2086
    echo "| random (offsets 0.3 s, sinking 0.5 um) | 0.5 |$(vcrit rnd 0.5 "$dtab" $L1 --set asperity_jitter=0.3 --set asperity_dz=0.5e-6 | fmt)"
} >"$tmp/vcrit.md"
{
    echo "The p = 0.5 speed [m/s] at d = 10 / 50 um over the asperity geometry ($points impact points)."
    echo
    echo "| asperity r [um] | spacing [um] | 10 um | 50 um |"
    echo "|---:|---:|---:|---:|"
    for r in 0.25 0.5 1 2 5; do
        s=$(awk -v r="$r" 'BEGIN { print 2 * r }')
        echo "| $r | $s |$(vcrit r$r 0.5 10e-6,50e-6 --set wall=lattice --set asperity_r=${r}e-6 --set asperity_spacing=${s}e-6 | fmt)"
    done
    for s in 3 4 8; do
        echo "| 1 | $s |$(vcrit s$s 0.5 10e-6,50e-6 --set wall=lattice --set asperity_r=1e-6 --set asperity_spacing=${s}e-6 | fmt)"
    done
} >"$tmp/geometry.md"
t1=$(date +%s)
# shellcheck disable=SC2086
"$sr" map $L1 "${sets[@]}" --points "$points" --nd "$nd" --nv "$nv" --out "$tmp/map" >"$tmp/map.log" 2>&1 \
    || { cat "$tmp/map.log" >&2; echo "rough-wall.sh: map failed" >&2; exit 1; }
cp "$tmp/map/map.png" "$tmp/rough-map.png"
t2=$(date +%s)
echo "rough-wall.sh: tables $((t1 - t0)) s, map $((t2 - t1)) s ($nd x $nv x $points points)" >"$tmp/times.txt"
rm -f "$tmp"/*.err "$tmp/err"
mkdir -p "$tmp/logs"
mv "$tmp"/*.txt "$tmp/map.log" "$tmp/logs/" 2>/dev/null || true
mv "$tmp/logs/times.txt" "$tmp/times.txt"
outdir_commit
cat "$out/vcrit.md"
echo
cat "$out/geometry.md"
echo
cat "$out/times.txt"
