#!/usr/bin/env bash
# test_film.sh - a snow patch that the cloud's surface-film model takes first: Debian's
# stock reactingParcelFoam splashPanel (4000 cells, its wall film on the patch
# region0_to_wallFilmRegion_wallFilmFaces, thermoSurfaceFilm with interactionType
# splashBai), made as its Allrun.pre makes it, changed only by the documented lines of
# doc/wallmodel.md (stock.sh) and run for two time steps (the film region is made after
# the cloud, so the check runs at the end of the first step):
#  1. snow on the film patch and on `sides`: a Warning naming the film patch, the film
#     model and its interaction type, and `sides` as decided as usual; the run ends;
#  2. snow on the film patch only: a FatalIOError (the wall model could decide nothing);
#  3. the same as 1 with `surfaceFilmModel none`: no film warning.
# About 15 s.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
# shellcheck source=stock.sh
. "$(dirname "$0")/stock.sh"
[ -x /usr/bin/reactingParcelFoam ] || { echo "SKIP: reactingParcelFoam not installed"; exit 77; }
command -v reactingParcelFoam > /dev/null || fail "reactingParcelFoam not on PATH"
film=region0_to_wallFilmRegion_wallFilmFaces

stock_copy lagrangian/reactingParcelFoam/splashPanel "$tmp/base"
(
    cd "$tmp/base"
    cp -r 0.orig 0
    run log.blockMesh blockMesh
    run log.topoSet topoSet -dict system/wallFilmRegion.topoSet
    run log.extrude extrudeToRegionMesh -overwrite
    run log.topoSet2 topoSet -region wallFilmRegion -dict system/createWallFilmRegionPatches.topoSet
    run log.createPatch createPatch -region wallFilmRegion -overwrite
)
shorten "$tmp/base" 2e-4

# 1. the film patch and sides: the warning, the run goes on
cp -r "$tmp/base" "$tmp/both"
dropin "$tmp/both" reactingCloud1Properties "$film { type snow; }" 'sides { type snow; }'
(cd "$tmp/both" && run log.run reactingParcelFoam)
w=$(tr '\n' ' ' < "$tmp/both/log.run" | grep -o "snowWallInteraction: the snow patches [^:]* are patches of the surface film.*decided as usual") ||
    { tail -40 "$tmp/both/log.run" >&2; fail "both: no warning about the film patch"; }
for want in "$film" "surfaceFilmModel thermoSurfaceFilm" "interactionType splashBai" \
            "sees no impact there" "1(sides)"; do
    echo "$w" | grep -qF -- "$want" || fail "both: the warning does not say '$want': $w"
done
[ "$(grep -c 'are patches of the surface film' "$tmp/both/log.run")" = 1 ] || fail "both: the warning is not said once"
echo "ok   warning: $(echo "$w" | cut -c1-160)..."

# 2. the film patch alone: nothing the wall model could decide
cp -r "$tmp/base" "$tmp/only"
dropin "$tmp/only" reactingCloud1Properties "$film { type snow; }" 'sides { type none; }'
expect_fatal_io "$tmp/only" "every snow patch 1($film) is a patch of the surface film" reactingParcelFoam
grep -qF "surfaceFilmModel thermoSurfaceFilm (interactionType splashBai) takes every parcel" "$tmp/only/log.run" ||
    fail "only: the error does not name the film model"
echo "ok   FatalIOError: $(grep -m1 'every snow patch' "$tmp/only/log.run" | cut -c1-140)..."

# 3. no film model in the cloud: no film warning
cp -r "$tmp/base" "$tmp/nofilm"
dropin "$tmp/nofilm" reactingCloud1Properties "$film { type snow; }" 'sides { type snow; }'
foamDictionary -entry subModels/surfaceFilmModel -set none "$tmp/nofilm/constant/reactingCloud1Properties" > /dev/null
(cd "$tmp/nofilm" && run log.run reactingParcelFoam)
! grep -q "of the surface film" "$tmp/nofilm/log.run" || fail "nofilm: a film message without a film model"
echo "PASS: surface-film patches reported"
