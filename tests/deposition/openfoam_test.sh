# shellcheck shell=bash
# tests/deposition/openfoam_test.sh - sourced by the deposition benchmarks'
# OpenFOAM tests (test_channel_openfoam, test_bend_openfoam, test_rib_openfoam):
# the OpenFOAM environment of SW_TOP, a skip (exit 77) naming what is missing
# (OpenFOAM, the project's solver and wrapper, gnuplot), a work folder $tmp
# removed at exit, and check NAME CONDITION (prints ok/FAIL, counts $fails).
set -u
top=${SW_TOP:?SW_TOP not set}
. "$top/etc/openfoam-env.sh" 2>/dev/null
command -v simpleFoam >/dev/null || { echo "OpenFOAM not found: skipped"; exit 77; }
command -v pimpleUncoupledKinematicParcelFoam >/dev/null || { echo "solver not built: skipped"; exit 77; }
[ -f "$FOAM_USER_LIBBIN/libsnowWallInteraction.so" ] || { echo "wrapper not built: skipped"; exit 77; }
command -v gnuplot >/dev/null || { echo "gnuplot missing: skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }
