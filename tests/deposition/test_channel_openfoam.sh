#!/usr/bin/env bash
# test_channel_openfoam.sh - the deposition benchmark, short (validation/deposition.sh
# --short): the channel on the wall-function mesh, the snowNearWall treatment
# with the shipped closure, tau+ 1 and 10, 1000 parcels, a window of 8000 wall
# units (about 20 s). Checks: V+ within a factor 3 of Wood's correlation at both
# tau+ (the benchmark's band; the statistical error at these counts is about 15 %),
# V+ at tau+ 10 from tracked deposits (the closure gives nothing there) and at
# tau+ 1 from the closure; the table and plot are written; nothing is left
# beside --out; --re-tau and --interpolation out of their ranges refused (exit 2,
# nothing written). Skipped (77) without OpenFOAM, the project's solver and wrapper,
# bin/snowdeposit or gnuplot.
# shellcheck source=openfoam_test.sh
. "$(dirname "$0")/openfoam_test.sh"
[ -x "$top/bin/snowdeposit" ] || { echo "bin/snowdeposit missing: skipped"; exit 77; }

"$top/validation/deposition.sh" --short --out "$tmp/out" > "$tmp/log" 2>&1
rc=$?
cat "$tmp/log"
check "deposition.sh --short exits 0" "[ $rc -eq 0 ]"
csv="$tmp/out/vplus.csv"
check "vplus.csv, vplus.md, vplus.png written" "[ -s '$csv' ] && [ -s '$tmp/out/vplus.md' ] && [ -s '$tmp/out/vplus.png' ]"
row() { awk -F, -v t="$1" '$2 == "nearwall" && $3 + 0 == t' "$csv"; }
for t in 1 10; do
    r=$(row $t)
    check "tau+ $t: a row" "[ -n '$r' ]"
    check "tau+ $t: V+ within a factor 3 of Wood ($r)" \
        "awk -F, '{ exit !(\$10 > \$12 / 3 && \$10 < 3 * \$12) }' <<< '$r'"
done
check "tau+ 10: tracked deposits, no closure" "awk -F, '{ exit !(\$6 > 50 && \$8 < 1) }' <<< '$(row 10)'"
check "tau+ 1: the closure's expected deposits carry V+" "awk -F, '{ exit !(\$8 > 3 && \$8 > 5 * \$6) }' <<< '$(row 1)'"
# the concentration outside the wall layer: the mean there at tau+ 1, below it at
# tau+ 10 (particles hover in the sublayer), and V+ on it within a factor 2 of Wood
check "tau+ 1: c_core within 10 % of 1 ($(row 1 | cut -d, -f13))" "awk -F, '{ exit !(\$13 > 0.9 && \$13 < 1.1) }' <<< '$(row 1)'"
check "tau+ 10: c_core in 0.3-0.95 ($(row 10 | cut -d, -f13))" "awk -F, '{ exit !(\$13 > 0.3 && \$13 < 0.95) }' <<< '$(row 10)'"
check "tau+ 10: V+_core = V+ / c_core within a factor 2 of Wood" \
    "awk -F, '{ exit !(\$14 > \$12 / 2 && \$14 < 2 * \$12 && (\$14 - \$10 / \$13) ^ 2 < 1e-12) }' <<< '$(row 10)'"
check "vplus.md: the table on the core concentration" "grep -q 'y+ > 30' '$tmp/out/vplus.md'"
for bad in "--re-tau 50" "--re-tau 3000" "--re-tau abc" "--re-tau" "--interpolation cell"; do
    # shellcheck disable=SC2086
    "$top/validation/deposition.sh" --out "$tmp/bad" $bad > "$tmp/log.bad" 2>&1
    rc=$?
    check "refused: $bad (exit 2, nothing written; $(head -1 "$tmp/log.bad"))" "[ $rc -eq 2 ] && [ ! -e '$tmp/bad' ]"
done
rm -f "$tmp/log.bad"
check "nothing left beside --out" "[ -z \"\$(ls -A '$tmp' | grep -v '^out$\\|^log$')\" ]"
[ "$fails" -eq 0 ] && { echo PASS; exit 0; } || { echo "$fails failure(s)"; exit 1; }
