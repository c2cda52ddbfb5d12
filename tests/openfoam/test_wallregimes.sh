#!/usr/bin/env bash
# test_wallregimes.sh - per-patch regimes of snowWallInteraction (wallRegimes)
# and a rough wall's stick-probability table, on the box case.
#   Both horizontal faces are snow walls: `wall` (y = 0) takes the regime of the
#   wallRegimes entry roughABS - the fixture's interface with a hand-written
#   probability table, p = 0.3 everywhere in 1-100 um x 0.1-10 m/s - and `top`
#   (y = 0.1) the main, sharp fixture regime. Both keep the main gates
#   (tangential gate 0.5 m/s; no shear gate here).
#   1000 force-free 10 um parcels fly at 1 m/s onto `wall` (random start points,
#   awk srand 9): its sticks / impacts must be 0.3 within 4 binomial sigma
#   (n 1000: +-0.058); three onto `top` behave as with the sharp map: 10 um at
#   1 m/s sticks, 40 um bounces, 10 um with v_t 0.8 m/s bounces (gate): 3 1 2 0.
# Checked: serial (the log lines of the entry and of the main regime), a second
# serial run gives the identical time series (the random numbers are
# reproducible), buildUp blends the entry's regime with the covered one,
# decomposePar + mpirun -np 2 (totals, ratio); the gate applies
# to the entry's regime (60 parcels with v_t 0.8 m/s onto `wall`: no stick,
# where p = 0.3 without the gate); the errors: a pattern matching no snow patch,
# a patch matched by two entries, an entry without regime, a bad table value.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

n_wall=1000

# the rough wall's regime: the fixture's interface plus the table (p = 0.3)
rough_coeffs() {
    sed -e 's/^\( *label *\).*/\1"rough test wall: p 0.3";/' -e '$d' "$fixture"
    tail -n 1 "$fixture" | grep -qx '}' || fail "fixture does not end with }"
    cat <<'EOF'
    // stick probability on a rough wall (hand-written: 0.3 everywhere)
    probabilityD      (1e-06 1e-04);
    probabilityVn     (0.1 10);
    probabilityStick  (0.3 0.3 0.3 0.3);
    probabilityPoints 64;
}
EOF
}

