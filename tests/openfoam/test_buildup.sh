#!/usr/bin/env bash
# test_buildup.sh - the build-up feedback of snowWallInteraction (buildUp) on
# the box case: a face switches from the bare-wall regime to the snow-covered one
# once its own deposit reaches the covering mass.
#   bare regime: the fixture map (d_crit(1 m/s) = 30 um); covered regime: the
#   same with d_crit halved (15 um). Four force-free 20 um parcels at 1 m/s normal
#   to the wall: three on face A (arriving at 7.5, 27.5 and 47.5 ms), one on
#   face B. buildUp coverDiameter puts one monolayer (0.6046 rho d) just below
#   one parcel's mass on a face (m1 = 920 pi/6 (20 um)^3 / 6.25e-4 m2), so
#   after its first stick face A is covered and the next two bounce:
#   impacts 4, sticks 2, bounces 2, deposit m1 on A and on B.
# Checked: serial; buildUp active false (4 sticks); coverDiameter just above m1
# (face A is only partly covered: w = 0.999, almost surely bounces); np 2 and a
# restart between the first and the second impact on A give the same totals and
# deposit field; the log reports the covered faces; input errors stop the solver.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

m1=$(awk 'BEGIN { printf "%.12g", 920 * atan2(0, -1) / 6 * (20e-6)^3 / 6.25e-4 }')
dc_below=$(awk -v m="$m1" 'BEGIN { printf "%.12g", m / (atan2(0, -1) / (2 * sqrt(3)) * 2 / 3 * 920) * (1 - 1e-3) }')

pos() { # NAME X Y Z
    printf 'FoamFile { version 2.0; format ascii; class vectorField; object %s; }\n( (%s %s %s) )\n' "$1" "$2" "$3" "$4" \
        > "constant/$1"
}
inj() { # NAME
    printf '        %s { type manualInjection; massTotal 0; parcelBasisType fixed; nParticle 1; SOI 0;
            positionsFile "%s"; U0 (0 -1 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value 2e-05; } } }\n' "$1" "$1"
}
prep() { # CASE: the box with the four parcels, both regimes and buildUp
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    # the covered regime: ln d_crit - ln 2
    awk '/^ *coeffs/ { sub(/\(-10.414313/, "(" sprintf("%.9f", -10.414313 - log(2))) } { print }' \
        "$fixture" > "$1/constant/regime-snow.coeffs"
    grep -q -- "-11.10746" "$1/constant/regime-snow.coeffs" || fail "covered regime not written"
    (
        cd "$1"
        rm -f constant/p?
        pos a1 0.0125 0.0075 0.0125; pos a2 0.0125 0.0275 0.0125; pos a3 0.0125 0.0475 0.0125
        pos b1 0.0375 0.0175 0.0125
        snow_cloud "$(for n in a1 a2 a3 b1; do inj "$n"; done)" "$(
            echo "        #include \"regime.coeffs\""
            echo "        patches ( wall { type snow; } \"(top|sides)\" { type escape; } );"
            echo "        buildUp { #include \"regime-snow.coeffs\"  coverDiameter $dc_below; }")"
        foamDictionary -entry writeInterval -set 0.02 system/controlDict > /dev/null
        run log.blockMesh blockMesh
    )
}
face_value() { # FIELDFILE FACE: the deposit on wall face FACE (0-based; uniform -> that)
    deposit_values "$1" wall | awk -v f="$2" 'NR == 1 && /^uniform/ { print $2; exit } NR == f + 1 { print $1; exit }'
}
check_case() { # CASE START WANT_COUNTS: totals at 0.1, deposit on A (face 0) and B (face 4)
    local line; line=$(series_last "$1" "$2")
    set -- "$1" "$2" "$3" $line
    [ "$4" = 0.1 ] || fail "$1: series ends at t=$4"
    [ "$5 $6 $7 $8" = "$3" ] || fail "$1: totals '$5 $6 $7 $8' != '$3'"
    local f="$1/0.1/kinematicCloud:snowDeposit" a b
    a=$(face_value "$f" 0); b=$(face_value "$f" 4)
    echo "$a $b"
}
rel_ok() { awk -v x="$1" -v r="$2" 'BEGIN { exit !((x - r) ^ 2 < (1e-9 * r) ^ 2) }'; }

# 1. serial: face A covered after its first stick
prep "$tmp/serial"
(cd "$tmp/serial" && run log.run icoUncoupledKinematicParcelFoam)
read -r a b < <(check_case "$tmp/serial" 0 "4 2 2 0")
rel_ok "$a" "$m1" && rel_ok "$b" "$m1" || fail "serial deposit A $a, B $b, expected $m1 each"
grep -q "build-up on: snow-covered regime" "$tmp/serial/log.run" || fail "no build-up line in the log"
grep -q "snowWall: patch wall: faces covered 2, partly covered 0, of 16" "$tmp/serial/log.run" \
    || fail "no covered-faces line: $(grep 'faces covered' "$tmp/serial/log.run" | tail -1)"
