#!/usr/bin/env bash
# test_wedge_ladder.sh - the resolution ladder end to end on the smallest meshes:
# tutorials/wedge/Allrun -test -sizes 10,20 -level N for N = -2, -1, 0, each in a
# temporary copy of the case, then post/wedge-ladder over the three runs and
# snowgci over its gci.csv. Checked: the level's block counts (sqrt(2)^N x the
# -test counts, rounded; level 0 the -test mesh itself), the cells rising from
# level to level, the time step following the cells at the same Courant number
# (maxCo 2 reached on every level; the mean step in the window shrinking from
# level to level), the replay interval a whole fraction of the library's period
# and never below maxDeltaT, results/level.txt whole (wall times of the flow and
# the clouds), the base-pressure records, the collector's outputs (every
# quantity on three levels, a verdict each, the total-error table and plot),
# Allrun's results/total_error.md saying why no -test level is judged against the
# default mesh's constant/ladder-rear-layers.csv, and --with (a stored ladder joined with one
# run gives that run the same total error as the ladder of all the runs; its
# refusals are test_snowladder_cli's, on fabricated runs).
#
# It runs three cases (measured on 2 cores shared with other jobs: 136 s in
# all at load average 2-4, 322 s at 7-8; most of it set-up and the
# post-processing of the clouds), so it is run on request only: it skips (77)
# unless SW_WEDGE_LADDER=1, e.g.
#   SW_WEDGE_LADDER=1 ctest --test-dir BUILD -R test_wedge_ladder --output-on-failure
# Skipped (77) too without OpenFOAM, the project's solver and libraries, or gnuplot.
set -u
[ "${SW_WEDGE_LADDER:-0}" = 1 ] || { echo "run on request only (SW_WEDGE_LADDER=1): skipped"; exit 77; }
top=${SW_TOP:?SW_TOP not set}
build=${SW_BUILD:?SW_BUILD not set}
L=$build/validation/convergence/snowladder
G=$build/validation/convergence/snowgci
[ -x "$L" ] && [ -x "$G" ] || { echo "snowladder / snowgci not built: skipped"; exit 77; }
. "$top/etc/openfoam-env.sh" 2>/dev/null
command -v pimpleUncoupledKinematicParcelFoam >/dev/null ||
    { echo "pimpleUncoupledKinematicParcelFoam not built (./Allwmake): skipped"; exit 77; }
[ -x "$top/bin/snowregime" ] && [ -x "$top/bin/snowphoto" ] || { echo "bin/snowregime or bin/snowphoto missing (./Allwmake): skipped"; exit 77; }
[ -f "$FOAM_USER_LIBBIN/libsnowWallInteraction.so" ] || { echo "libsnowWallInteraction.so missing: skipped"; exit 77; }
command -v gnuplot >/dev/null || { echo "gnuplot missing: skipped"; exit 77; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if git -C "$top" rev-parse >/dev/null 2>&1; then
    (cd "$top/tutorials/wedge" && git ls-files -co --exclude-standard . | sort) > "$tmp/tracked"
else
    (cd "$top/tutorials/wedge" && ./Allclean >/dev/null && find . -type f | sed 's|^\./||' | sort) > "$tmp/tracked"
fi
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }
key() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }

levels="-2 -1 0"
cells_of=() dt_of=()
for n in $levels; do
    w="$tmp/level$n"
    mkdir -p "$w"
    (cd "$top/tutorials/wedge" && tar cf - -T "$tmp/tracked") | (cd "$w" && tar xf -)
    start=$(date +%s)
    SNOWWALL_TOP="$top" "$w/Allrun" -test -sizes 10,20 -level "$n" > "$tmp/allrun$n.log" 2>&1
    rc=$?
    echo "Allrun -test -sizes 10,20 -level $n: exit $rc in $(( $(date +%s) - start )) s"
    [ $rc = 0 ] || { tail -30 "$tmp/allrun$n.log"; fails=$((fails+1)); continue; }
    lt="$w/results/level.txt"
    check "level $n: results/level.txt" "[ -s '$lt' ] && [ \"\$(key level '$lt')\" = '$n' ]"
    sed 's/^/     /' "$lt"
    # the block counts: sqrt(2)^n x the -test counts (8 12 16 12 7), rounded half up
    # (level -2: 4 6 8 6 4, 7 / 2 = 3.5 -> 4)
    want=$(awk -v n="$n" 'BEGIN { split("nxUp nxBody nxDown nBody nOut", k, " "); split("8 12 16 12 7", c, " ")
        f = (n % 2 == 0) ? 2 ^ (n / 2) : sqrt(2) ^ n
        for (i = 1; i <= 5; i++) { m = int(c[i] * f + 0.5); if (m < 1) m = 1; printf "%s %d; ", k[i], m } }')
    [ "$n" != -2 ] || check "level -2: the counts of the rule (nOut 7 / 2 rounds up)" "[ '${want% }' = 'nxUp 4; nxBody 6; nxDown 8; nBody 6; nOut 4;' ]"
    check "level $n: block counts ${want% }" "grep -qF -- \"${want% }\" '$tmp/allrun$n.log'"
    cells=$(key cells "$lt")
    check "level $n: cells of checkMesh ($cells)" "grep -Eq \"^ *cells: *$cells\$\" '$w/log.checkMesh'"
    [ "$n" != 0 ] || check "level 0: the -test mesh with its rear layers (22 608 + 5 x 144 = 23 328 cells)" "[ '$cells' = 23328 ]"
    # the step: the Courant number reaches maxCo 2 (the step is Courant-limited on every
    # level); the steps' numbers, not the initial field's printed before the first step
    cmax=$(awk '/^Time = / { s = 1 } s && /^Courant Number/ { if ($6 > m) m = $6 } END { print m }' "$w/log.pimpleUncoupledKinematicParcelFoam")
    check "level $n: largest Courant number $cmax within 2 +- 10 %" "awk -v c='$cmax' 'BEGIN { exit !(c > 1.8 && c < 2.2) }'"
    # the replay interval: a whole fraction of the period 0.05 s, at least maxDeltaT
    ri=$(key replay_interval "$lt"); md=$(key max_delta_t "$lt")
    check "level $n: replay interval $ri = 0.05 / whole, >= maxDeltaT $md" \
        "awk -v i='$ri' -v m='$md' 'BEGIN { k = 0.05 / i; exit !(k - int(k + 0.5) < 1e-6 && int(k + 0.5) - k < 1e-6 && i >= m * (1 - 1e-6)) }'"
    [ "$n" = 0 ] || check "level $n: system/levelStep maxDeltaT $md" "grep -q \"^maxDeltaT $md;\" '$w/system/levelStep'"
    [ "$n" != 0 ] || check "level 0: no system/levelStep (the default unchanged)" "[ ! -e '$w/system/levelStep' ]"
    check "level $n: wall times of the flow and the clouds" \
        "awk '\$1 == \"wall_flow_s\" && \$2 > 0 { a = 1 } \$1 == \"wall_clouds_s\" && \$2 > 0 { b = 1 } END { exit !(a && b) }' '$lt'"
    check "level $n: base pressure every step" \
        "[ \"\$(grep -vc '^#' '$w/postProcessing/basePressure/0/surfaceFieldValue.dat')\" = \"\$(grep -vc '^#' '$w/postProcessing/forceCoeffs/0/coefficient.dat')\" ]"
    cells_of[n + 2]=$cells; dt_of[n + 2]=$(key mean_delta_t "$lt")
