#!/usr/bin/env bash
# run.sh - fvc::reconstruct of a uniform vector on the meshes of Debian's stock tutorials,
# compiled with GCC's defaults of wmake (-O3) and with the fix -D__restrict__= (the flag of
# etc/setup.sh --stock-solvers): prints per mesh the cells off by more than 1e-9 |U0|, the
# largest relative error of each build and that of each component. On demand (not a ctest test): it compiles
# reconstructCheck.C twice (about 1 min each on 2 cores) into a temp folder.
#
# Usage: tests/openfoam/reconstructCheck/run.sh [TUTORIAL...]
#   TUTORIAL: a folder under /usr/share/doc/openfoam-examples/examples whose mesh blockMesh
#   makes (default: lagrangian/MPPICFoam/column lagrangian/MPPICFoam/injectionChannel
#   lagrangian/reactingParcelFoam/verticalChannel)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
case "${1:-}" in -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
examples=/usr/share/doc/openfoam-examples/examples
[ -x /usr/bin/blockMesh ] || { echo "run.sh: OpenFOAM not installed" >&2; exit 1; }
[ -f "$top/.cache/openfoam/.ready" ] || { echo "run.sh: no OpenFOAM headers (run etc/setup.sh)" >&2; exit 1; }
# shellcheck source=../../../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh"
tmp=$(mktemp -d /tmp/sw-reconstruct-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
[ $# -gt 0 ] || set -- lagrangian/MPPICFoam/column lagrangian/MPPICFoam/injectionChannel \
    lagrangian/reactingParcelFoam/verticalChannel

# build NAME FLAGS: reconstructCheck compiled with FLAGS (wmake's FOAM_EXTRA_CXXFLAGS)
build() {
    mkdir -p "$tmp/src-$1"
    cp -r "$here/reconstructCheck.C" "$here/Make" "$tmp/src-$1/"
    rm -rf "$tmp/src-$1/Make/linux64"*
    (cd "$tmp/src-$1" && FOAM_USER_APPBIN="$tmp/bin" RC_SUFFIX="-$1" FOAM_EXTRA_CXXFLAGS="$2" \
        wmake > "$tmp/log.build-$1" 2>&1) || { tail -20 "$tmp/log.build-$1" >&2; exit 1; }
}
echo "run.sh: compiling reconstructCheck as wmake does (-O3) and with -D__restrict__="
build default ""
build fixed "-D__restrict__="
printf '| mesh | build | cells | cells off by > 1e-9 U0 | max error / U0 | x | y | z |\n|---|---|---:|---:|---:|---:|---:|---:|\n'
for t in "$@"; do
    [ -d "$examples/$t" ] || { echo "run.sh: no $examples/$t" >&2; exit 1; }
    c="$tmp/case-${t//\//_}"
    cp -r "$examples/$t" "$c"
    find "$c" -name '*.gz' -exec gunzip {} +
    (cd "$c" && blockMesh > log.blockMesh 2>&1) || { tail -5 "$c/log.blockMesh" >&2; exit 1; }
    for b in default fixed; do
        line=$(cd "$c" && "$tmp/bin/reconstructCheck-$b" 2>&1 | grep '^reconstructCheck:') \
            || { echo "run.sh: reconstructCheck-$b failed on $t" >&2; exit 1; }
        read -r n bad mx ex ey ez <<< "$(sed 's/.*cells \([0-9]*\), off.*: \([0-9]*\), max.*: \(.*\), per component x y z: \(.*\)/\1 \2 \3 \4/' <<< "$line")"
        printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "${t##*/}" "$b" "$n" "$bad" "$mx" "$ex" "$ey" "$ez"
    done
done
