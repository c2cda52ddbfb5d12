#!/usr/bin/env bash
# bench/regime.sh - benchmark of the regime kernel and snowregime (prints figures).
#
# Usage: bench/regime.sh [--reps N] [--build DIR] [--set KEY=VALUE]... [--help]
#
# --set KEY=VALUE: a kernel setting for every figure (e.g. cor=thornton-ning;
# keys: snowregime --help), passed to swr_bench and snowregime.
# Uses the release build (./Allwmake: build/release and bin/; --build DIR: another
# CMake release build folder, its snowregime and swr_bench). Prints medians of
# N repetitions (default 7) on this machine, 2 threads:
#   one collision (impacts at 0.5, 0.9, 1.1, 2 x v_crit for 46 diameters 10-100 um),
#   the accuracy of v_crit at the default accuracy setting (vs accuracy 30720),
#   the lowest accuracy setting giving v_crit within 0.1 % and one collision there,
#   v_crit for 46 diameters (library, and `snowregime vcrit` end to end),
#   the 46 x 50 map (library: grid, grid + interface refinement; and
#   `snowregime map --no-plot` end to end including the automatic range,
#   fit and file output),
# and their ratios to the project's speed targets (collision <= 10 us at 0.1 %
# v_crit accuracy, map <= 20 ms) and to the DEM codes used in this field
# (0.35 s per collision run, about 4 s for the same map).
# Not a test: nothing is asserted.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
reps=7
build=
sets=()
missing_value() { echo "regime.sh: $1 (see --help)" >&2; exit 2; }   # a usage error: exit 2
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        --set) [ -n "${2:-}" ] || missing_value "--set needs KEY=VALUE"; sets+=(--set "$2"); shift ;;
        --reps) [ -n "${2:-}" ] || missing_value "--reps needs a number"; reps=$2; shift ;;
        --build) [ -n "${2:-}" ] || missing_value "--build needs a folder"; build=$2; shift ;;
        *) echo "bench/regime.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
case "$reps" in ''|*[!0-9]*) echo "bench/regime.sh: --reps: '$reps' is not a positive integer" >&2; exit 2 ;; esac
[ "$reps" -ge 1 ] || { echo "bench/regime.sh: --reps: '$reps' must be >= 1" >&2; exit 2; }

if [ -n "$build" ]; then
    bench=$build/bench/swr_bench
    sr=$build/regime/cli/snowregime
else
    bench=$top/build/release/bench/swr_bench
    sr=$top/bin/snowregime
    [ -x "$sr" ] || sr=$top/build/release/regime/cli/snowregime
fi
if [ ! -x "$bench" ] || [ ! -x "$sr" ]; then
    echo "bench/regime.sh: release build missing ($bench, $sr): run ./Allwmake first" >&2
    exit 1
fi

echo "# bench/regime.sh on $(uname -n), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), $reps repetitions${sets[*]:+, ${sets[*]}}"
out=$("$bench" --reps "$reps" --threads 2 "${sets[@]}")
echo "$out" | sed 's/^/# /'
get() { echo "$out" | awk -v k="$1" '$1 == k { print $2 }'; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dlist=$(awk 'BEGIN { for (i = 0; i < 46; i++) printf "%s%.6g", (i ? "," : ""), 10e-6 + 90e-6 * i / 45 }')
median_of() {   # command... -> median wall time in ms over $reps runs
    local ts=()
    for ((r = 0; r < reps; r++)); do
        local t0 t1
        t0=$(date +%s%N)
        "$@" >/dev/null
        t1=$(date +%s%N)
        ts+=("$(( (t1 - t0) / 1000 ))")
    done
    printf '%s\n' "${ts[@]}" | sort -n | awk '{ a[NR] = $1 } END { m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2; printf "%.2f", m / 1000 }'
}
cli_vcrit=$(median_of "$sr" vcrit --d "$dlist" --threads 2 "${sets[@]}")
cli_map=$(median_of "$sr" map --out "$tmp/map" --no-plot --threads 2 "${sets[@]}")
cli_map_png=$(median_of "$sr" map --out "$tmp/map" --threads 2 "${sets[@]}")

coll=$(get collision_us); accerr=$(get vcrit_rel_error_max)
acc01=$(get accuracy_for_0.1pct); coll01=$(get collision_us_at_0.1pct); err01=$(get vcrit_rel_error_at_it)
ccoll=$(get collision_cpu_us); ccoll01=$(get collision_cpu_us_at_0.1pct)
v46=$(get vcrit46_ms); grid=$(get map_grid_ms); map=$(get map_total_ms)
awk -v coll="$coll" -v acc="$accerr" -v v46="$v46" -v grid="$grid" -v map="$map" \
 -v ccoll="$ccoll" -v ccoll01="$ccoll01" \
    -v acc01="$acc01" -v coll01="$coll01" -v err01="$err01" -v cv="$cli_vcrit" -v cm="$cli_map" -v cmp="$cli_map_png" 'BEGIN {
    printf "%-52s %12s %12s %12s\n", "figure", "measured", "target", "DEM codes"
    printf "%-52s %9.3g us %9s us %10s s\n", "one collision (median, wall)", coll, "10", "0.35"
    printf "%-52s %9.3g us\n", "  the same, thread CPU time", ccoll
    printf "%-52s %12.2g %12s\n", "  v_crit rel. error at this accuracy (max of 3 d)", acc, "1e-3"
    if (acc01 > 0) {
        printf "%-52s %9.3g us %9s us %10s s\n", "one collision at accuracy " acc01 " (v_crit within 0.1 %)", coll01, "10", "0.35"
        printf "%-52s %9.3g us\n", "  the same, thread CPU time", ccoll01
        printf "%-52s %12.2g\n", "  v_crit rel. error there (max of 3 d)", err01
    } else
        printf "%-52s\n", "no accuracy setting <= 1920 reaches 0.1 % on v_crit"
    printf "%-52s %9.3g ms\n", "vcrit, 46 diameters (library, 2 threads)", v46
    printf "%-52s %9.3g ms\n", "snowregime vcrit, 46 diameters (end to end)", cv
    printf "%-52s %9.3g ms\n", "map 46 x 50, grid only (library, 2 threads)", grid
    printf "%-52s %9.3g ms %9s ms %10s s\n", "map 46 x 50, grid + interface (library)", map, "20", "4"
    printf "%-52s %9.3g ms\n", "snowregime map --no-plot (end to end)", cm
    printf "%-52s %9.3g ms\n", "snowregime map with PNG (end to end)", cmp
    printf "ratios: collision / target %.3g, DEM / collision %.3g (default accuracy)\n", coll / 10, 0.35e6 / coll
    if (acc01 > 0) printf "ratios: collision at 0.1 %% / target %.3g, DEM / collision %.3g\n", coll01 / 10, 0.35e6 / coll01
    printf "ratios: map / target %.3g, DEM map / map %.3g, DEM map / snowregime map %.3g\n", map / 20, 4000 / map, 4000 / cm
}'
