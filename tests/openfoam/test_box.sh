#!/usr/bin/env bash
# test_box.sh - snowWallInteraction on the tiny box case (tests/openfoam/box):
# seven force-free parcels whose fates follow from the fixture regime map, the
# tangential gate and the adhesion shear gate (see box/constant/kinematicCloudProperties).
# Checked: serial totals and deposit, decomposePar + mpirun -np 2 (same totals,
# same deposit), restart from t = 0.05 serial and np 2 (same final totals and
# deposit), and the FatalErrors for a missing wallShearStress field, a missing
# rhoAir and a bad regime key.
# Bookkeeping: the mass balance injected = airborne + escaped + deposited closes (the
# escapes through the open patches top/sides, counted by the cloud); with the wall an
# escape patch every impact is an escape of the cloud's own counter; errors naming the
# file and the line (a bad value in regime.coeffs), a patches entry matching no patch, a
# patch without an entry; the warning for a wall taken by a catch-all escape entry.
# Set-up inputs that could end in a SIGFPE are FatalIOErrors naming the key,
# the value and the range: buildUp coverDiameter / coverMass out of range or both
# given, tangentialGate slideLength against an oblique table without obliqueSlide, a
# different obliqueSlide, a negative slideLength, shearGate rhoAir out of range
# (expect_fatal_io of common.sh).
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"

# expected: 7 impacts, 3 sticks, 3 bounces, 1 ripoff; 3 parcels of 10 um ice stick
want_counts="7 3 3 1"
want_mass=$(awk 'BEGIN { printf "%.12g", 3 * 920 * atan2(0, -1) / 6 * 1e-15 }')
face_area=6.25e-04   # (0.1 m / 4)^2

prep() {
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    (cd "$1" && run log.blockMesh blockMesh)
}

check_series() { # CASE START: last series line at t 0.1 with the expected totals
    local line; line=$(series_last "$1" "$2")
    set -- $line
    [ "$1" = 0.1 ] || fail "series ends at t=$1, not 0.1: $line"
    [ "$2 $3 $4 $5" = "$want_counts" ] || fail "totals '$2 $3 $4 $5' != '$want_counts' ($line)"
    awk -v m="$6" -v w="$want_mass" 'BEGIN { exit !(m > 0 && (m - w) ^ 2 < (1e-9 * w) ^ 2) }' \
        || fail "deposited mass $6 != $want_mass"
}

deposit_sum() { # FIELDFILE -> sum(value * area) over the wall patch
    deposit_values "$1" wall | awk -v a="$face_area" '{ s += $1 * a } END { printf "%.12g", s }'
}

