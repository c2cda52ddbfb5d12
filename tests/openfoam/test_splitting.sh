#!/usr/bin/env bash
# test_splitting.sh - the parcelSplitting cloud function object on the box case
# (tests/openfoam/box): seven force-free parcels (no drag, no dispersion) whose
# paths are deterministic, so every copy of a split parcel meets the fate of its
# original. Splitting must therefore leave the deposit unchanged to rounding
# (it is unbiased, and here exactly so) while multiplying the impacts.
#
# Region: the second cell layer (centres at y = 0.0375), factor 20. Parcels p1-p3
# (10, 40, 20 um, from y = 0.07 at -1 m/s) cross it 0.05 s before they reach the
# wall; p4-p7 start below it and are never split (splitting acts at the end of a
# step, on the parcels then in the region). The reference mass is the mean
# injected parcel mass, m_ref = 920 pi/6 <d^3>, <d^3> = (1+64+8+1+3.375+1+1)/7 um^3
# (10, 40, 20, 10, 15, 10, 10 um); a parcel of mass m becomes n = round(20 m / m_ref)
# copies: p1 -> 2, p2 -> 113, p3 -> 14 (126 copies made). With the reference
# fates (p1 sticks, p2 bounces, p3 is ripped off; p4-p7: 2 sticks, 2 bounces) the
# split run has 2+113+14+4 = 133 impacts, 4 sticks, 115 bounces, 14 rip-offs and
# exactly the reference deposit. Checked serial, with mpirun -np 2 and across a
# restart, the maxParcels cap (before and within a step), the maxCopies cap (a parcel
# too heavy to split stays whole; copies are not split again), plus the input errors
# as FatalIOErrors (regions in dictionary form and a region named twice among them).
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
[ -f "$top/platforms/lib/libparcelSplitting.so" ] || { echo "SKIP: libparcelSplitting.so not built (run ./Allwmake)"; exit 77; }

lower="box (-1 0.025 -1) (1 0.06 1);"
prep() {  # prep CASE [FACTOR [REGION [EXTRA]]]: the box, with splitting when FACTOR is given
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    if [ -n "${2:-}" ]; then
        split_with "$1" "regions ( lower { ${3:-$lower} factor $2; } ); ${4:-}"
    fi
    (cd "$1" && run log.blockMesh blockMesh)
}
split_with() {  # split_with CASE BODY: cloudFunctions { split { type parcelSplitting; BODY } }
    foamDictionary -entry libs -set '("libsnowWallInteraction.so" "libparcelSplitting.so")' \
        "$1/system/controlDict" > /dev/null
    foamDictionary -entry cloudFunctions -set "{ split { type parcelSplitting; $2 } }" \
        "$1/constant/kinematicCloudProperties" > /dev/null
}
deposit_sum() { deposit_values "$1" wall | awk '{ s += $1 * 6.25e-04 } END { printf "%.12g", s }'; }
same_field() {  # same_field FILE_A FILE_B: per-face values equal within 1e-9 relative
    paste <(deposit_values "$1" wall) <(deposit_values "$2" wall) |
        awk '{ d = $1 - $2; if (d < 0) d = -d; m = ($1 > 0) ? $1 : -$1; if (d > 1e-9 * m + 1e-300) bad++; n++ }
             END { exit !(n == 16 && !bad) }'
}

# reference: no splitting
prep "$tmp/ref"
(cd "$tmp/ref" && run log.run icoUncoupledKinematicParcelFoam)
ref="$tmp/ref/0.1/kinematicCloud:snowDeposit"
[ "$(series_last "$tmp/ref" 0 | cut -d' ' -f2-5)" = "7 3 3 1" ] || fail "reference totals: $(series_last "$tmp/ref" 0)"

# expected copies of p1-p3 from the rule n = round(20 m / m_ref)
want_copies=$(awk 'BEGIN { split("10 40 20 10 15 10 10", d, " "); s = 0
    for (i = 1; i <= 7; i++) s += d[i]^3; r = s / 7
    for (i = 1; i <= 3; i++) n += int(20 * d[i]^3 / r + 0.5); print n }')
