#!/usr/bin/env bash
# wake.sh - the wedge's wake over the solved flow of one or more runs: per run the
# Strouhal number of the side force, the drag and base pressure and their slowest
# mode, and how much a flow library of a given length sees of the long-run mean.
#
# Usage: validation/wake.sh [--help] [--from T0] [--to T1] [--segments K]
#                           [--library L] RUN_DIR...
#
#   RUN_DIR        a tutorials/wedge run (a copy of the case after Allrun, best with the
#                  flow solved throughout: -coupled, or a library as long as the record):
#                  postProcessing/forceCoeffs/0/coefficient.dat and basePressure,
#                  inletPressure/0/surfaceFieldValue.dat
#   --from T0      the record's start (default 0.1 s: the end of the spin-up)
#   --to T1        its end (default: the run's last solved time, the library's end
#                  with -replay, read from log.Allrun.args and system/replay)
#   --segments K   Welch's segments (default 3: half-overlapping, a third of the
#                  record's resolution, smoother)
#   --library L    the library length whose means are judged (default 0.1 s): the
#                  record cut into windows of L, their means of Cd and Cp_b against
#                  the whole record's, rms over the windows (the error a library of L
#                  makes in the mean flow the particles see)
#
# Prints a markdown table, one row per run: the record, the resolution, St of Cs's
# peak (+- half a bin), Cd and Cp_b (means; Cp_b = (p_rear - p_inlet) / (0.5 U^2), U =
# 19.444 m/s), the slowest mode holding 10 % of Cd's and of Cp_b's variance, and the rms
# of the L-window means of Cd and Cp_b about the record's mean. Exit 2 on bad usage,
# 1 when a run's tables are missing. Nothing is written.
set -euo pipefail
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
die() { echo "wake.sh: $1" >&2; exit "${2:-2}"; }
top=$(cd "$(dirname "$0")/.." && pwd)
S=$top/bin/snowwedge
[ -x "$S" ] || die "$S missing (run ./Allwmake)" 1
from=0.1 to= segs=3 lib=0.1 runs=()
num() { [[ $2 =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] || die "$1 needs a positive number, got '$2'"; }
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage; exit 0 ;;
        --from) [ $# -ge 2 ] || die "--from needs a time"; num --from "$2"; from=$2; shift ;;
        --to) [ $# -ge 2 ] || die "--to needs a time"; num --to "$2"; to=$2; shift ;;
        --segments) [ $# -ge 2 ] && [[ $2 =~ ^[1-9][0-9]*$ ]] || die "--segments needs a whole number, got '${2:-}'"; segs=$2; shift ;;
        --library) [ $# -ge 2 ] || die "--library needs a length"; num --library "$2"; lib=$2; shift ;;
        -*) die "unknown option '$1' (see --help)" ;;
        *) runs+=("$1") ;;
    esac
    shift
done
[ ${#runs[@]} -gt 0 ] || die "give at least one run folder (see --help)"
for r in "${runs[@]}"; do
    for f in postProcessing/forceCoeffs/0/coefficient.dat postProcessing/basePressure/0/surfaceFieldValue.dat \
             postProcessing/inletPressure/0/surfaceFieldValue.dat; do
        [ -s "$r/$f" ] || die "$r/$f missing" 1
    done
done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "| run | record [s] | df [Hz] | St (Cs peak) | Cd | Cp_b | Cd's slowest mode [Hz] (St) | Cp_b's slowest mode [Hz] (St) | rms of the ${lib} s means: Cd, Cp_b |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---|"
for r in "${runs[@]}"; do
    fc=$r/postProcessing/forceCoeffs/0/coefficient.dat
    pb=$r/postProcessing/basePressure/0/surfaceFieldValue.dat pi=$r/postProcessing/inletPressure/0/surfaceFieldValue.dat
    t1=$to
    if [ -z "$t1" ]; then   # the solved flow: the library's end with -replay, else the last time
        t1=$(awk '!/^#/ { t = $1 } END { print t }' "$fc")
        if [ -f "$r/system/replay" ] && ! grep -qx -- -coupled "$r/log.Allrun.args" 2>/dev/null; then
            a=$(sed -n 's/^ *start \([^;]*\);/\1/p' "$r/system/replay"); p=$(sed -n 's/^ *period \([^;]*\);/\1/p' "$r/system/replay")
            t1=$(awk -v a="$a" -v p="$p" -v t="$t1" 'BEGIN { e = a + p; print (e < t ? e : t) }')
        fi
    fi
    # Cp_b per step from the two pressure tables (the same steps)
    paste <(grep -v '^#' "$pb") <(grep -v '^#' "$pi") |
        awk 'BEGIN { print "# Time Cpb" } $1 != $3 { exit 1 } { printf "%s %.10g\n", $1, ($2 - $4) / (0.5 * 19.444^2) }' > "$tmp/cpb" ||
        die "$r: basePressure and inletPressure are not on the same steps" 1
    out=$("$S" spectrum --window "$from,$t1" --segments "$segs" "$fc" Cs "$fc" Cd "$tmp/cpb" Cpb) || exit 1
    res=$(sed -n '1s/.*df \([0-9.e+-]*\) Hz.*/\1/p' <<< "$out")
    st=$(sed -n '1s/.*; peak \([0-9.]*\) Hz (St \([0-9.]*\)).*/\2/p' <<< "$out")
    ste=$(awk -v d="$res" 'BEGIN { printf "%.3f", d / 2 * 0.12 / 19.444 }')
    mode() { sed -n "${1}s/.*lowest peak with 10 % of the variance \\([0-9.]*\\) Hz (St \\([0-9.]*\\)).*/\\1 (\\2)/p" <<< "$out"; }
    means=$(awk -v a="$from" -v b="$t1" -v L="$lib" '
        FNR == 1 { k++ } /^#/ { next }
        { t = $1; if (t <= a || t > b) next; w = int((t - a) / L - 1e-9)
          if (k == 1) { x = $2; s1 += x; n1++; ws1[w] += x; wn1[w]++ } else { x = $2; s2 += x; n2++; ws2[w] += x; wn2[w]++ } }
        END { m1 = s1 / n1; m2 = s2 / n2; nw = int((b - a) / L + 1e-9)
              for (w = 0; w < nw; w++) { d1 = ws1[w] / wn1[w] - m1; d2 = ws2[w] / wn2[w] - m2; q1 += d1 * d1; q2 += d2 * d2 }
              printf "%.4f %.4f %.4f %.4f %d", m1, m2, sqrt(q1 / nw), sqrt(q2 / nw), nw }' \
        <(grep -v '^#' "$fc" | awk '{ print $1, $2 }') "$tmp/cpb")
    read -r cd cpb cdr cpbr nw <<< "$means"
    spread="$cdr, $cpbr ($nw windows)"; [ "$nw" -ge 2 ] || spread="- (fewer than 2 windows)"
    printf '| %s | %s .. %s | %s | %s +- %s | %s | %s | %s | %s | %s |\n' "$(basename "$r")" "$from" "$t1" "$res" \
        "$st" "$ste" "$cd" "$cpb" "$(mode 2)" "$(mode 3)" "$spread"
done
