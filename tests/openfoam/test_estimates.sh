#!/usr/bin/env bash
# test_estimates.sh - what stickRecords (snowWallInteraction) and parcelSplitting
# multiply, estimated at set-up from the inputs, on the box case with a patchInjection
# from `top` (parcelsPerSecond x duration parcels) and a short run:
#  1. stickRecords on `wall`, 100 parcels: the one-line estimate "at most 100 sticks";
#  2. with parcelSplitting (factor 10): at most 100 (1 + 4 x 10/3) = 1433 sticks, and
#     splitting's own line (at most 1433 parcels x 0.56 kB scaled by the parcel
#     type's size: 0.9 kB for the colliding parcel of icoUncoupledKinematicParcelFoam);
#  3. the records' upper bound (128 bytes a parcel) above the free disk, then (320
#     bytes a parcel between writes) above 80 % of MemAvailable: FatalIOErrors naming
#     stickRecords, before any step;
#  4. splitting that may hold 2e9 parcels (maxParcels 2e9, 1e9 injected at factor 10):
#     1.1 TB, above the available memory: a FatalIOError naming parcelSplitting.
# About 10 s.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
[ -f "$top/platforms/lib/libparcelSplitting.so" ] || { echo "SKIP: libparcelSplitting.so not built (run ./Allwmake)"; exit 77; }

# make_case DIR PPS [SPLITTING [N]]: the box, N (default 1) patch injections of PPS
# parcels per second from top over 0.1 s, stick records on the wall; SPLITTING: the
# body of a parcelSplitting entry
make_case() {
    cp -r "$top/tests/openfoam/box" "$1"
    cp "$fixture" "$1/constant/regime.coeffs"
    (
        cd "$1"
        snow_cloud "$(for i in $(seq 1 "${4:-1}"); do
            echo "        top$i { type patchInjection; patch top; SOI 0; duration 0.1;
            parcelsPerSecond $2; massTotal 1e-9; parcelBasisType mass; U0 (0 -1 0);
            flowRateProfile constant 1;
            sizeDistribution { type fixedValue; fixedValueDistribution { value 2e-05; } } }"; done)" "$(
            echo "        #include \"regime.coeffs\""
            echo "        patches ( wall { type snow; } \"(top|sides)\" { type escape; } );"
            echo "        stickRecords (wall);")"
        if [ -n "${3:-}" ]; then
            foamDictionary -entry libs -set '("libsnowWallInteraction.so" "libparcelSplitting.so")' \
                system/controlDict > /dev/null
            foamDictionary -entry cloudFunctions -set "{ split { type parcelSplitting; $3 } }" \
                constant/kinematicCloudProperties > /dev/null
        fi
        foamDictionary -entry functions -set '{}' system/controlDict > /dev/null
        foamDictionary -entry endTime -set 0.01 system/controlDict > /dev/null
        run log.blockMesh blockMesh
    )
}
box='regions ( all { box (-1 -1 -1) (1 1 1); factor 10; } );'

# 1. the estimate line
make_case "$tmp/one" 1000
(cd "$tmp/one" && run log.run icoUncoupledKinematicParcelFoam)
line=$(grep 'snowWallInteraction: stickRecords: at most' "$tmp/one/log.run") || fail "one: no stickRecords estimate"
echo "$line"
echo "$line" | grep -qF "at most 100 sticks (100 parcels injected; an upper bound: every parcel sticks) x 128 bytes = 0.013824 MB on disk" ||
    fail "one: the estimate is not 100 sticks x 128 bytes (+ 1 kB of header): $line"
echo "$line" | grep -q "GB free; at most .* MB of memory between writes, .* GB available" || fail "one: no disk or memory in: $line"

# 2. with splitting: the copies counted
make_case "$tmp/split" 1000 "$box"
(cd "$tmp/split" && run log.run icoUncoupledKinematicParcelFoam)
grep -qF "stickRecords: at most 1433 sticks (100 parcels injected, split up to factor 10: x (1 + 4F/3)" "$tmp/split/log.run" ||
    fail "split: $(grep 'stickRecords: at most' "$tmp/split/log.run")"
grep -q "parcelSplitting: at most 1433 parcels (injected x (1 + 4F/3), F 10; an upper bound) x [0-9.]* kB = [0-9.e-]* GB of memory" "$tmp/split/log.run" ||
    fail "split: $(grep 'parcelSplitting: at most [0-9]* parcels (' "$tmp/split/log.run")"

# 3. the records above the free disk, and above the memory: injections of 1e8 parcels
# each (one of 1e9 or more ends in a floating-point exception in OpenFOAM's own
# patchInjection), as many as make twice the machine's free disk or MemAvailable
free=$(df -Pk "$tmp" | awk 'NR == 2 { print $4 * 1024 }')
avail=$(awk '$1 == "MemAvailable:" { print $2 * 1024 }' /proc/meminfo)
n=$(awk -v f="$free" 'BEGIN { print int(2 * f / (1e8 * 128)) + 1 }')
make_case "$tmp/disk" 1e9 "" "$n"
expect_fatal_io "$tmp/disk" "stickRecords: the records may need up to"
grep -q "MB free in" "$tmp/disk/log.run" || fail "disk: the error does not give the free disk"
! grep -q '^Time = ' "$tmp/disk/log.run" || fail "disk: time steps before the refusal"
n=$(awk -v a="$avail" 'BEGIN { print int(2 * a / (1e8 * 320)) + 1 }')
if awk -v n="$n" -v f="$free" 'BEGIN { exit !(n * 1e8 * 128 < f) }'; then
    make_case "$tmp/mem" 1e9 "" "$n"
    expect_fatal_io "$tmp/mem" "stickRecords: the records held between writes may need up to"
    grep -q "GB available (MemAvailable of /proc/meminfo)" "$tmp/mem/log.run" || fail "mem: no available memory in the error"
fi

# 4. splitting above the available memory
make_case "$tmp/memory" 1e10 "maxParcels 2000000000; $box"      # 1e9 injected
expect_fatal_io "$tmp/memory" "parcelSplitting split: the cloud may hold up to 2000000000 parcels"
grep -q "GB available (MemAvailable of /proc/meminfo)" "$tmp/memory/log.run" || fail "memory: no available memory in the error"
! grep -q '^Time = ' "$tmp/memory/log.run" || fail "memory: time steps before the refusal"
echo "PASS: stickRecords and parcelSplitting estimates"