[ "$want_copies" = 129 ] || fail "expected p1-p3 to make 129 parcels by the rule, computed $want_copies"

# 1. serial with splitting
prep "$tmp/split" 20
(cd "$tmp/split" && run log.run icoUncoupledKinematicParcelFoam)
line=$(series_last "$tmp/split" 0)
[ "$(echo "$line" | cut -d' ' -f2-5)" = "133 4 115 14" ] \
    || fail "split: totals '$(echo "$line" | cut -d' ' -f2-5)', expected '133 4 115 14' ($line)"
grep -q "parcelSplitting split: .* (totals 3, +126)" "$tmp/split/log.run" \
    || fail "split: log does not report 3 parcels split into 129 (+126)"
same_field "$ref" "$tmp/split/0.1/kinematicCloud:snowDeposit" \
    || fail "split: deposit field differs from the reference ($(deposit_sum "$ref") vs $(deposit_sum "$tmp/split/0.1/kinematicCloud:snowDeposit") kg)"
grep -q "nCopies *126;" "$tmp/split/0.1/uniform/lagrangian/kinematicCloud/kinematicCloudOutputProperties" \
    || fail "split: nCopies 126 not in the cloud's output properties"
echo "serial: ok ($line; deposit $(deposit_sum "$tmp/split/0.1/kinematicCloud:snowDeposit") kg as without splitting)"

# 2. mpirun -np 2: the same
prep "$tmp/par" 20
(cd "$tmp/par" && run log.decomposePar decomposePar \
    && run log.run mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && run log.reconstructPar reconstructPar -latestTime)
[ "$(series_last "$tmp/par" 0 | cut -d' ' -f2-5)" = "133 4 115 14" ] || fail "parallel totals: $(series_last "$tmp/par" 0)"
same_field "$ref" "$tmp/par/0.1/kinematicCloud:snowDeposit" || fail "parallel: deposit field differs from the reference"
echo "parallel: ok ($(series_last "$tmp/par" 0))"

# 3. restart at 0.05 (after the splits): the restored copies are light enough not
# to be split again, the totals and the deposit are those of the uninterrupted run
prep "$tmp/restart" 20
(cd "$tmp/restart" && foamDictionary -entry endTime -set 0.05 system/controlDict > /dev/null \
    && run log.run1 icoUncoupledKinematicParcelFoam \
    && foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null \
    && run log.run2 icoUncoupledKinematicParcelFoam)
[ "$(series_last "$tmp/restart" 0.05 | cut -d' ' -f2-5)" = "133 4 115 14" ] || fail "restart totals: $(series_last "$tmp/restart" 0.05)"
! grep -q "parcelSplitting split:" "$tmp/restart/log.run2" || fail "restart: restored parcels were split again"
grep -q "nCopies *126;" "$tmp/restart/0.1/uniform/lagrangian/kinematicCloud/kinematicCloudOutputProperties" \
    || fail "restart: nCopies 126 not restored"
same_field "$ref" "$tmp/restart/0.1/kinematicCloud:snowDeposit" || fail "restart: deposit field differs from the reference"
echo "restart: ok"

# 3b. maxParcels 1: more parcels than that are in the cloud while p1-p3 cross the
# splitting layer, so nothing is split; the log says so
prep "$tmp/capped" 20 "$lower" "maxParcels 1;"
(cd "$tmp/capped" && run log.run icoUncoupledKinematicParcelFoam)
[ "$(series_last "$tmp/capped" 0 | cut -d' ' -f2-5)" = "7 3 3 1" ] || fail "maxParcels: totals $(series_last "$tmp/capped" 0)"
grep -q "parcels >= maxParcels 1: no splitting" "$tmp/capped/log.run" || fail "maxParcels: no notice in the log"
echo "maxParcels 1: ok"