positions() { # NAME N VX SEED XMAX: N start points above `wall`, in constant/NAME
    awk -v n="$2" -v s="$4" -v xm="$5" -v name="$1" 'BEGIN {
        srand(s);
        printf "FoamFile { version 2.0; format ascii; class vectorField; object %s; }\n%d\n(\n", name, n
        for (i = 0; i < n; i++)
            printf "(%.6f %.6f %.6f)\n", 0.002 + (xm - 0.002) * rand(), 0.003 + 0.087 * rand(), 0.002 + 0.096 * rand()
        print ")"
    }' > "constant/$1"
}
inj() { # NAME D UX UY
    printf '        %s { type manualInjection; massTotal 0; parcelBasisType fixed; nParticle 1; SOI 0;
            positionsFile "%s"; U0 (%s %s 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value %s; } } }\n' \
        "$1" "$1" "$3" "$4" "$2"
}
prep() { # CASE [oblique]: the box with two snow walls and the parcels
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    rough_coeffs > "$1/constant/regime-rough.coeffs"
    (
        cd "$1"
        rm -f constant/p?
        sed -i 's/top    { type patch;/top    { type wall; /' system/blockMeshDict
        foamDictionary -entry functions -remove system/controlDict > /dev/null
        if [ "${2:-}" = oblique ]; then
            positions rough 60 0.8 5 0.02
        else
            positions rough "$n_wall" 0 9 0.098
        fi
        printf 'FoamFile { version 2.0; format ascii; class vectorField; object t; }\n( (0.05 0.05 0.05) )\n' \
            > constant/t
        snow_cloud "$(
            if [ "${2:-}" = oblique ]; then inj rough 1e-05 0.8 -1; else inj rough 1e-05 0 -1; fi
            inj t1 1e-05 0 1 | sed 's/"t1"/"t"/'
            inj t2 4e-05 0 1 | sed 's/"t2"/"t"/'
            inj t3 1e-05 0.8 1 | sed 's/"t3"/"t"/')" "$(
            echo "        #include \"regime.coeffs\""
            echo "        patches ( \"(wall|top)\" { type snow; } sides { type escape; } );"
            echo "        tangentialGate { vtMax 0.5; }"
            echo "        wallRegimes"
            echo "        {"
            echo "            roughABS { patches (\"wa.*\"); #include \"regime-rough.coeffs\" }"
            echo "        }")"
        run log.blockMesh blockMesh
    )
}
# check CASE: totals at 0.1; wall within 4 sigma of 0.3, top exactly 3 1 2 0
check() {
    local line; line=$(series_last "$1" 0)
    set -- "$1" $line
    [ "$2" = 0.1 ] || fail "$1: series ends at t=$2"
    [ "$3" = "$n_wall" ] || fail "$1: wall impacts $3, expected $n_wall ($line)"
    [ "$6" = 0 ] || fail "$1: wall rip-offs $6"
    [ "$(($4 + $5))" = "$3" ] || fail "$1: wall sticks $4 + bounces $5 != impacts $3"
    awk -v k="$4" -v n="$3" 'BEGIN { p = 0.3; exit !((k - n * p) ^ 2 <= 16 * n * p * (1 - p)) }' \
        || fail "$1: wall sticks $4 of $3: not 0.3 within 4 sigma"
    [ "$8 $9 ${10} ${11}" = "3 1 2 0" ] || fail "$1: top totals '$8 $9 ${10} ${11}' != '3 1 2 0'"
    # counts by reason: on wall every bounce is the draw's (p = 0.3
    # everywhere), on top one each by the criterion and the gate
    local r="$1/postProcessing/kinematicCloud:snowWall/0.1/reasons.dat"
    [ "$(awk '$1 == "wall"' "$r")" = "wall snow $3 $4 0 0 0 $5 0" ] \
        || fail "$1: reasons wall '$(awk '$1 == "wall"' "$r")' != 'wall snow $3 $4 0 0 0 $5 0'"
    [ "$(awk '$1 == "top"' "$r")" = "top snow 3 1 1 1 0 0 0" ] \
        || fail "$1: reasons top '$(awk '$1 == "top"' "$r")' != 'top snow 3 1 1 1 0 0 0'"
    echo "$4"
}
sum_reasons() { # CASE PATCH: impacts - (stuck + criterion + tangential + shear + probability)
    awk -v p="$2" '$1 == p { print $3 - ($4 + $5 + $6 + $7 + $8) }' \
        "$1/postProcessing/kinematicCloud:snowWall/0.1/reasons.dat"
}

# 1. serial
prep "$tmp/serial"
(cd "$tmp/serial" && run log.run icoUncoupledKinematicParcelFoam)
k=$(check "$tmp/serial")
log="$tmp/serial/log.run"
grep -q "snowWallInteraction: wallRegimes roughABS: patches wall; regime 'rough test wall: p 0.3' .*; stick probability table 2 x 2 (d 1e-06..0.0001 m, v_n 0.1..10 m/s; outside: the interface)$" "$log" \
    || fail "no wallRegimes line for roughABS: $(grep wallRegimes "$log" || true)"
grep -q "snowWallInteraction: main regime on the snow patches top$" "$log" || fail "no main-regime line"
grep "snowWallInteraction: regime 'test fixture" "$log" | grep -q "probability" \
    && fail "the main (sharp) regime is described with a table"
echo "serial: ok (wall $k sticks of $n_wall, top 3 1 2 0)"

# 1b. the same run again: the same random numbers, the same series
prep "$tmp/again"
(cd "$tmp/again" && run log.run icoUncoupledKinematicParcelFoam)
cmp -s "$tmp/serial/postProcessing/kinematicCloud:snowWall/0/snowWall.dat" \
       "$tmp/again/postProcessing/kinematicCloud:snowWall/0/snowWall.dat" \
    || fail "a second serial run gives another time series"
echo "reproducible: ok"

# 1c. buildUp on top of the entry's regime: the covered regime (the sharp
# fixture: 10 um at 1 m/s sticks) from one stuck parcel on (coverMass 1e-10,
# a tenth of one parcel per face): on each of the 16 wall faces the impacts
# bounce with p 0.7 until the first stick, then all stick (about 37 bounces;
# none if the bare regime were the main, sharp one)
prep "$tmp/buildup"
sed -i 's/^\( *\)tangentialGate { vtMax 0.5; }$/&\n\1buildUp { #include "regime.coeffs" coverMass 1e-10; }/' \
    "$tmp/buildup/constant/kinematicCloudProperties"