# counts by reason at t 0.1: the wall's 7 impacts are 3 stuck, 2 bounced by
# the criterion (p2 40 um and p5 15 um), 1 by the tangential gate (p6, v_t 0.8 m/s), 1
# ripped off (p7); one bounced parcel has escaped through the sides by then
want_reasons="wall snow 7 3 2 1 1 0 0
top escape 0 0 0 0 0 0 0
sides escape 1 0 0 0 0 0 1
total - 8 3 2 1 1 0 1"
check_reasons() { # CASE [TIME]: reasons.dat of the write time as expected, adding up
    local f="$1/postProcessing/kinematicCloud:snowWall/${2:-0.1}/reasons.dat"
    [ -f "$f" ] || fail "no $f"
    [ "$(grep -v '^#' "$f")" = "$want_reasons" ] || fail "reasons.dat: $(grep -v '^#' "$f" | tr '\n' '|') != $(echo "$want_reasons" | tr '\n' '|')"
    awk '!/^#/ && $2 == "snow" && $3 != $4 + $5 + $6 + $7 + $8 { exit 1 }' "$f" \
        || fail "reasons.dat: the counts by reason do not add up to the impacts"
    ! ls "$1"/postProcessing/kinematicCloud:snowWall/*/.reasons.dat.tmp > /dev/null 2>&1 \
        || fail "reasons.dat: a temporary left behind"
}

check_deposit() { # CASE: deposit at 0.1 sums to the expected mass
    local f="$1/0.1/kinematicCloud:snowDeposit" s
    [ -f "$f" ] || fail "no deposit field $f"
    s=$(deposit_sum "$f")
    awk -v m="$s" -v w="$want_mass" 'BEGIN { exit !((m - w) ^ 2 < (1e-9 * w) ^ 2) }' \
        || fail "deposit field sums to $s kg, expected $want_mass"
}

# 1. serial
prep "$tmp/serial"
(cd "$tmp/serial" && run log.run icoUncoupledKinematicParcelFoam)
check_series "$tmp/serial" 0
check_deposit "$tmp/serial"
# p7 (0.1 m/s) is the one impact below vnMin
summary="snowWall: patch wall: impacts 7, sticks 3, bounces 3, ripoffs 1, deposited mass [0-9.e-]* kg (1 impacts outside the fitted v_n range)"
tail -n 40 "$tmp/serial/log.run" | grep -q "$summary" || fail "no per-patch summary in the log"
check_reasons "$tmp/serial"
tail -n 40 "$tmp/serial/log.run" | grep -q "snowWall: patch wall by reason: stuck 3, criterion 2, tangential 1, shear 1, probability 0, escaped 0" \
    || fail "no counts by reason in the log"
tail -n 40 "$tmp/serial/log.run" | grep -q "snowWall: total: impacts 8 by reason: stuck 3, criterion 2, tangential 1, shear 1, probability 0, escaped 1" \
    || fail "no total by reason in the log"
head -n 1 "$tmp/serial/postProcessing/kinematicCloud:snowWall/0/snowWall.dat" \
    | grep -q '^# time wall:impacts wall:sticks wall:bounces wall:ripoffs wall:depositedMass\[kg\]$' \
    || fail "time series header"
# stuck parcels left the tracking: 7 injected - 3 stuck - escaped ones remain
n_end=$(grep "Current number of parcels" "$tmp/serial/log.run" | tail -1 | awk '{ print $NF }')
n_esc=$(escaped_parcels "$tmp/serial/log.run" kinematicCloud)
[ -n "$n_esc" ] && [ "$n_end" = "$((7 - 3 - n_esc))" ] || fail "parcels left: $n_end (escaped $n_esc), stuck ones not removed?"
check_balance "$tmp/serial/log.run" kinematicCloud
echo "serial: ok ($(series_last "$tmp/serial" 0))"

# 1a. the wall as an escape patch: all 7 parcels escape, 4 of them through the wall
#     (a wall: OpenFOAM does not count it, the model does), 3 through top/sides
prep "$tmp/escape"
sed -i 's/^\( *\)wall { type snow; }/\1wall { type escape; }/' "$tmp/escape/constant/kinematicCloudProperties"
grep -q 'wall { type escape; }' "$tmp/escape/constant/kinematicCloudProperties" || fail "escape: no wall entry"
(cd "$tmp/escape" && run log.run icoUncoupledKinematicParcelFoam)
[ "$(escaped_parcels "$tmp/escape/log.run" kinematicCloud)" = 7 ] \
    || fail "escape: the cloud counts $(escaped_parcels "$tmp/escape/log.run" kinematicCloud) escapes, expected 7"
grep -q "Current number of parcels *= 0$" "$tmp/escape/log.run" || fail "escape: parcels left"
check_balance "$tmp/escape/log.run" kinematicCloud
echo "escape: ok (7 escaped, balance closes)"

# 1b. stuckParcels keep: same fates, the stuck parcels stay in the cloud (inactive)
prep "$tmp/keep"
foamDictionary -entry subModels/snowWallInteractionCoeffs/stuckParcels -set keep \
    "$tmp/keep/constant/kinematicCloudProperties" > /dev/null
(cd "$tmp/keep" && run log.run icoUncoupledKinematicParcelFoam)
check_series "$tmp/keep" 0
n_keep=$(grep "Current number of parcels" "$tmp/keep/log.run" | tail -1 | awk '{ print $NF }')
[ "$n_keep" = "$((7 - n_esc))" ] || fail "stuckParcels keep: $n_keep parcels left, expected $((7 - n_esc))"
echo "keep: ok ($n_keep parcels left)"

# 2. decomposePar + mpirun -np 2 + reconstructPar
prep "$tmp/par"
(cd "$tmp/par" && run log.decomposePar decomposePar \
    && run log.run mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && run log.reconstructPar reconstructPar)
check_series "$tmp/par" 0
check_deposit "$tmp/par"
diff <(deposit_values "$tmp/serial/0.1/kinematicCloud:snowDeposit" wall) \
     <(deposit_values "$tmp/par/0.1/kinematicCloud:snowDeposit" wall) > /dev/null \
    || fail "parallel deposit field differs from the serial one"
check_reasons "$tmp/par"
echo "parallel: ok ($(series_last "$tmp/par" 0))"

# 3. restart: stop at 0.05 (2 sticks so far), continue to 0.1
prep "$tmp/restart"
(cd "$tmp/restart" && foamDictionary -entry endTime -set 0.05 system/controlDict > /dev/null \
    && run log.run1 icoUncoupledKinematicParcelFoam)
[ "$(series_last "$tmp/restart" 0 | cut -d' ' -f1-5)" = "0.05 4 2 2 0" ] \
    || fail "first half: $(series_last "$tmp/restart" 0)"
(cd "$tmp/restart" && foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null \
    && run log.run2 icoUncoupledKinematicParcelFoam)
check_series "$tmp/restart" 0.05
check_deposit "$tmp/restart"
diff <(deposit_values "$tmp/serial/0.1/kinematicCloud:snowDeposit" wall) \
     <(deposit_values "$tmp/restart/0.1/kinematicCloud:snowDeposit" wall) > /dev/null \
    || fail "restarted deposit field differs from the uninterrupted one"
check_reasons "$tmp/restart"
echo "restart: ok ($(series_last "$tmp/restart" 0.05))"

# 3b. parallel restart: np 2 to 0.05, np 2 on to 0.1 (per-processor totals restored)
prep "$tmp/parRestart"
(cd "$tmp/parRestart" && foamDictionary -entry endTime -set 0.05 system/controlDict > /dev/null \
    && run log.decomposePar decomposePar \
    && run log.run1 mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null \
    && run log.run2 mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && run log.reconstructPar reconstructPar -latestTime)
check_series "$tmp/parRestart" 0.05
check_deposit "$tmp/parRestart"
tail -n 40 "$tmp/parRestart/log.run2" | grep -q "$summary" || fail "parallel restart: log summary"
check_reasons "$tmp/parRestart"
echo "parallel restart: ok ($(series_last "$tmp/parRestart" 0.05))"

# 4. errors: each must stop the solver with a message naming what to fix
expect_fatal() { # CASE PATTERN
    if (cd "$1" && icoUncoupledKinematicParcelFoam > log.run 2>&1); then
        fail "$1: solver succeeded, expected a FatalError"
    fi
    grep -q "$2" "$1/log.run" || { tail -20 "$1/log.run" >&2; fail "$1: no '$2' in the error"; }
}
prep "$tmp/noTau"
foamDictionary -entry functions -remove "$tmp/noTau/system/controlDict" > /dev/null
expect_fatal_io "$tmp/noTau" "shearGate: the field 'wallShearStress' is not registered, not in the start time's folder and made by no function object"
# a field no function object makes: refused at set-up, before the function objects
# start and write postProcessing/ (a case that cannot run leaves none behind)
prep "$tmp/noField"
sed -i 's/^\( *\)roughnessFactor *0.01;/&\n\1field noSuchField;/' "$tmp/noField/constant/kinematicCloudProperties"
grep -q "^ *field noSuchField;" "$tmp/noField/constant/kinematicCloudProperties" || fail "noField: field not written"
expect_fatal_io "$tmp/noField" "shearGate: the field 'noSuchField' is not registered"
[ ! -e "$tmp/noField/postProcessing" ] || fail "noField: postProcessing/ left behind: $(find "$tmp/noField/postProcessing")"
prep "$tmp/noRho"
foamDictionary -entry subModels/snowWallInteractionCoeffs/shearGate/rhoAir -remove \
    "$tmp/noRho/constant/kinematicCloudProperties" > /dev/null
expect_fatal "$tmp/noRho" "is kinematic \[m2/s2\] (incompressible solver): add rhoAir"
prep "$tmp/badRegime"
sed -i 's/^\( *vnMin *\)0.2;/\1 9;/' "$tmp/badRegime/constant/regime.coeffs"
expect_fatal "$tmp/badRegime" "key 'vnMin': value 9 is not below vnMax 6"
# the error names the file that holds the bad line, regime.coeffs, not the including one
grep -q "^file: .*/badRegime/constant/regime.coeffs from line [0-9]* to line [0-9]*" "$tmp/badRegime/log.run" \
    || fail "badRegime: the error does not name regime.coeffs: $(grep '^file:' "$tmp/badRegime/log.run")"
prep "$tmp/badKey"
sed -i 's/^\( *mu *\)0.05;/\1 (1 2);/' "$tmp/badKey/constant/regime.coeffs"
line=$(grep -n '^ *mu ' "$tmp/badKey/constant/regime.coeffs" | cut -d: -f1)
expect_fatal "$tmp/badKey" "key 'mu': expects one number, got a list of 2"
grep -q "^file: .*/badKey/constant/regime.coeffs at line $line\." "$tmp/badKey/log.run" \
    || fail "badKey: not regime.coeffs line $line: $(grep '^file:' "$tmp/badKey/log.run")"
prep "$tmp/noMatch"
sed -i 's/"(top|sides)"/"(top|sdes)"/' "$tmp/noMatch/constant/kinematicCloudProperties"
expect_fatal "$tmp/noMatch" "no entry of patches (...) takes the patch sides (patch)"
! grep -q "local patch interaction" "$tmp/noMatch/log.run" || fail "noMatch: OpenFOAM's localInteraction message"
prep "$tmp/misspelt"
sed -i 's/^\( *\)wall { type snow; }/\1wal { type snow; }/' "$tmp/misspelt/constant/kinematicCloudProperties"
expect_fatal "$tmp/misspelt" "patches entry wal (type snow) matches no patch of the mesh"
prep "$tmp/catchAll"
sed -i 's/^\( *\)wall { type snow; }/\1".*" { type escape; }/' "$tmp/catchAll/constant/kinematicCloudProperties"
(cd "$tmp/catchAll" && run log.run icoUncoupledKinematicParcelFoam)
grep -q 'wall patch wall is taken by the entry ".\*" (type escape) of ".*constant/kinematicCloudProperties"' \
    "$tmp/catchAll/log.run" || fail "catchAll: no warning for the wall taken by the catch-all"
echo "errors: ok"

# 5. set-up inputs that could end in a SIGFPE without a message: each must be a
#    FatalIOError (exit 1, not a signal) naming the key, its value and the accepted range
prep "$tmp/base"
cpr=constant/kinematicCloudProperties
case_from_base() { cp -r "$tmp/base" "$1"; }
with_buildup() { # CASE BODY: the box with buildUp { #include "regime-snow.coeffs" BODY }
    case_from_base "$1"
    cp "$1/constant/regime.coeffs" "$1/constant/regime-snow.coeffs"
    sed -i "s/^\( *\)tangentialGate { vtMax 0.5; }/&\n\1buildUp { #include \"regime-snow.coeffs\"\n\1    $2 }/" \
        "$1/$cpr"
    grep -q "^ *$2 }" "$1/$cpr" || fail "buildUp not written into $1/$cpr"
}
for v in 0 -3.3e-05 1e+300; do
    with_buildup "$tmp/coverD$v" "coverDiameter $v;"
    expect_fatal_io "$tmp/coverD$v" \
        "buildUp: coverDiameter $v is outside the accepted range (0, 0.1\] m (the mean particle diameter"
done
line=$(grep -n "coverDiameter 0;" "$tmp/coverD0/$cpr" | cut -d: -f1)
grep -q "^file: .*/coverD0/$cpr at line $line\." "$tmp/coverD0/log.run" \
    || fail "coverDiameter 0: the error is not located at $cpr line $line: $(grep '^file:' "$tmp/coverD0/log.run")"
for v in 0 -1; do
    with_buildup "$tmp/coverM$v" "coverMass $v;"
    expect_fatal_io "$tmp/coverM$v" "buildUp: coverMass $v is outside the accepted range (0, 10000\] kg/m2"
done
with_buildup "$tmp/coverBoth" "coverMass 0.01; coverDiameter 3e-05;"
expect_fatal_io "$tmp/coverBoth" "buildUp: give coverDiameter or coverMass, not both"
# shearGate rhoAir: checked at set-up (a huge one overflowed rhoAir * tau at an impact)
case_from_base "$tmp/rhoHuge"
sed -i 's/^\( *rhoAir *\)1;/\1 1e300;/' "$tmp/rhoHuge/$cpr"
grep -q "rhoAir *1e300;" "$tmp/rhoHuge/$cpr" || fail "rhoHuge: rhoAir not set"
expect_fatal_io "$tmp/rhoHuge" "shearGate: rhoAir 1e+300 is outside the accepted range \[1e-06, 10000\] kg/m3"
# an oblique table with (SLIDE) or without obliqueSlide, and tangentialGate { GATE }
with_oblique() { # CASE SLIDE GATE
    case_from_base "$1"
    sed -i "s/^}/    obliqueVt (0 0.5 1);\n    obliqueVn (0.1 1 10);\n    obliqueDCrit (1e-4 3e-5 1e-5 5e-5 2e-5 8e-6 2e-5 1e-5 5e-6);\n    $2\n}/" \
        "$1/constant/regime.coeffs"
    sed -i "s/tangentialGate { vtMax 0.5; }/tangentialGate { $3 }/" "$1/$cpr"
    grep -q "obliqueDCrit" "$1/constant/regime.coeffs" && grep -q "tangentialGate { $3 }" "$1/$cpr" \
        || fail "$1: oblique table or gate not written"
}
with_oblique "$tmp/noSlide" "" "model regime; slideLength 1e-4;"
expect_fatal_io "$tmp/noSlide" "tangentialGate slideLength 0.0001 m: the regime's oblique table has no obliqueSlide"
with_oblique "$tmp/otherSlide" "obliqueSlide 2e-4;" "model regime; slideLength 1e-4;"
expect_fatal_io "$tmp/otherSlide" "tangentialGate slideLength 0.0001 m differs from the regime table's obliqueSlide 0.0002 m"
with_oblique "$tmp/negSlide" "obliqueSlide 1e-4;" "model regime; slideLength -1;"
expect_fatal_io "$tmp/negSlide" "tangentialGate slideLength -1 must be a finite length >= 0 m"
# the same table with its slide length stated: the case runs (the gate is on)
with_oblique "$tmp/vtShort" "obliqueSlide 1e-4;" "model regime; slideLength 1e-4; vtTable (0 0.5);"
expect_fatal_io "$tmp/vtShort" "tangentialGate vtTable has 2 speeds, the regime's oblique table 3 (obliqueVt)"
with_oblique "$tmp/slideOk" "obliqueSlide 1e-4;" "model regime; slideLength 1e-4; vtTable (0 0.5 1);"
(cd "$tmp/slideOk" && foamDictionary -entry endTime -set 0.005 system/controlDict > /dev/null \
    && run log.run icoUncoupledKinematicParcelFoam)
echo "set-up inputs: ok (buildUp cover numbers, slideLength against obliqueSlide)"
# 6. no silent change of meaning: every key of the coefficients is
#    known to the model it belongs to, given lists are not empty; the error names the
#    key, where it is, and the accepted keys
with_buildup "$tmp/misCover" "coverDiamter 3e-5;"
expect_fatal_io "$tmp/misCover" "buildUp: unknown key 'coverDiamter'; the accepted keys are active regime coverMass coverDiameter patches"
line=$(grep -n "coverDiamter" "$tmp/misCover/$cpr" | cut -d: -f1)
grep -q "^file: .*/misCover/$cpr at line $line\." "$tmp/misCover/log.run" \
    || fail "misCover: the error is not located at $cpr line $line: $(grep '^file:' "$tmp/misCover/log.run")"
with_oblique "$tmp/misSlide" "obliqueSlide 1e-4;" "model regime; slidLength 1e-4;"
expect_fatal_io "$tmp/misSlide" "tangentialGate (model regime): unknown key 'slidLength'"
with_oblique "$tmp/vtRegime" "obliqueSlide 1e-4;" "model regime; vtMax 0.5;"
expect_fatal_io "$tmp/vtRegime" "tangentialGate (model regime): unknown key 'vtMax' (the regime gate takes d_crit(v_n, v_t) from the oblique table"
case_from_base "$tmp/extraKey"
sed -i 's/^\( *\)tangentialGate { vtMax 0.5; }/&\n\1stickParcels keep;/' "$tmp/extraKey/$cpr"
expect_fatal_io "$tmp/extraKey" "snowWallInteractionCoeffs: unknown key 'stickParcels'; the accepted keys are patches regime stuckParcels"
case_from_base "$tmp/gateValue"
sed -i 's/tangentialGate { vtMax 0.5; }/tangentialGate 0.5;/' "$tmp/gateValue/$cpr"
expect_fatal_io "$tmp/gateValue" "tangentialGate is not a sub-dictionary"
case_from_base "$tmp/shearKey"
sed -i 's/^\( *\)roughnessFactor *0.01;/&\n\1tauCrit 0.1;/' "$tmp/shearKey/$cpr"
grep -q "^ *tauCrit 0.1;" "$tmp/shearKey/$cpr" || fail "shearKey: tauCrit not written"
expect_fatal_io "$tmp/shearKey" "shearGate (model adhesion): unknown key 'tauCrit'"
with_buildup "$tmp/emptyBuild" "coverMass 0.01; patches ();"
expect_fatal_io "$tmp/emptyBuild" "buildUp: the patches list is empty"
case_from_base "$tmp/emptyPatches"
python3 - "$tmp/emptyPatches/$cpr" <<'PY'
import re, sys
p = sys.argv[1]; s = open(p).read()
s2 = re.sub(r"patches\s*\(.*?\);", "patches ();", s, count=1, flags=re.S)
assert s2 != s
open(p, "w").write(s2)
PY
expect_fatal_io "$tmp/emptyPatches" "the patches list is empty: give every boundary patch a type"
# snowNearWall: a depositionClosure given as a value is an error, not "no closure"
case_from_base "$tmp/nwClosure"
foamDictionary -entry cloudFunctions -set "{ nw { type snowNearWall; patches (wall); depositionClosure 1; } }" \
    "$tmp/nwClosure/$cpr" > /dev/null
expect_fatal_io "$tmp/nwClosure" "snowNearWall: depositionClosure is not a sub-dictionary"
# snowNearWall: the wall layer's velocity scale is one of three words
case_from_base "$tmp/nwScale"
foamDictionary -entry cloudFunctions -set "{ nw { type snowNearWall; patches (wall); velocityScale maximum; } }" \
    "$tmp/nwScale/$cpr" > /dev/null
expect_fatal_io "$tmp/nwScale" "snowNearWall: velocityScale 'maximum' is not max, wallCell, wallShear or turbulence"
# snowNearWall on a laminar flow would walk with k = epsilon = 0: dispersion none without
# a word; refused at set-up
case_from_base "$tmp/nwLaminar"
foamDictionary -entry cloudFunctions -set "{ nw { type snowNearWall; patches (wall); } }" \
    "$tmp/nwLaminar/$cpr" > /dev/null
expect_fatal_io "$tmp/nwLaminar" "snowNearWall: the flow is laminar (simulationType laminar in"
! grep -q "^Time = " "$tmp/nwLaminar/log.run" || fail "nwLaminar: refused only after a time step"
# the #included regime file with a key or the block twice: OpenFOAM merged them (the
# later won) where the C loader refuses; refused with the file and the key
case_from_base "$tmp/dupKey"
sed -i 's/^\( *vnMax .*\)$/&\n    vnMax 5.0;/' "$tmp/dupKey/constant/regime.coeffs"
[ "$(grep -c '^ *vnMax ' "$tmp/dupKey/constant/regime.coeffs")" = 2 ] || fail "dupKey: vnMax not doubled"
expect_fatal_io "$tmp/dupKey" "regime file .*dupKey/constant/regime.coeffs: duplicate entry: vnMax"
line=$(grep -n '^ *vnMax 5.0;' "$tmp/dupKey/constant/regime.coeffs" | cut -d: -f1)
grep -q "^file: .*/dupKey/constant/regime.coeffs at line $line\." "$tmp/dupKey/log.run" \
    || fail "dupKey: not regime.coeffs line $line: $(grep '^file:' "$tmp/dupKey/log.run")"
case_from_base "$tmp/dupBlock"
printf 'regime { version 1; }\n' >> "$tmp/dupBlock/constant/regime.coeffs"
expect_fatal_io "$tmp/dupBlock" "regime file .*dupBlock/constant/regime.coeffs: duplicate entry: regime"
echo "unknown keys and empty lists: ok"

# 6. the rebound: `rebound table` needs the regime file's tables; a file with
#    them bounces with them (the log says so), the same sticks and counts
case_from_base "$tmp/rbNoTable"
sed -i 's/^\( *\)tangentialGate { vtMax 0.5; }/&\n\1rebound table;/' "$tmp/rbNoTable/$cpr"
expect_fatal_io "$tmp/rbNoTable" "rebound 'table': the regime map has no rebound table"
case_from_base "$tmp/rbBad"
sed -i 's/^\( *\)tangentialGate { vtMax 0.5; }/&\n\1rebound kernel;/' "$tmp/rbBad/$cpr"
expect_fatal_io "$tmp/rbBad" "rebound 'kernel' is not auto, table or classic"
case_from_base "$tmp/rbTable"
sed -i 's/^}/    reboundD (1e-6 1e-4);\n    reboundVn (0.1 10);\n    reboundEn (0.5 0.5 0.5 0.5);\n}/' \
    "$tmp/rbTable/constant/regime.coeffs"
sed -i 's/^\( *\)tangentialGate { vtMax 0.5; }/&\n\1rebound table;/' "$tmp/rbTable/$cpr"
(cd "$tmp/rbTable" && run log.run icoUncoupledKinematicParcelFoam)
grep -q "regime .*e_n kernel table 2 x 2 (d 1e-06..0.0001 m, v_n 0.1..10 m/s), e_t 1;" "$tmp/rbTable/log.run" \
    || fail "rbTable: the log does not describe the rebound table"
check_series "$tmp/rbTable" 0
echo "rebound: ok (table required, a bad word refused, a table used)"

echo "PASS"