done
if [ "$fails" = 0 ]; then
    # finer from level to level: cells x about 2.8, the mean step in the window smaller
    c0=${cells_of[0]} c1=${cells_of[1]} c2=${cells_of[2]} d0=${dt_of[0]} d1=${dt_of[1]} d2=${dt_of[2]}
    check "cells rise by 2-3.5 x a level ($c0, $c1, $c2)" \
        "awk -v a=$c0 -v b=$c1 -v c=$c2 'BEGIN { exit !(b / a > 2 && b / a < 3.5 && c / b > 2 && c / b < 3.5) }'"
    check "the mean step shrinks a level ($d0, $d1, $d2 s)" "awk -v a=$d0 -v b=$d1 -v c=$d2 'BEGIN { exit !(b < a && c < b) }'"
    "$top/tutorials/wedge/post/wedge-ladder" --snowladder "$L" --out "$tmp/ladder" \
        --run "$tmp/level-2" --run "$tmp/level-1" --run "$tmp/level0" > "$tmp/ladder.log" 2>&1
    rc=$?
    cat "$tmp/ladder.log"
    check "wedge-ladder over the three runs" "[ $rc = 0 ]"
    for f in ladder.csv ladder.md total_error.csv gci.csv total_error.png; do
        check "ladder: $f" "[ -s '$tmp/ladder/$f' ]"
    done
    nq=$(awk -F, 'NR > 1 { q[$1]++ } END { n = 0; for (k in q) if (q[k] == 3) n++; print n }' "$tmp/ladder/ladder.csv")
    # Cd, Cp_b, St, 5 regions x 3 sprays, 2 classes
    check "every quantity on the three levels ($nq of 20)" "[ '$nq' = 20 ]"
    check "a verdict per quantity in ladder.md" "[ \"\$(grep -cE '^\| [A-Za-z].* \| 3 \| ' '$tmp/ladder/ladder.md')\" = 20 ]"
    "$G" "$tmp/ladder/gci.csv" > "$tmp/gci.out" 2>&1
    check "snowgci reads gci.csv" "[ $? = 0 ] && grep -q '^quantity face-mvd20: 3 levels' '$tmp/gci.out'"
    grep -E '^\| (Cd|Cp_b|St|face-mvd20) \|' "$tmp/ladder/ladder.md"
    # Allrun's judgement against the case's constant/ladder-rear-layers.csv (the default mesh's
    # levels -1, 0, 1): no -test level is on it, each says why
    check "level -2: total_error.md not judged, level not on the ladder" \
        "grep -q '^Not judged: .*level -2 is not on the ladder' '$tmp/level-2/results/total_error.md'"
    check "level 0: total_error.md not judged, another mesh (23328 cells here)" \
        "grep -q '^Not judged: .*level 0 has 102568 cells on the ladder, 23328 here' '$tmp/level0/results/total_error.md'"
    # --with: the two coarse levels stored, level 0 given as a run: the same total
    # error for level 0 as the three runs gathered together
    grep -v ',level0,' "$tmp/ladder/ladder.csv" > "$tmp/stored.csv"
    "$top/tutorials/wedge/post/wedge-ladder" --snowladder "$L" --out "$tmp/with" --run "$tmp/level0" \
        --with "$tmp/stored.csv" > "$tmp/with.log" 2>&1
    check "wedge-ladder --with: exit 0" "[ $? = 0 ]"
    check "wedge-ladder --with: level 0's total errors equal the three-run ladder's" \
        "diff <(grep ',level0,' '$tmp/ladder/total_error.csv' | sort) <(grep ',level0,' '$tmp/with/total_error.csv' | sort)"
    # ladder.csv names its runs' family (the refusals of --with: test_snowladder_cli)
    check "ladder.csv: the family's settings (variant test, rear_layers 1)" \
        "grep -qx '# setting variant test' '$tmp/ladder/ladder.csv' && grep -qx '# setting rear_layers 1' '$tmp/ladder/ladder.csv'"
fi
echo "$fails failure(s)"
[ "$fails" = 0 ]
