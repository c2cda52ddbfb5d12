#!/usr/bin/env bash
# test_stock_reacting.sh - the reacting cloud families on Debian's stock tutorials, each
# changed only by the documented lines of doc/wallmodel.md and shortened (stock.sh):
# 1. coalChemistryFoam simplifiedSiwek (2500 cells, to 0.01 s): coalCloud1 (coalCloud, the
#    parcel type of basicReactingMultiphaseCloud) and limestoneCloud1 (basicThermoCloud),
#    both on snowWallInteraction with top/bottom snow and the side wall `walls` an
#    escape patch. The stock case (standardWallInteraction) and the snow case record wall
#    hits on the same patches; every hit is an impact or an escape; the mass balance
#    injected = airborne + escaped + deposited + phase change + devolatilisation +
#    surface reaction closes to 1e-6 for both clouds; serial equals mpirun -np 2.
#    Both runs use dispersionModel none: the stochastic RAS dispersion draws its own
#    random numbers on each processor, so serial and parallel could not agree.
# 2. reactingParcelFoam parcelInBox (basicReactingMultiphaseCloud; one evaporating
#    droplet at rest, which never reaches a wall): the model loads, the run ends, the
#    balance with the phase change closes.
# 3. reactingHeterogenousParcelFoam rectangularDuct (basicHeterogeneousReactingCloud,
#    to 0.3 s; its parcels do not reach a wall that early): loads, ends, balance with the
#    surface reaction.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"
[ -x /usr/bin/coalChemistryFoam ] || { echo "SKIP: coalChemistryFoam not installed"; exit 77; }

# 1. coal and limestone
clouds="coalCloud1 limestoneCloud1"
stock_copy lagrangian/coalChemistryFoam/simplifiedSiwek "$tmp/stock"
(cd "$tmp/stock" && run log.blockMesh blockMesh && run log.topoSet topoSet)
shorten "$tmp/stock" 0.01
for c in $clouds; do
    foamDictionary -entry subModels/dispersionModel -set none \
        "$tmp/stock/constant/${c}Properties" > /dev/null
done
cp -r "$tmp/stock" "$tmp/snow"
for c in $clouds; do count_hits "$tmp/stock/constant/${c}Properties" "(top bottom walls)"; done
(cd "$tmp/stock" && run log.run coalChemistryFoam)

for c in $clouds; do
    dropin "$tmp/snow" "${c}Properties" '"(top|bottom)" { type snow; }' \
        'walls { type escape; }' '".*" { type none; }'
done
cp -r "$tmp/snow" "$tmp/par"
for c in $clouds; do count_hits "$tmp/snow/constant/${c}Properties" "(top bottom walls)"; done
(cd "$tmp/snow" && run log.run coalChemistryFoam)
grep -q "snowWallInteraction: regime 'test fixture" "$tmp/snow/log.run" || fail "model not selected"
[ -f "$tmp/snow/0.01/coalCloud1:snowDeposit" ] && [ -f "$tmp/snow/0.01/limestoneCloud1:snowDeposit" ] \
    || fail "no deposit fields in 0.01"

for c in $clouds; do
    for p in top bottom walls; do
        sh=$(hits "$tmp/stock" "$c" "$p"); nh=$(hits "$tmp/snow" "$c" "$p")
        if [ "$sh" -gt 0 ]; then
            [ "$nh" -gt 0 ] || fail "$c: the stock case hits $p ($sh), the snow case not"
        fi
        if [ "$p" = walls ]; then
            # every hit on the escape wall is an escaped parcel of the cloud's own counter
            [ "$(escaped_parcels "$tmp/snow/log.run" "$c")" = "$nh" ] \
                || fail "$c: $nh hits on walls but $(escaped_parcels "$tmp/snow/log.run" "$c") escaped"
            echo "$c walls: stock hits $sh; snow hits $nh = escaped"
        else
            # the two clouds print their summaries in turn: take this cloud's
            ni=$(snow_counts "$tmp/snow/log.run" "$p" "$c" | cut -d' ' -f1)
            [ "$ni" = "$nh" ] || fail "$c $p: $ni impacts but $nh wall hits"
            echo "$c $p: stock hits $sh; snow impacts $ni = hits $nh"
        fi
    done
    check_balance "$tmp/snow/log.run" "$c"
