#!/usr/bin/env bash
# test_stock_colliding.sh - the colliding cloud (basicKinematicCollidingCloud) on Debian's
# stock tutorials, changed only by the documented lines of doc/wallmodel.md and shortened
# (stock.sh):
# 1. DPMFoam Goldschmidt (24750 parcels of 2.5 mm, pairCollision with the
#    wallSpringSliderDashpot wall model): with the stock collision model the model says
#    once at start-up that the collision model meets the walls first, and sees no impact
#    (2 time steps); with the one extra line `collisionModel none;` (to 0.02 s, deltaT
#    1e-4) every hit on bottom is an impact (they bounce); the mass balance closes to
#    1e-6.
# 2. icoUncoupledKinematicParcelDyMFoam mixerVesselAMI2D (rotor and stator turning at
#    +-2 pi rad/s; to 0.01 s, deltaT 1e-4), `collisionModel none;` and g = 0 so that the
#    parcels rest (to 1e-3 of the blade speed: the frozen flow drags them a little)
#    until a blade reaches them; per-impact lines (DebugSwitches
#    snowWallInteraction 1): a parcel at rest hit by a blade has v_n = the blade face's
#    normal speed, the wall velocity is omega x r of its own patch (to 1e-3), every hit
#    is an impact, the balance closes.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"
[ -x /usr/bin/DPMFoam ] || { echo "SKIP: DPMFoam not installed"; exit 77; }
props=constant/kinematicCloudProperties

