#!/usr/bin/env bash
# test_box_compressible.sh - the box case with uncoupledKinematicParcelFoam (the
# basicKinematicCloud registration of snowWallInteraction): a psiThermo gas with
# mu = 1 Pa s, so the wallShearStress field is in Pa (tau_w = mu dU/dy = 2 Pa) and
# the shear gate must not need rhoAir. Same seven parcels, same fates as test_box.sh:
# 7 impacts, 3 sticks, 3 bounces, 1 rip-off.
set -euo pipefail
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
[ -x /usr/bin/uncoupledKinematicParcelFoam ] || { echo "SKIP: uncoupledKinematicParcelFoam not installed"; exit 77; }

c="$tmp/box"
cp -r "$top/tests/openfoam/box" "$c"
cp "$fixture" "$c/constant/regime.coeffs"
cd "$c"
foamDictionary -entry application -set uncoupledKinematicParcelFoam system/controlDict > /dev/null
cloud=constant/kinematicCloudProperties
foamDictionary -entry subModels/snowWallInteractionCoeffs/shearGate/rhoAir -remove $cloud > /dev/null
foamDictionary -entry solution/interpolationSchemes/mu -remove $cloud > /dev/null
foamDictionary -entry solution/interpolationSchemes/thermo:mu -set cell $cloud > /dev/null
cat > constant/thermophysicalProperties <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object thermophysicalProperties; }
thermoType
{
    type hePsiThermo; mixture pureMixture; transport const; thermo hConst;
    equationOfState perfectGas; specie specie; energy sensibleInternalEnergy;
}
mixture
{
    specie { molWeight 28.9; }
    thermodynamics { Cp 1007; Hf 0; }
    transport { mu 1; Pr 0.7; }
}
EOT
for f in p:101325:'[1 -1 -2 0 0 0 0]' T:253:'[0 0 0 1 0 0 0]'; do
    IFS=: read -r name val dims <<< "$f"
    cat > "0/$name" <<EOT
FoamFile { version 2.0; format ascii; class volScalarField; object $name; }
dimensions $dims;
internalField uniform $val;
boundaryField { ".*" { type zeroGradient; } }
EOT
done
run log.blockMesh blockMesh
run log.run uncoupledKinematicParcelFoam
line=$(series_last . 0)
[ "$(echo "$line" | cut -d' ' -f1-5)" = "0.1 7 3 3 1" ] || fail "totals: $line"
grep -q "snowWall: patch wall: impacts 7, sticks 3, bounces 3, ripoffs 1" log.run || fail "log summary"
echo "PASS ($line)"