done
cloud_block "$tmp/snow/log.run" coalCloud1 | grep -q "snowWall: patch bottom: impacts [1-9]" \
    || fail "coalCloud1: no impact on bottom"
cloud_block "$tmp/snow/log.run" limestoneCloud1 | grep -q "snowWall: patch bottom: impacts [1-9]" \
    || fail "limestoneCloud1: no impact on bottom"

# np 2
run_np2 "$tmp/par" coalChemistryFoam "(2 1 1)"
for c in $clouds; do
    s=$(cloud_block "$tmp/snow/log.run" "$c" | grep "snowWall: patch" | sed 's/ deposited mass.*//')
    p=$(cloud_block "$tmp/par/log.run" "$c" | grep "snowWall: patch" | sed 's/ deposited mass.*//')
    [ "$s" = "$p" ] || fail "np 2, $c: counts differ: serial [$s] np 2 [$p]"
    # escaped and deposited mass: the reacting parcels' mass follows the gas phase,
    # which differs at round-off between serial and parallel (1e-5)
    sd=$(balance "$tmp/snow/log.run" "$c" | cut -d' ' -f3-4)
    pd=$(balance "$tmp/par/log.run" "$c" | cut -d' ' -f3-4)
    awk -v s="$sd" -v p="$pd" 'BEGIN { split(s, a, " "); split(p, b, " ")
        for (i = 1; i <= 2; i++) { d = a[i] - b[i]; if (d < 0) d = -d; if (d > 1e-5 * a[i]) exit 1 } }' \
        || fail "np 2, $c: escaped/deposited $pd, serial $sd"
    check_balance "$tmp/par/log.run" "$c"
    same_patch_field "$tmp/snow/0.01/$c:snowDeposit" "$tmp/par/0.01/$c:snowDeposit" bottom 1e-5 \
        || fail "np 2, $c: deposit field differs"
done
echo "np 2: ok (counts as serial; escaped and deposited mass, deposit fields to 1e-5)"

# 2. parcelInBox
if [ -x /usr/bin/reactingParcelFoam ]; then
    stock_copy lagrangian/reactingParcelFoam/parcelInBox "$tmp/box"
    (cd "$tmp/box" && run log.blockMesh blockMesh)
    foamDictionary -entry writePrecision -set 12 "$tmp/box/system/controlDict" > /dev/null
    dropin "$tmp/box" reactingCloud1Properties '"(inlet|outlet|walls)" { type snow; }' \
        '".*" { type none; }'
    (cd "$tmp/box" && run log.run reactingParcelFoam)
    grep -q "snowWallInteraction: regime 'test fixture" "$tmp/box/log.run" || fail "parcelInBox: model not selected"
    check_balance "$tmp/box/log.run" reactingCloud1
    t=$(cd "$tmp/box" && foamListTimes -latestTime | tail -n 1)
    [ -f "$tmp/box/$t/reactingCloud1:snowDeposit" ] || fail "parcelInBox: no deposit field in $t"
    echo "parcelInBox: ok (to t = $t)"
fi

# 3. rectangularDuct
if [ -x /usr/bin/reactingHeterogenousParcelFoam ]; then
    stock_copy lagrangian/reactingHeterogenousParcelFoam/rectangularDuct "$tmp/duct"
    (cd "$tmp/duct" && run log.blockMesh blockMesh)
    shorten "$tmp/duct" 0.3
    dropin "$tmp/duct" reactingCloud1Properties 'walls { type snow; }' '".*" { type none; }'
    (cd "$tmp/duct" && run log.run reactingHeterogenousParcelFoam)
    grep -q "snowWallInteraction: regime 'test fixture" "$tmp/duct/log.run" || fail "rectangularDuct: model not selected"
    check_balance "$tmp/duct/log.run" reactingCloud1
    [ -f "$tmp/duct/0.3/reactingCloud1:snowDeposit" ] || fail "rectangularDuct: no deposit field"
    echo "rectangularDuct: ok"
fi
echo PASS