(cd "$tmp/buildup" && run log.run icoUncoupledKinematicParcelFoam)
line=$(series_last "$tmp/buildup" 0)
set -- $line
[ "$2" = "$n_wall" ] && [ "$(($3 + $4))" = "$n_wall" ] && [ "$4" -gt 0 ] && [ "$4" -lt 150 ] \
    || fail "buildUp: wall totals '$2 $3 $4 $5', expected $n_wall impacts with 1-149 bounces"
[ "$(sum_reasons "$tmp/buildup" wall)" = 0 ] || fail "buildUp: the counts by reason do not add up"
[ "$7 $8 $9 ${10}" = "3 1 2 0" ] || fail "buildUp: top totals '$7 $8 $9 ${10}' != '3 1 2 0'"
echo "buildUp over the entry's regime: ok (wall $3 sticks, $4 bounces)"

# 2. np 2
prep "$tmp/par"
(cd "$tmp/par" && run log.decomposePar decomposePar \
    && run log.run mpirun -np 2 --oversubscribe icoUncoupledKinematicParcelFoam -parallel)
k=$(check "$tmp/par")
echo "parallel: ok (wall $k sticks of $n_wall)"

# 3. the entry's regime has the main gates: v_t 0.8 > vtMax 0.5 never sticks
prep "$tmp/gate" oblique
(cd "$tmp/gate" && run log.run icoUncoupledKinematicParcelFoam)
line=$(series_last "$tmp/gate" 0)
set -- $line
[ "$2 $3 $4 $5" = "60 0 60 0" ] || fail "gate: wall totals '$2 $3 $4 $5' != '60 0 60 0'"
# the draw's candidates (u < 0.3) meet the gate: tangential; the others: the draw
read -r tg pr < <(awk '$1 == "wall" { print $6, $8 }' "$tmp/gate/postProcessing/kinematicCloud:snowWall/0.1/reasons.dat")
[ "$((tg + pr))" = 60 ] && [ "$tg" -gt 0 ] && [ "$pr" -gt 0 ] \
    || fail "gate: reasons tangential $tg + probability $pr != 60 (or one of them 0)"
echo "gate on the entry's regime: ok"

# 3b. draws fixed by the parcel: with DebugSwitches every impact's line names
#     the parcel (origin processor:id), the time step and the fate. The uninterrupted
#     serial run, a serial restart at 0.05, and the serial start continued on np 2 and on
#     np 3 (decomposePar of the cloud at 0.05) give every parcel the same fate at the same
#     step. (A run decomposed from the start draws other numbers: OpenFOAM numbers the
#     parcels per processor at injection, so there a parcel is another key.)
debug_on() { printf 'DebugSwitches { snowWallInteraction 1; }\n' >> "$1/system/controlDict"; }
fates() { # LOG...: "origProc:origId step fate" of every impact on wall, sorted
    grep -h "snowWallInteraction: impact patch wall " "$@" \
        | sed -n 's/.* parcel \([0-9]*:[0-9]*\) step \([0-9]*\) -> \([a-z]*\)$/\1 \2 \3/p' | sort
}
half() { # CASE: run to 0.05 serially
    (cd "$1" && foamDictionary -entry endTime -set 0.05 system/controlDict > /dev/null \
        && run log.run1 icoUncoupledKinematicParcelFoam \
        && foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null)
}
prep "$tmp/dserial"; debug_on "$tmp/dserial"
(cd "$tmp/dserial" && run log.run icoUncoupledKinematicParcelFoam)
fates "$tmp/dserial/log.run" > "$tmp/fates.serial"
[ "$(wc -l < "$tmp/fates.serial")" = "$n_wall" ] || fail "draws: $(wc -l < "$tmp/fates.serial") impact lines, expected $n_wall"
prep "$tmp/drestart"; debug_on "$tmp/drestart"; half "$tmp/drestart"
(cd "$tmp/drestart" && run log.run2 icoUncoupledKinematicParcelFoam)
fates "$tmp/drestart/log.run1" "$tmp/drestart/log.run2" > "$tmp/fates.restart"
cmp -s "$tmp/fates.serial" "$tmp/fates.restart" \
    || fail "draws: a restart changes $(diff "$tmp/fates.serial" "$tmp/fates.restart" | grep -c '^>') parcel fates"
