# common.sh - sourced by the tests/regime_cli scripts.
set -u
: "${SW_TOP:?SW_TOP not set (run through ctest)}"
: "${SW_BUILD:?SW_BUILD not set (run through ctest)}"
SR=$SW_BUILD/regime/cli/snowregime
CHECK=$SW_BUILD/tests/regime_cli/regime_coeffs_check
[ -x "$SR" ] || { echo "SKIP: $SR not built"; exit 77; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/regime_cli.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
FAILS=0
fail() { echo "FAIL: $*"; FAILS=$((FAILS + 1)); }
ok() { echo "ok: $*"; }
finish() { if [ "$FAILS" -eq 0 ]; then echo "PASS"; exit 0; else echo "$FAILS failure(s)"; exit 1; fi; }
# float comparison with awk: fcmp A OP B
fcmp() { awk -v a="$1" -v b="$3" -v op="$2" 'BEGIN { r = (op == "<") ? a < b : (op == ">") ? a > b : (op == "<=") ? a <= b : a >= b; exit !r }'; }
