#!/usr/bin/env bash
# test_rib_openfoam.sh - the separated-flow benchmark, short (validation/rib.sh
# --short): the ribbed channel on the wall-function mesh, no dispersion and
# snowNearWall with the shipped closure, tau+ 10, 1500 parcels, a window of
# 4000 t+ (about 20 s). Checks: the flow separates behind the rib and
# reattaches between 3 and 12 rib heights (measured 7.2; the resolved mesh
# and the literature's ribs: doc/deposition.md); the top wall's first cell
# at y+ 15-60 and the ribbed wall's u* above the top wall's; snowNearWall on
# the smooth top wall within a factor 3 of Wood's correlation (measured 1.44);
# the floor of the recirculation (0-4 H behind the rib) gets less than 0.3
# of the V+ of the floor after reattachment (9-14 H; measured 0.02 from 1
# and 72 deposits: a model that deposited evenly would fail); the rib's front
# face gets more than the top wall (impaction; measured 22 times); the mean
# flow alone puts nothing on the top wall or the floor after the rib; the
# counts add up (the reader refuses otherwise); the tables, plot and flow
# page are written; bad options are refused before any work (exit 2,
# nothing written).
# Skipped (77) without OpenFOAM, the project's solver and wrapper or gnuplot.
# shellcheck source=openfoam_test.sh
. "$(dirname "$0")/openfoam_test.sh"
rib="$top/validation/rib.sh"

# refusals: exit 2 before any work, nothing written
mkdir "$tmp/foreign" && echo keep > "$tmp/foreign/mine.txt"
printf 'depositionClosure { bogus 1; }\n' > "$tmp/bad.coeffs"
for args in "--tau-plus 0" "--tau-plus 1e-300" "--tau-plus nan" "--tau-plus 1,,3" "--tau-plus 1,1" "--tau-plus 2000" \
            "--models foo" "--models none,none" "--parcels 0" "--parcels 1e3" "--mesh coarse" \
            "--gravity up" "--t-run 0" "--t-run 1e4" "--coeffs $tmp/none.coeffs" "--coeffs $tmp/bad.coeffs"; do
    # shellcheck disable=SC2086
    "$rib" --out "$tmp/refused" $args > "$tmp/err" 2>&1
    rc=$?
    check "refused: $args (exit 2, one message, no folder)" \
        "[ $rc -eq 2 ] && [ ! -e '$tmp/refused' ] && grep -q '^rib.sh: ' '$tmp/err'"
done
"$rib" --short --out "$tmp/foreign" > "$tmp/err" 2>&1
rc=$?
check "refused: --out onto a foreign folder (exit 2, its file kept, nothing added)" \
    "[ $rc -eq 2 ] && [ \"\$(ls -A '$tmp/foreign')\" = mine.txt ] && grep -qx keep '$tmp/foreign/mine.txt'"
"$rib" --short > "$tmp/err" 2>&1
check "refused: no --out (exit 2)" "[ $? -eq 2 ]"
for o in --tau-plus --gravity --mesh --out; do
    "$rib" --out "$tmp/refused" $o > "$tmp/err" 2>&1
    rc=$?
    check "refused: $o without its value (exit 2, named)" "[ $rc -eq 2 ] && grep -q '^rib.sh: $o needs ' '$tmp/err'"
done
# what the options multiply, estimated before any work: too much memory refused
# (84 M parcels a mesh: about 0.17 TB)
"$rib" --out "$tmp/huge" --parcels 999999 --models stochastic,gradient,none,crw,nearwall,nearwall-utau,nearwall-k \
    --tau-plus 0.1,0.2,0.3,0.5,1,2,3,5,10,20,30,50 > "$tmp/err" 2>&1
rc=$?
check "refused: an estimate above the available memory (exit 2, nothing written)" \
    "[ $rc -eq 2 ] && [ ! -e '$tmp/huge' ] && grep -q 'rib.sh: estimate: 83999916 parcels in 84 clouds per mesh' '$tmp/err' && grep -q 'more than the .* GB available' '$tmp/err'"