# 3c. maxParcels 60 binds within the step where p1-p3 ask for 1 + 112 + 13 copies: the
# cloud never holds more than 60; p1 and p3 are split, p2 (112 copies) is left whole
# and stays whole while the cap binds; the deposit is still the reference one
prep "$tmp/cap60" 20 "$lower" "maxParcels 60;"
(cd "$tmp/cap60" && run log.run icoUncoupledKinematicParcelFoam)
most1=$(grep "Current number of parcels" "$tmp/cap60/log.run" | awk '$NF > m { m = $NF } END { print m + 0 }')
[ "$most1" -le 60 ] || fail "maxParcels 60: the cloud held $most1 parcels"
[ "$(series_last "$tmp/cap60" 0 | cut -d' ' -f2-5)" = "21 4 3 14" ] || fail "maxParcels 60: totals $(series_last "$tmp/cap60" 0), expected 21 4 3 14"
grep -q "parcelSplitting split: 1 parcels left whole: their copies would take the cloud past maxParcels 60" \
    "$tmp/cap60/log.run" || fail "maxParcels 60: no notice of the parcel left whole"
same_field "$ref" "$tmp/cap60/0.1/kinematicCloud:snowDeposit" || fail "maxParcels 60: deposit differs from the reference"
prep "$tmp/cap60par" 20 "$lower" "maxParcels 60;"
(cd "$tmp/cap60par" && run log.decomposePar decomposePar \
    && run log.run mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel \
    && run log.reconstructPar reconstructPar -latestTime)
most2=$(grep "Current number of parcels" "$tmp/cap60par/log.run" | awk '$NF > m { m = $NF } END { print m + 0 }')
[ "$most2" -le 60 ] || fail "maxParcels 60, np 2: the cloud held $most2 parcels"
same_field "$ref" "$tmp/cap60par/0.1/kinematicCloud:snowDeposit" || fail "maxParcels 60, np 2: deposit differs from the reference"
echo "maxParcels 60: ok (at most $most1 parcels, 21 4 3 14; np 2: at most $most2, same deposit)"

# 3d. maxCopies: one split makes at most maxCopies parcels. With maxCopies 100, p2
# (113 needed) is left whole and said so once; p1 and p3 give 2 + 14: 21 4 3 14 again.
# With factor 1000 (the default maxCopies 1000), p1 -> 88 and p3 -> 706 parcels of the
# target mass, p2 (5644) whole; the copies are never split again (one split line)
prep "$tmp/copies100" 20 "$lower" "maxCopies 100;"
(cd "$tmp/copies100" && run log.run icoUncoupledKinematicParcelFoam)
[ "$(series_last "$tmp/copies100" 0 | cut -d' ' -f2-5)" = "21 4 3 14" ] || fail "maxCopies 100: totals $(series_last "$tmp/copies100" 0)"
[ "$(grep -c "parcels left whole: heavier than maxCopies/F reference masses" "$tmp/copies100/log.run")" = 1 ] \
    || fail "maxCopies 100: the heavy parcel is not noticed once"
same_field "$ref" "$tmp/copies100/0.1/kinematicCloud:snowDeposit" || fail "maxCopies 100: deposit differs from the reference"
prep "$tmp/f1000" 1000
(cd "$tmp/f1000" && run log.run icoUncoupledKinematicParcelFoam)
[ "$(grep -c "parcelSplitting split: .* split into" "$tmp/f1000/log.run")" = 1 ] \
    || fail "factor 1000: parcels split in more than one step: $(grep "split into" "$tmp/f1000/log.run")"
grep -q "parcelSplitting split: 2 parcels split into 794 (totals 2, +792)" "$tmp/f1000/log.run" \
    || fail "factor 1000: $(grep "split into" "$tmp/f1000/log.run")"
same_field "$ref" "$tmp/f1000/0.1/kinematicCloud:snowDeposit" || fail "factor 1000: deposit differs from the reference"
echo "maxCopies: ok (p2 left whole; factor 1000 splits once, copies not split again)"

