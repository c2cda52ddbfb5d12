# common.sh - sourced by the OpenFOAM tests of tests/openfoam.
# Skips (exit 77) when OpenFOAM v1912 or the built libsnowWallInteraction.so is absent;
# sources etc/openfoam-env.sh; makes a temp folder $tmp (removed at exit).
top=${SW_TOP:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
lib="$top/platforms/lib/libsnowWallInteraction.so"
if [ ! -x /usr/bin/icoUncoupledKinematicParcelFoam ]; then
    echo "SKIP: OpenFOAM (icoUncoupledKinematicParcelFoam) not installed"; exit 77
fi
if [ ! -f "$lib" ]; then
    echo "SKIP: $lib not built (run ./Allwmake)"; exit 77
fi
# shellcheck source=../../etc/openfoam-env.sh
. "$top/etc/openfoam-env.sh"
export FOAM_USER_LIBBIN="$top/platforms/lib"
tmp=$(mktemp -d /tmp/sw-openfoam-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fixture="$top/tests/wallmodel/fixtures/regime.coeffs"

fail() { echo "FAIL: $*" >&2; exit 1; }

# run LOG CMD... : run in the current folder, log to LOG, fail with the log tail
run() {
    local log=$1; shift
    if ! "$@" > "$log" 2>&1; then
        tail -25 "$log" >&2
        fail "$* (see above)"
    fi
}

# expect_fatal_io CASE PATTERN [SOLVER]: in CASE the solver (default
# icoUncoupledKinematicParcelFoam) must stop with a FatalIOError (exit 1, "FOAM FATAL IO
# ERROR") whose text holds PATTERN (grep); success, any other exit, or a signal (SIGFPE
# 136, abort 134: a crash without a message) fails, with the log's tail
expect_fatal_io() {
    local rc=0
    (cd "$1" && "${3:-icoUncoupledKinematicParcelFoam}" > log.run 2>&1) || rc=$?
    if [ "$rc" = 0 ]; then
        fail "$1: the solver succeeded, expected a FatalIOError ('$2')"
    elif [ "$rc" -gt 128 ]; then
        tail -20 "$1/log.run" >&2
        fail "$1: the solver died of signal $((rc - 128)) (exit $rc), expected a FatalIOError ('$2')"
    elif [ "$rc" != 1 ] || ! grep -q "FOAM FATAL IO ERROR" "$1/log.run"; then
        tail -20 "$1/log.run" >&2
        fail "$1: exit $rc without a FatalIOError, expected one with '$2'"
    fi
    grep -q -- "$2" "$1/log.run" || { tail -20 "$1/log.run" >&2; fail "$1: no '$2' in the error"; }
}

# snow_cloud INJECTIONS COEFFS: in the current box case, rewrite
# constant/kinematicCloudProperties with these injection models and this body of
# snowWallInteractionCoeffs (both text), the box's solution and properties kept
snow_cloud() {
    {
        sed -n '1,/^subModels/p' constant/kinematicCloudProperties
        echo "{"
        echo "    particleForces {}"
        echo "    injectionModels"
        echo "    {"
        printf '%s\n' "$1"
        echo "    }"
        echo "    dispersionModel none; patchInteractionModel snowWallInteraction;"
        echo "    surfaceFilmModel none; stochasticCollisionModel none; collisionModel none;"
        echo "    snowWallInteractionCoeffs"
        echo "    {"
        printf '%s\n' "$2"
        echo "    }"
        echo "}"
        echo "cloudFunctions {}"
    } > constant/kinematicCloudProperties.new
    mv constant/kinematicCloudProperties.new constant/kinematicCloudProperties
}

# series CASE START: the last data line of the snowWall time series
series_last() { tail -n 1 "$1/postProcessing/kinematicCloud:snowWall/$2/snowWall.dat"; }

# deposit_values FIELDFILE PATCH: the face values of PATCH, one per line
deposit_values() {
    awk -v p="$2" '
        $1 == p && !inb { inb = 1; next }
        inb && /uniform/ && !/nonuniform/ { v = $0; sub(/.*uniform */, "", v); sub(/;.*/, "", v); print "uniform " v; exit }
        inb && /nonuniform/ { inl = 1; next }
        inl && /^\(/ { on = 1; next }
        inl && /^\)/ { exit }
        on { print $1 }
    ' "$1"
}