"$rib" --short --out "$tmp/out" > "$tmp/log" 2>&1
rc=$?
cat "$tmp/log"
check "rib.sh --short exits 0" "[ $rc -eq 0 ]"
check "the estimate line first" "head -1 '$tmp/log' | grep -q '^rib.sh: estimate: 3000 parcels in 2 clouds per mesh, 2500 steps'"
csv="$tmp/out/zones.csv"
check "zones.csv, wakes.csv, rib.md, rib.png, flow.md, wf/wall.csv written" \
    "[ -s '$csv' ] && [ -s '$tmp/out/wakes.csv' ] && [ -s '$tmp/out/rib.md' ] && [ -s '$tmp/out/rib.png' ] && [ -s '$tmp/out/flow.md' ] && [ -s '$tmp/out/wf/wall.csv' ]"
xr=$(awk -F, '$1 == "reattachment" { print $2 }' "$tmp/out/wf/wall.csv")
check "the flow reattaches 3-12 rib heights behind the rib ($xr H)" \
    "awk -v x='$xr' 'BEGIN { exit !(x + 0 > 3 && x + 0 < 12) }'"
check "the recirculation's floor shear runs back, the far floor's forward" \
    "awk -F, '\$1 == \"floor_1\" { a = \$4 } \$1 == \"floor_5\" { b = \$4 } END { exit !(a < 0 && b > 0) }' '$tmp/out/wf/wall.csv'"
flow=$(awk -F'|' '$2 ~ /wf/ { print $5 + 0, $6 + 0, $8 + 0 }' "$tmp/out/flow.md")
check "top wall y+ 15-60, ribbed wall u* above the top wall's ($flow: u_top, u*, y+)" \
    "awk -v f='$flow' 'BEGIN { split(f, a, \" \"); exit !(a[3] > 15 && a[3] < 60 && a[2] > a[1] && a[1] > 0) }'"
zone() { awk -F, -v m="$1" -v z="$2" '$2 == m && $5 == z { print $11 }' "$csv"; }
vt=$(zone nearwall top)
check "snowNearWall on the smooth top wall within a factor 3 of Wood at tau+ 10 (V+ $vt, Wood 0.045)" \
    "awk -v v='$vt' 'BEGIN { exit !(v > 0.015 && v < 0.135) }'"
w=$(awk -F, '$2 == "nearwall" { print $4, $5, $9 }' "$tmp/out/wakes.csv")
check "snowNearWall: the recirculation's floor below 0.3 of the floor after reattachment ($w: near, far, far count)" \
    "awk -v w='$w' 'BEGIN { split(w, a, \" \"); exit !(a[3] >= 20 && a[1] < 0.3 * a[2]) }'"
vf=$(zone nearwall ribFront)
check "snowNearWall: the rib's front face above the top wall ($vf against $vt)" \
    "awk -v a='$vf' -v b='$vt' 'BEGIN { exit !(a > b && b > 0) }'"
check "the mean flow alone: nothing on the top wall or the floor after the rib" \
    "awk -F, '\$2 == \"none\" && (\$5 == \"top\" || \$5 ~ /^floor_/) && \$9 + \$10 > 0 { bad = 1 } END { exit bad + 0 }' '$csv'"
check "the wall table and the deposit table give every zone the same extent (one zones file)" \
    "awk -F, 'FNR == NR { if (\$1 != \"reattachment\") w[\$1] = \$2 \",\" \$3; next } FNR > 1 { n++; if (w[\$5] != \$6 \",\" \$7) bad = 1 } END { exit !(n > 0 && !bad && w[\"floorUp\"] == \"-6,-1\" && w[\"floor_0\"] == \"0,2\") }' '$tmp/out/wf/wall.csv' '$csv'"
check "11 zones per cloud, 2 clouds" "[ \$(awk 'NR > 1' '$csv' | wc -l) -eq 22 ]"
check "nothing left beside --out" "[ -z \"\$(ls -A '$tmp' | grep -v '^out$\\|^log$\\|^err$\\|^foreign$\\|^bad.coeffs$')\" ]"
[ "$fails" -eq 0 ] && { echo PASS; exit 0; } || { echo "$fails failure(s)"; exit 1; }