# 4. input errors: FatalIOErrors (exit 1, not a signal) naming the key and the value
prep "$tmp/badFactor" 0.5
expect_fatal_io "$tmp/badFactor" "region lower: factor 0.5 must be in \[1, maxCopies 1000\]"
prep "$tmp/bigFactor" 1e6
expect_fatal_io "$tmp/bigFactor" "region lower: factor 1000000 must be in \[1, maxCopies 1000\]: .* raise maxCopies (at most 1000000)"
prep "$tmp/badCopies" 20 "$lower" "maxCopies 2000000;"
expect_fatal_io "$tmp/badCopies" "parcelSplitting split: maxCopies 2000000 must be in \[2, 1000000\]"
prep "$tmp/badParcels" 20 "$lower" "maxParcels 0;"
expect_fatal_io "$tmp/badParcels" "parcelSplitting split: maxParcels 0 must be in \[1, "
prep "$tmp/badBox" 20 "box (1 0.025 -1) (-1 0.06 1);"
expect_fatal_io "$tmp/badBox" "region lower: box (1 0.025 -1) (-1 0.06 1) needs min < max"
prep "$tmp/oddBoxes" 20 "boxes ((0 0 0) (1 1 1) (2 2 2));"
expect_fatal_io "$tmp/oddBoxes" "region lower: 'boxes' holds 3 points"
prep "$tmp/noBox" 20 " "
expect_fatal_io "$tmp/noBox" "needs 'box (min) (max);'"
# regions in dictionary form are a FatalIOError naming the form (not OpenFOAM's generic
# "Attempt to return dictionary entry as a primitive", exit 134); a name given twice too
prep "$tmp/regionsDict"
split_with "$tmp/regionsDict" "regions { lower { $lower factor 20; } }"
expect_fatal_io "$tmp/regionsDict" "parcelSplitting split: 'regions' is a dictionary { ... } but must be a list in parentheses:  regions ( name { box (min) (max); factor F; } ... );"
grep -q "^file: .*/regionsDict/constant/kinematicCloudProperties.cloudFunctions.split.regions from line" \
    "$tmp/regionsDict/log.run" || fail "regionsDict: the error is not located at regions: $(grep '^file:' "$tmp/regionsDict/log.run")"
prep "$tmp/regionsWord"
split_with "$tmp/regionsWord" "regions lower;"
expect_fatal_io "$tmp/regionsWord" "'regions' must be a list in parentheses: .* got  .lower."
prep "$tmp/noRegions"
split_with "$tmp/noRegions" "maxCopies 10;"
expect_fatal_io "$tmp/noRegions" "parcelSplitting split: missing 'regions'"
prep "$tmp/notDict"
split_with "$tmp/notDict" "regions ( lower 20; );"
expect_fatal_io "$tmp/notDict" "parcelSplitting split: 'regions': region 'lower' must be followed by its dictionary { box (min) (max); factor F; }, got"
# without the ';' the error names the region (OpenFOAM's own reading would run into
# "attempt to read beyond EOF", naming nothing)
prep "$tmp/notDictEOF"
split_with "$tmp/notDictEOF" "regions ( lower 4 );"
expect_fatal_io "$tmp/notDictEOF" "parcelSplitting split: 'regions': region 'lower' must be followed by its dictionary"
prep "$tmp/noName"
split_with "$tmp/noName" "regions ( 4 );"
expect_fatal_io "$tmp/noName" "parcelSplitting split: 'regions': expected a region name, got 4"
prep "$tmp/twice"
split_with "$tmp/twice" "regions ( lower { $lower factor 20; } lower { $lower factor 2; } );"
expect_fatal_io "$tmp/twice" "parcelSplitting split: region 'lower' is given twice in 'regions'"
# every key is known: a misspelt key is an error, and so is 'box' beside 'boxes'
prep "$tmp/misKey"
split_with "$tmp/misKey" "maxCopy 10; regions ( lower { $lower factor 20; } );"
expect_fatal_io "$tmp/misKey" "parcelSplitting split: unknown key 'maxCopy'; the accepted keys are"
prep "$tmp/misRegionKey"
split_with "$tmp/misRegionKey" "regions ( lower { $lower factr 2; factor 20; } );"
expect_fatal_io "$tmp/misRegionKey" "parcelSplitting split: region lower: unknown key 'factr'; the accepted keys are"
prep "$tmp/boxAndBoxes"
split_with "$tmp/boxAndBoxes" "regions ( lower { $lower boxes ((0 0 0) (1 1 1)); factor 20; } );"
expect_fatal_io "$tmp/boxAndBoxes" "parcelSplitting split: region lower: give 'box' or 'boxes', not both"
echo "errors: ok"
echo "PASS"
