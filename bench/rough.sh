#!/usr/bin/env bash
# bench/rough.sh - cost of the rough wall next to the flat wall (prints figures).
#
# Usage: bench/rough.sh [--reps N] [--points LIST] [--set KEY=VALUE]...
#                       [--before REV | --no-before] [--help]
#
# Runs `snowregime map --no-plot` on the default 46 x 50 grid (10-100 um, the
# automatic speed range) on 2 threads, N repetitions (default 3), for the flat
# wall and for a lattice of 1 um asperities (square, spacing 2 um) at each
# number of impact points per cell in LIST (default 16,64; no empty item, no
# value twice, used in ascending order with a note when given otherwise), and prints the
# medians of
#   grid     the map's grid (the stick fraction of every cell) [s]
#   total    grid + the contour bisection (p = 0.1, 0.5, 0.9) + fit [s]
#   impact   grid wall time x 2 threads / impacts: CPU time per rough impact [us]
# and the ratios to the flat map. Before and after in one run: the lattice
# maps are also run with the snowregime of git revision REV (default
# d83784a, the last commit before the rough wall's adaptive step (rough_step adaptive) made it faster),
# built from `git archive REV` in a temporary folder (about 1 min), and the
# ratios before / after are printed. --no-before skips that. --set
# KEY=VALUE: a setting for every run (e.g. asperity_r=0.5e-6; it must exist
# in both revisions). Uses bin/snowregime (./Allwmake).
# Not a test: nothing is asserted.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
sr=${SNOWREGIME:-$top/bin/snowregime}
reps=3
plist=16,64
sets=()
before=d83784a
missing_value() { echo "rough.sh: $1 (see --help)" >&2; exit 2; }   # a usage error: exit 2
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        --reps) [ -n "${2:-}" ] || missing_value "--reps needs a number"; reps=$2; shift ;;
        --points) [ -n "${2:-}" ] || missing_value "--points needs a list"; plist=$2; shift ;;
        --set) [ -n "${2:-}" ] || missing_value "--set needs KEY=VALUE"; sets+=(--set "$2"); shift ;;
        --before) [ -n "${2:-}" ] || missing_value "--before needs a git revision"; before=$2; shift ;;
        --no-before) before= ;;
        *) echo "bench/rough.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[[ "$reps" =~ ^[1-9][0-9]*$ ]] || { echo "bench/rough.sh: --reps: '$reps' is not a positive integer" >&2; exit 2; }
# shellcheck source=../etc/outdir.sh
. "$top/etc/outdir.sh"
outdir_list plist rough.sh --points "$plist" num
[[ "$plist" =~ ^[1-9][0-9]*(,[1-9][0-9]*)*$ ]] || { echo "bench/rough.sh: --points: '$plist' is not a list of positive integers" >&2; exit 2; }
[ -x "$sr" ] || { echo "bench/rough.sh: $sr missing: run ./Allwmake" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
srb=
if [ -n "$before" ]; then
    git -C "$top" rev-parse -q --verify "$before^{commit}" >/dev/null \
        || { echo "bench/rough.sh: --before: '$before' is not a commit of $top (a shallow clone? use --no-before)" >&2; exit 2; }
    mkdir -p "$tmp/src"
    git -C "$top" archive "$before" | tar -x -C "$tmp/src"
    { cmake -S "$tmp/src" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
        && cmake --build "$tmp/build" -j 2 --target snowregime; } >"$tmp/build.log" 2>&1 \
        || { tail -20 "$tmp/build.log" >&2; echo "bench/rough.sh: cannot build snowregime of $before" >&2; exit 1; }
    srb=$(find "$tmp/build" -name snowregime -type f -perm -u+x | head -n 1)
    [ -x "$srb" ] || { echo "bench/rough.sh: no snowregime in the build of $before" >&2; exit 1; }
fi
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1]) }'; }

# run LABEL ARGS... -> lines "grid total impacts" per repetition in $tmp/LABEL
# (the program: $prog, bin/snowregime unless set)
prog=$sr
run() {
    local label=$1; shift
    : >"$tmp/$label"
    for _ in $(seq "$reps"); do
        "$prog" map --no-plot --threads 2 --out "$tmp/out" "${sets[@]}" "$@" >"$tmp/log" 2>&1 \
            || { cat "$tmp/log" >&2; exit 1; }
        sed -n 's/.*wall time: grid \([0-9.]*\) s (\([0-9]*\) collisions.*total \([0-9.]*\) s.*/\1 \3 \2/p' "$tmp/log" >>"$tmp/$label"
    done
}
col() { awk -v c="$2" '{ print $c }' "$tmp/$1" | median; }

echo "# bench/rough.sh on $(uname -n), $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), $reps repetitions, 46 x 50 grid, 2 threads${sets[*]:+, ${sets[*]}}${before:+, before = $before}"
run flat
fg=$(col flat 1); ft=$(col flat 2); fn=$(col flat 3)
printf "%-28s grid %9.4f s  total %9.4f s  impact %9.3f us\n" "flat wall" "$fg" "$ft" \
    "$(awk -v g="$fg" -v n="$fn" 'BEGIN { print 2e6 * g / n }')"
IFS=, read -r -a pts <<<"$plist"
for n in "${pts[@]}"; do
    run "r$n" --set wall=lattice --points "$n"
    g=$(col "r$n" 1); t=$(col "r$n" 2); k=$(col "r$n" 3)
    ia=$(awk -v g="$g" -v n="$k" 'BEGIN { print 2e6 * g / n }')
    printf "%-36s grid %9.4f s  total %9.4f s  impact %9.3f us  (grid x%.0f, total x%.0f the flat map)\n" \
        "lattice 1 um, $n points/cell" "$g" "$t" "$ia" \
        "$(awk -v a="$g" -v b="$fg" 'BEGIN { print a / b }')" "$(awk -v a="$t" -v b="$ft" 'BEGIN { print a / b }')"
    if [ -n "$srb" ]; then
        prog=$srb
        run "b$n" --set wall=lattice --points "$n"
        prog=$sr
        bg=$(col "b$n" 1); bt=$(col "b$n" 2); bk=$(col "b$n" 3)
        ib=$(awk -v g="$bg" -v n="$bk" 'BEGIN { print 2e6 * g / n }')
        printf "%-36s grid %9.4f s  total %9.4f s  impact %9.3f us  (before / now: impact x%.1f, grid x%.1f, total x%.1f)\n" \
            "  the same, $before" "$bg" "$bt" "$ib" "$(awk -v a="$ib" -v b="$ia" 'BEGIN { print a / b }')" \
            "$(awk -v a="$bg" -v b="$g" 'BEGIN { print a / b }')" "$(awk -v a="$bt" -v b="$t" 'BEGIN { print a / b }')"
    fi
done