for np in 2 3; do
    prep "$tmp/dnp$np"; debug_on "$tmp/dnp$np"; half "$tmp/dnp$np"
    foamDictionary -entry numberOfSubdomains -set $np "$tmp/dnp$np/system/decomposeParDict" > /dev/null
    foamDictionary -entry coeffs/n -set "($np 1 1)" "$tmp/dnp$np/system/decomposeParDict" > /dev/null
    (cd "$tmp/dnp$np" && run log.decomposePar decomposePar -latestTime \
        && run log.run2 mpirun -np $np --oversubscribe --output-filename out icoUncoupledKinematicParcelFoam -parallel)
    # each rank's output in a file of its own (mpirun --output-filename): no interleaved lines
    fates "$tmp/dnp$np/log.run1" $(find "$tmp/dnp$np/out" -name stdout) > "$tmp/fates.np$np"
    cmp -s "$tmp/fates.serial" "$tmp/fates.np$np" \
        || fail "draws: continued on np $np, $(diff "$tmp/fates.serial" "$tmp/fates.np$np" | grep -c .^>.) parcel fates differ: $(diff "$tmp/fates.serial" "$tmp/fates.np$np" | head -8 | tr "\n" "|")"
done
echo "draws fixed by the parcel: ok ($n_wall wall impacts: serial = restart = continued on np 2 = on np 3)"

# 4. errors
expect_fatal() { # CASE PATTERN
    if (cd "$1" && icoUncoupledKinematicParcelFoam > log.run 2>&1); then
        fail "$1: solver succeeded, expected a FatalError"
    fi
    grep -q "$2" "$1/log.run" || { tail -20 "$1/log.run" >&2; fail "$1: no '$2' in the error"; }
}
cpr="constant/kinematicCloudProperties"
prep "$tmp/unmatched"
sed -i 's/patches ("wa\.\*");/patches ("wa.*" nose);/' "$tmp/unmatched/$cpr"
expect_fatal "$tmp/unmatched" "wallRegimes entry 'roughABS': patch pattern 'nose' matches no snow patch"
prep "$tmp/twice"
sed -i 's/^\( *\)roughABS {/\1other { patches (wall); #include "regime.coeffs" }\n&/' "$tmp/twice/$cpr"
expect_fatal "$tmp/twice" "snow patch wall is matched by two wallRegimes entries, 'other' and 'roughABS'"
prep "$tmp/noRegime"
sed -i 's/#include "regime-rough.coeffs"//' "$tmp/noRegime/$cpr"
expect_fatal "$tmp/noRegime" "wallRegimes entry 'roughABS': missing sub-dictionary 'regime'"
prep "$tmp/badTable"
sed -i 's/probabilityStick  (0.3 0.3 0.3 0.3)/probabilityStick  (0.3 1.3 0.3 0.3)/' \
    "$tmp/badTable/constant/regime-rough.coeffs"
expect_fatal "$tmp/badTable" "wallRegimes roughABS: key 'probabilityStick': value 1.3 (entry 1) is not a probability in \[0, 1\]"
# an error in the main regime names regime.coeffs, not the wallRegimes entry's file
# (both hold the same keys at the same lines)
prep "$tmp/badMain"
sed -i 's/^\( *vnMin *\)0.2;/\1 9;/' "$tmp/badMain/constant/regime.coeffs"
expect_fatal "$tmp/badMain" "key 'vnMin': value 9 is not below vnMax 6"
grep -q "^file: .*/badMain/constant/regime.coeffs from line" "$tmp/badMain/log.run" \
    || fail "badMain: the error does not name regime.coeffs: $(grep '^file:' "$tmp/badMain/log.run")"
grep -q "^file: .*/badTable/constant/regime-rough.coeffs" "$tmp/badTable/log.run" \
    || fail "badTable: the error does not name regime-rough.coeffs: $(grep '^file:' "$tmp/badTable/log.run")"
echo "errors: ok"
echo "PASS"