# 1. Goldschmidt
stock_copy lagrangian/DPMFoam/Goldschmidt "$tmp/col"
(cd "$tmp/col" && run log.blockMesh blockMesh)
shorten "$tmp/col" 4e-5
dropin "$tmp/col" kinematicCloudProperties '"(top|bottom|walls)" { type snow; }' '".*" { type none; }'
cp -r "$tmp/col" "$tmp/nocol"
(cd "$tmp/col" && run log.run DPMFoam)
[ "$(grep -c "snowWallInteraction: the cloud's collisionModel pairCollision (wallModel wallSpringSliderDashpot) meets the walls first" "$tmp/col/log.run")" = 1 ] \
    || fail "Goldschmidt: no (or more than one) collision-model notice"
grep -q 'set  collisionModel none;  in subModels of ".*/constant/kinematicCloudProperties"' "$tmp/col/log.run" \
    || fail "Goldschmidt: the notice does not say the line to change"
[ "$(snow_counts "$tmp/col/log.run" bottom)" = "0 0 0 0" ] || fail "Goldschmidt with collisions: impacts"

foamDictionary -entry subModels/collisionModel -set none "$tmp/nocol/$props" > /dev/null
shorten "$tmp/nocol" 0.02 1e-4
count_hits "$tmp/nocol/$props" "(top bottom walls)"
(cd "$tmp/nocol" && run log.run DPMFoam)
! grep -q "meets the walls first" "$tmp/nocol/log.run" || fail "Goldschmidt: notice without a collision model"
read -r ni ns nb nr <<< "$(snow_counts "$tmp/nocol/log.run" bottom)"
[ "$ni" = "$(hits "$tmp/nocol" kinematicCloud bottom)" ] \
    || fail "Goldschmidt: $ni impacts on bottom, $(hits "$tmp/nocol" kinematicCloud bottom) hits"
# (2.5 mm parcels, ten times the regime map's largest diameter: they bounce until they
# slow down in the settled bed, after 0.03 s)
[ "$ni" -gt 0 ] && [ $((ns + nb + nr)) = "$ni" ] || fail "Goldschmidt: impacts/sticks/bounces $ni/$ns/$nb"
[ -f "$tmp/nocol/0.02/kinematicCloud:snowDeposit" ] || fail "Goldschmidt: no deposit field"
check_balance "$tmp/nocol/log.run" kinematicCloud
echo "Goldschmidt: notice with pairCollision (0 impacts); collisionModel none: bottom impacts/sticks/bounces $ni/$ns/$nb = hits"

# 2. mixerVesselAMI2D
if [ -x /usr/bin/icoUncoupledKinematicParcelDyMFoam ] && command -v m4 > /dev/null; then
    m="$tmp/mixer"
    stock_copy lagrangian/icoUncoupledKinematicParcelDyMFoam/mixerVesselAMI2D "$m"
    (cd "$m" && m4 system/blockMeshDict.m4 > system/blockMeshDict && run log.blockMesh blockMesh)
    shorten "$m" 0.01 1e-4
    dropin "$m" kinematicCloudProperties '"(rotor|stator)" { type snow; }' '".*" { type none; }'
    foamDictionary -entry subModels/collisionModel -set none "$m/$props" > /dev/null
    foamDictionary -entry value -set "(0 0 0)" "$m/constant/g" > /dev/null
    foamDictionary -entry DebugSwitches -set "{ snowWallInteraction 1; }" "$m/system/controlDict" > /dev/null
    count_hits "$m/$props" "(rotor stator)"
    (cd "$m" && run log.run icoUncoupledKinematicParcelDyMFoam)
    omega() { foamDictionary -entry "multiSolidBodyMotionSolverCoeffs/$1/rotatingMotionCoeffs/omega" \
        -value "$m/constant/dynamicMeshDict" | sed 's/;.*//'; }
    wr=$(omega rotor); ws=$(omega stator)
    n=0
    for p in rotor stator; do
        ni=$(snow_counts "$m/log.run" "$p" | cut -d' ' -f1)
        [ "$ni" = "$(hits "$m" kinematicCloud "$p")" ] || fail "mixer $p: $ni impacts, $(hits "$m" kinematicCloud "$p") hits"
        n=$((n + ni))
    done
    [ "$n" -gt 0 ] || fail "mixer: no impact"
    [ -f "$m/0.01/kinematicCloud:snowDeposit" ] || fail "mixer: no deposit field"
    # impact lines of parcels at rest: x, n, U, Uwall, vn
    res=$(grep "^snowWallInteraction: impact patch" "$m/log.run" | tr '()' '  ' | awk -v wr="$wr" -v ws="$ws" '
        { for (i = 1; i <= NF; i++) k[$i] = i
          p = $4; w = (p == "rotor" ? wr : ws)
          x = $(k["x"] + 1); y = $(k["x"] + 2)
          nx = $(k["n"] + 1); ny = $(k["n"] + 2); nz = $(k["n"] + 3)
          ux = $(k["U"] + 1); uy = $(k["U"] + 2); uz = $(k["U"] + 3)
          wx = $(k["Uwall"] + 1); wy = $(k["Uwall"] + 2); wz = $(k["Uwall"] + 3)
          vn = $(k["vn"] + 1)
          ex = -w * y; ey = w * x                          # omega x r
          e = sqrt(ex * ex + ey * ey)
          # only parcels at rest (the frozen flow drags them at < 1e-3 of the wall speed)
          if (sqrt(ux * ux + uy * uy + uz * uz) > 1e-3 * e) next
          dw = sqrt((wx - ex) ^ 2 + (wy - ey) ^ 2 + wz ^ 2) / e
          want = -(ex * nx + ey * ny)                      # the face normal speed
          dv = vn - want; if (dv < 0) dv = -dv; dv /= e
          if (dw > mw) mw = dw; if (dv > mv) mv = dv
          if (want / e > 0.9) nf++                         # blade faces moving head-on
          n++ }
        END { printf "%d %d %.3g %.3g\n", n, nf, mw, mv }')
    read -r nrest nhead ew ev <<< "$res"
    [ "$nrest" -gt 0 ] || fail "mixer: no impact of a parcel at rest"
    awk -v a="$ew" -v b="$ev" 'BEGIN { exit !(a <= 1e-3 && b <= 1e-3) }' \
        || fail "mixer: wall velocity off omega x r by $ew, v_n off the face normal speed by $ev"
    check_balance "$m/log.run" kinematicCloud
    echo "mixer: $n impacts, $nrest of parcels at rest ($nhead head-on): |Uwall - omega x r| / |omega x r| <= $ew, |v_n - (omega x r).n| / |omega x r| <= $ev"
fi
echo PASS