echo "serial: ok ($(series_last "$tmp/serial" 0))"

# 1b. buildUp off: every parcel sticks
prep "$tmp/off"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/active -add false \
    "$tmp/off/constant/kinematicCloudProperties" > /dev/null
(cd "$tmp/off" && run log.run icoUncoupledKinematicParcelFoam)
read -r a b < <(check_case "$tmp/off" 0 "4 4 0 0")
rel_ok "$a" "$(awk -v m="$m1" 'BEGIN { printf "%.12g", 3 * m }')" || fail "buildUp off: A $a, expected 3 m1"
echo "off: ok"

# 1b'. buildUp patches (wall): the same as all snow patches
prep "$tmp/sel"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/patches -add "(wall)" \
    "$tmp/sel/constant/kinematicCloudProperties" > /dev/null
(cd "$tmp/sel" && run log.run icoUncoupledKinematicParcelFoam)
check_case "$tmp/sel" 0 "4 2 2 0" > /dev/null
grep -q "build-up on the snow patches wall" "$tmp/sel/log.run" || fail "patches: no selection line"
echo "patch selection: ok"

# 1c. covering mass just above one parcel: face A 99.9 % covered, the blend bounces
prep "$tmp/partly"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/coverDiameter \
    -set "$(awk -v d="$dc_below" 'BEGIN { printf "%.12g", d / (1 - 1e-3) * (1 + 1e-3) }')" \
    "$tmp/partly/constant/kinematicCloudProperties" > /dev/null
(cd "$tmp/partly" && run log.run icoUncoupledKinematicParcelFoam)
read -r a b < <(check_case "$tmp/partly" 0 "4 2 2 0")
grep -q "faces covered 0, partly covered 2, of 16" "$tmp/partly/log.run" || fail "partly: covered-faces line"
echo "partly covered: ok"

# same_deposit CASE WHAT: the wall's deposit field at 0.1 equals the serial run's
same_deposit() {
    diff <(deposit_values "$tmp/serial/0.1/kinematicCloud:snowDeposit" wall) \
         <(deposit_values "$1/0.1/kinematicCloud:snowDeposit" wall) > /dev/null \
        || fail "$2 deposit field differs from the serial, uninterrupted one"
}

# 2. np 2: the same
prep "$tmp/par"
(cd "$tmp/par" && run log.decomposePar decomposePar \
    && run log.run mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && run log.reconstructPar reconstructPar)
check_case "$tmp/par" 0 "4 2 2 0" > /dev/null
same_deposit "$tmp/par" parallel
echo "parallel: ok"

# 3. restart at 0.02: face A holds one parcel (the state is its deposit field)
prep "$tmp/restart"
(cd "$tmp/restart" && foamDictionary -entry endTime -set 0.02 system/controlDict > /dev/null \
    && run log.run1 icoUncoupledKinematicParcelFoam \
    && foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null \
    && run log.run2 icoUncoupledKinematicParcelFoam)
check_case "$tmp/restart" 0.02 "4 2 2 0" > /dev/null
same_deposit "$tmp/restart" restarted
echo "restart: ok"

# 4. errors
expect_fatal() { # CASE PATTERN
    if (cd "$1" && icoUncoupledKinematicParcelFoam > log.run 2>&1); then
        fail "$1: solver succeeded, expected a FatalError"
    fi
    grep -q "$2" "$1/log.run" || { tail -20 "$1/log.run" >&2; fail "$1: no '$2' in the error"; }
}
prep "$tmp/noRegime"
sed -i 's/#include "regime-snow.coeffs"//' "$tmp/noRegime/constant/kinematicCloudProperties"
expect_fatal "$tmp/noRegime" "buildUp: missing sub-dictionary 'regime'"
prep "$tmp/noMass"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/coverDiameter -remove \
    "$tmp/noMass/constant/kinematicCloudProperties" > /dev/null
expect_fatal "$tmp/noMass" "buildUp: give coverDiameter"
prep "$tmp/badMass"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/coverDiameter -remove \
    "$tmp/badMass/constant/kinematicCloudProperties" > /dev/null
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/coverMass -add -1 \
    "$tmp/badMass/constant/kinematicCloudProperties" > /dev/null
expect_fatal_io "$tmp/badMass" "buildUp: coverMass -1 is outside the accepted range (0, 10000\] kg/m2"
# both keys are an error (else one would win silently)
prep "$tmp/bothKeys"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/coverMass -add 0.01 \
    "$tmp/bothKeys/constant/kinematicCloudProperties" > /dev/null
expect_fatal_io "$tmp/bothKeys" "buildUp: give coverDiameter or coverMass, not both"
prep "$tmp/badSel"
foamDictionary -entry subModels/snowWallInteractionCoeffs/buildUp/patches -add "(top)" \
    "$tmp/badSel/constant/kinematicCloudProperties" > /dev/null
expect_fatal "$tmp/badSel" "buildUp patches: 'top' matches no snow patch"
echo "errors: ok"
echo "PASS"
