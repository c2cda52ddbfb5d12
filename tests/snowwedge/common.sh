# common.sh - sourced by the snowwedge script tests: the command under test ($S,
# the build's, else bin/'s), a temporary folder ($tmp, removed on exit), check NAME
# TEST (eval TEST; counts the failures) and finish (PASS and exit 0, or the count
# of failures and exit 1).
set -u
top=${SW_TOP:?SW_TOP not set}
build=${SW_BUILD:?SW_BUILD not set}
S="$build/tools/snowwedge/snowwedge"
[ -x "$S" ] || S="$top/bin/snowwedge"
[ -x "$S" ] || { echo "snowwedge not built"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails+1)); fi; }
finish() { [ "$fails" -eq 0 ] && { echo PASS; exit 0; }; echo "$fails failure(s)"; exit 1; }
