#!/usr/bin/env bash
# test_stock.sh - Debian's stock Lagrangian example IO/fileHandler (a hopper,
# icoUncoupledKinematicParcelFoam), changed only by the lines doc/wallmodel.md
# documents (libs in controlDict; patchInteractionModel snowWallInteraction and its
# coefficients with #include "regime.coeffs"), runs with the model: the solver
# ends normally, the deposit field and the time series are written.
# (The case writes once and stops, stopAt writeNow; its 6 mm parcels meet the walls
# through the pairCollision wall model, so no parcel centre reaches a wall face.)
# Also: the library registers the model for every cloud type of the stock v1912 Lagrangian
# solvers (one typeName per parcel type; the stock runs of each family are in
# test_stock_{mppic,reacting,colliding,spray}.sh; fireFoam's basicReactingCloud is the one
# no stock case runs with an active cloud, so its registration is checked here only);
# libparcelSplitting.so registers parcelSplitting for the same 8.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
if command -v nm > /dev/null; then
    syms=$(nm -DC "$lib" | grep 'Foam::SnowWallInteraction<.*>::typeName$' || true)
    for parcel in \
        'KinematicParcel<Foam::particle>' \
        'CollidingParcel<Foam::KinematicParcel<Foam::particle> >' \
        'MPPICParcel<Foam::KinematicParcel<Foam::particle> >' \
        'ThermoParcel<Foam::KinematicParcel<Foam::particle> >' \
        'ReactingParcel<Foam::ThermoParcel<Foam::KinematicParcel<Foam::particle> > >' \
        'ReactingMultiphaseParcel<Foam::ReactingParcel<Foam::ThermoParcel<Foam::KinematicParcel<Foam::particle> > > >' \
        'ReactingHeterogeneousParcel<Foam::ReactingParcel<Foam::ThermoParcel<Foam::KinematicParcel<Foam::particle> > > >' \
        'SprayParcel<Foam::ReactingParcel<Foam::ThermoParcel<Foam::KinematicParcel<Foam::particle> > > >'; do
        grep -qF "SnowWallInteraction<Foam::KinematicCloud<Foam::Cloud<Foam::$parcel > > >::typeName" <<< "$syms" \
            || fail "libsnowWallInteraction.so registers no model for the parcel type $parcel"
    done
    [ "$(grep -c . <<< "$syms")" = 8 ] || fail "expected 8 registrations, found: $syms"
    echo "registered for 8 parcel types (kinematic, colliding, MPPIC, thermo, reacting, reacting-multiphase and coal, heterogeneous reacting, spray)"
    # parcelSplitting for the same 8 cloud types
    psyms=$(nm -DC "$top/platforms/lib/libparcelSplitting.so" | grep 'Foam::ParcelSplitting<.*>::typeName$' || true)
    for parcel in KinematicParcel CollidingParcel MPPICParcel ThermoParcel 'ReactingParcel<Foam::ThermoParcel' \
        ReactingMultiphaseParcel ReactingHeterogeneousParcel SprayParcel; do
        grep -qF "ParcelSplitting<Foam::KinematicCloud<Foam::Cloud<Foam::$parcel<" <<< "$psyms" \
            || fail "libparcelSplitting.so registers no parcelSplitting for the parcel type $parcel"
    done
    [ "$(grep -c . <<< "$psyms")" = 8 ] || fail "expected 8 parcelSplitting registrations, found: $psyms"
    echo "parcelSplitting registered for the same 8 parcel types"
fi
stock=/usr/share/doc/openfoam-examples/examples/IO/fileHandler
[ -d "$stock" ] || { echo "SKIP: $stock not installed (openfoam-examples)"; exit 77; }

c="$tmp/fileHandler"
cp -r "$stock" "$c"
find "$c" -name '*.gz' -exec gunzip {} +
# the documented lines
cp "$fixture" "$c/constant/regime.coeffs"
sed -i 's/^application .*/&\nlibs ("libsnowWallInteraction.so");/' "$c/system/controlDict"
sed -i 's/^\( *\)patchInteractionModel none;/\1patchInteractionModel snowWallInteraction;\
\1snowWallInteractionCoeffs\
\1{\
\1    #include "regime.coeffs"\
\1    patches ( "(walls|frontAndBack)" { type snow; } ".*" { type escape; } );\
\1}/' "$c/constant/kinematicCloudProperties"
grep -q 'patchInteractionModel snowWallInteraction;' "$c/constant/kinematicCloudProperties" \
    || fail "the stock case no longer has 'patchInteractionModel none;'"
# the change is exactly these lines
n=$(diff "$stock/constant/kinematicCloudProperties" "$c/constant/kinematicCloudProperties" \
    | grep -c '^[<>]' || true)
[ "$n" = 7 ] || fail "kinematicCloudProperties changed by $n lines, expected 1 replaced + 5 added"

cd "$c"
run log.blockMesh blockMesh
run log.run icoUncoupledKinematicParcelFoam
grep -q "snowWallInteraction: regime 'test fixture" log.run || fail "model not selected"
grep -q "snowWall: patch walls: impacts" log.run || fail "no per-patch summary"
grep -q "snowWallInteraction: the cloud's collisionModel pairCollision (wallModel wallLocalSpringSliderDashpot) meets the walls first" log.run \
    || fail "no collision-model notice"
t=$(foamListTimes -latestTime | tail -1)
[ -f "$t/kinematicCloud:snowDeposit" ] || fail "no deposit field in $t"
head -n 1 "postProcessing/kinematicCloud:snowWall/0/snowWall.dat" | grep -q "frontAndBack:depositedMass" \
    || fail "time series header"
echo "PASS (stock fileHandler ran to t=$t with snowWallInteraction)"
