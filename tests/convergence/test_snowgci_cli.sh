#!/usr/bin/env bash
# snowgci: --help, a good table (a synthetic ladder with a known order and limit,
# Celik et al. 2008's example, every verdict, the markdown file written whole),
# and every bad input refused with one line naming it, exit 2, no output file.
set -u
: "${SW_TOP:?SW_TOP not set (run through ctest)}"
: "${SW_BUILD:?SW_BUILD not set (run through ctest)}"
G=$SW_BUILD/validation/convergence/snowgci
[ -x "$G" ] || { echo "SKIP: $G not built"; exit 77; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/snowgci.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
FAILS=0
fail() { echo "FAIL: $*"; FAILS=$((FAILS + 1)); }
ok() { echo "ok: $*"; }

"$G" --help >"$WORK/help" && grep -q "^SYNOPSIS" "$WORK/help" && grep -q "^EXIT STATUS" "$WORK/help" \
    && ok "--help" || fail "--help"

# a good table: phi = 0.3 + 2 h^1.5 on a non-constant ladder (Cd, exact, rows
# coarsest first), phi = 0.2 - 3 h^2 on a constant ratio with small sampling errors
# (St); an oscillating, a divergent, an unresolved and a two-level quantity; a
# comment, a blank line, an extra column
awk 'BEGIN {
    print "# a resolution ladder"
    print "note,quantity,level,h,value,se"
    n = split("0.01 0.013 0.025", h, " ")
    for (i = n; i >= 1; i--) printf "x,Cd,L%d,%s,%.15g,0\n", i, h[i], 0.3 + 2 * h[i] ^ 1.5
    n = split("0.01 0.02 0.04", k, " ")
    for (i = 1; i <= n; i++) printf "x,St,L%d,%s,%.15g,1e-6\n", i, k[i], 0.2 - 3 * k[i] ^ 2
    print "x,osc,a,0.1,1.0,0"; print "x,osc,b,0.2,1.1,0"; print "x,osc,c,0.4,0.8,0"
    print "x,div,a,0.1,1.0,0"; print "x,div,b,0.2,1.2,0"; print "x,div,c,0.4,1.3,0"
    print "x,noisy,a,0.1,1.10,0.04"; print "x,noisy,b,0.2,1.20,0.04"; print "x,noisy,c,0.4,1.40,0.04"
    print "x,pair,a,0.1,3.02,0"; print ""; print "x,pair,b,0.2,3.08,0"
}' >"$WORK/good.csv"
"$G" --md "$WORK/gci.md" "$WORK/good.csv" >"$WORK/out" 2>"$WORK/err" || fail "good table: $(cat "$WORK/err")"
[ -s "$WORK/err" ] && fail "good table: stderr not empty: $(cat "$WORK/err")"
cat "$WORK/out"
# the recovered order and limit, read back from the output
block() { awk -v q="$1" '/^quantity /{on = ($2 == q ":")} on' "$WORK/out"; }
block Cd | awk '/verdict:/ {v = $2} / p [0-9]/ {for (i = 1; i < NF; i++) if ($i == "p") p = $(i + 1)}
    /phi_ext21/ {e = $2} END {exit !(v == "monotone" && p > 1.4999 && p < 1.5001 && e > 0.29999 && e < 0.30001)}' \
    && ok "Cd: p 1.5 and phi_ext 0.3 recovered (non-constant ratio)" || fail "Cd: $(block Cd)"
block St | awk '/verdict:/ {v = $2} / p [0-9]/ {for (i = 1; i < NF; i++) if ($i == "p") p = $(i + 1)}
    /phi_ext21/ {e = $2} END {exit !(v == "monotone" && p > 1.99 && p < 2.01 && e > 0.19999 && e < 0.20001)}' \
    && ok "St: p 2 and phi_ext 0.2 recovered (constant ratio, sampling errors)" || fail "St: $(block St)"
block osc | grep -q "verdict: oscillatory$" && ! block osc | grep -q "phi_ext21" \
    && ok "osc: oscillatory, no order" || fail "osc: $(block osc)"
block div | grep -q "verdict: divergent$" && ok "div: divergent" || fail "div: $(block div)"
block noisy | grep -q "verdict: not resolved by the statistics (the values alone: monotone" \
    && ok "noisy: not resolved by the statistics" || fail "noisy: $(block noisy)"
block pair | grep -q "verdict: two-level" && block pair | grep -q "p 2 assumed, safety factor 3" \
    && ok "pair: two-level estimate, assumed order 2, Fs 3" || fail "pair: $(block pair)"
# the levels sorted finest first whatever the row order
block Cd | awk '/^  L[0-9]/ {s = s $1} END {exit s != "L1L2L3"}' && ok "levels sorted finest first" \
    || fail "level order: $(block Cd)"
# the markdown file: whole, one row per quantity, no temporary left
[ -f "$WORK/gci.md" ] && [ "$(grep -c '^| \(Cd\|St\|osc\|div\|noisy\|pair\) | [0-9]' "$WORK/gci.md")" -eq 6 ] \
    && ok "markdown: six quantity rows" || fail "markdown: $(cat "$WORK/gci.md" 2>/dev/null)"
grep -q '^| Cd | 3 | monotone | 1.5 ' "$WORK/gci.md" && ok "markdown: Cd row" || fail "markdown Cd row"
ls "$WORK" | grep -q tmp && fail "a temporary file was left" || ok "no temporary left"

# Celik et al. 2008, Table 1 column 1 from cell counts in 2-D, from standard input
printf 'quantity,level,cells,value,se\nL,1,18000,6.063,0\nL,2,8000,5.972,0\nL,3,4500,5.863,0\n' |
    "$G" --dim 2 - >"$WORK/celik" 2>&1 || fail "celik: $(cat "$WORK/celik")"
grep -q "r21 1.5, r32 1.33333" "$WORK/celik" && grep -q "p 1.53397" "$WORK/celik" \
    && grep -q "phi_ext21 6.16849" "$WORK/celik" && ok "Celik's example: p 1.53, phi_ext 6.1685" \
    || fail "celik: $(cat "$WORK/celik")"

# bad input: exit 2, one line naming it, nothing on stdout, no markdown file
check() {   # expected-text table-content [options...]
    local want=$1 content=$2; shift 2
    printf '%b' "$content" >"$WORK/bad.csv"
    "$G" --md "$WORK/bad.md" "$@" "$WORK/bad.csv" >"$WORK/bout" 2>"$WORK/err"; local rc=$?
    [ $rc -eq 2 ] || fail "'$want': exit $rc, want 2"
    [ "$(wc -l <"$WORK/err")" -eq 1 ] || fail "'$want': want one error line, got: $(cat "$WORK/err")"
    grep -qF -- "$want" "$WORK/err" || fail "'$want': message does not name it: $(cat "$WORK/err")"
    [ -s "$WORK/bout" ] && fail "'$want': printed to stdout"
    [ -e "$WORK/bad.md" ] && { fail "'$want': wrote the markdown file"; rm -f "$WORK/bad.md"; }
    echo "ok: refused: $(cat "$WORK/err")"
}
H='quantity,level,h,value,se\n'
G3="$H"'q,a,0.1,1.1,0\nq,b,0.2,1.2,0\nq,c,0.4,1.4,0\n'
check "no column 'se'" 'quantity,level,h,value\nq,a,0.1,1\nq,b,0.2,2\n'
check "no column 'h' or 'cells'" 'quantity,level,value,se\nq,a,1,0\n'
check "both 'h' and 'cells'" 'quantity,level,h,cells,value,se\nq,a,0.1,10,1,0\n'
check "names column 'value' twice" 'quantity,level,h,value,value,se\n'
check "value 'nan' is not a finite decimal number" "$H"'q,a,0.1,nan,0\nq,b,0.2,1,0\n'
check "value 'inf'" "$H"'q,a,0.1,inf,0\nq,b,0.2,1,0\n'
check "se '0x1'" "$H"'q,a,0.1,1,0x1\nq,b,0.2,1,0\n'
check "value ''" "$H"'q,a,0.1,,0\nq,b,0.2,1,0\n'
check "h '0' is not positive" "$H"'q,a,0,1,0\nq,b,0.2,1,0\n'
check "h '-0.1' is not positive" "$H"'q,a,-0.1,1,0\nq,b,0.2,1,0\n'
check "cells '0' is not at least 1" 'quantity,level,cells,value,se\nq,a,0,1,0\nq,b,10,1,0\n'
check "se '-1' is negative" "$H"'q,a,0.1,1,-1\nq,b,0.2,1,0\n'
check "value '1e300' is above 1e100" "$H"'q,a,0.1,1e300,0\nq,b,0.2,1,0\n'
check "quantity 'q' has 1 level (need at least 2)" "$H"'q,a,0.1,1,0\n'
check "4 fields, the header has 5" "$H"'q,a,0.1,1,0\nq,b,0.2,1\n'
check "has level 'a' twice" "$H"'q,a,0.1,1,0\nq,a,0.2,1,0\n'
check "levels 'a' and 'b' have the same h" "$H"'q,a,0.1,1,0\nq,b,0.1,2,0\n'
check "r21 = h2/h1" "$H"'q,a,0.1,1,0\nq,b,0.10001,2,0\n'
check "r32 = h3/h2" "$H"'q,a,0.1,1,0\nq,b,0.2,2,0\nq,c,50,3,0\n'
check "empty level name" "$H"'q,,0.1,1,0\n'
check "no data rows" "$H"
check "no header line" '# only a comment\n'
check "--order: 0 is outside" "$G3" --order 0
check "--p-range: '2,1' is not" "$G3" --p-range 2,1
check "--p-range: 'x' is not a finite" "$G3" --p-range x,2
check "--z: 11 is outside" "$G3" --z 11
check "--safety-three: 0.5 is outside" "$G3" --safety-three 0.5
check "--safety-two: 'nan'" "$G3" --safety-two nan
check "--dim: '4'" "$G3" --dim 4
check "--volume: -1 is outside" "$G3" --volume -1
check "unknown option '--frobnicate'" "$G3" --frobnicate 1
# the table is the check's last argument; a second one is refused
check "one table only" "$G3" "$WORK/good.csv"
"$G" >/dev/null 2>"$WORK/err"; [ $? -eq 2 ] && grep -q "no table given" "$WORK/err" && ok "no table" || fail "no table"
"$G" "$WORK/none.csv" >/dev/null 2>"$WORK/err"; [ $? -eq 2 ] && grep -q "none.csv: cannot open" "$WORK/err" \
    && ok "missing file named" || fail "missing file: $(cat "$WORK/err")"
"$G" --md "$WORK/no/such/x.md" "$WORK/good.csv" >"$WORK/bout" 2>"$WORK/err"
[ $? -eq 2 ] && grep -q "cannot write .*no/such/x.md.*No such file" "$WORK/err" && [ ! -s "$WORK/bout" ] \
    && ok "--md in a missing folder: refused, nothing printed" || fail "--md missing folder: $(cat "$WORK/err")"
# an existing markdown file is replaced whole only on success
echo keep >"$WORK/keep.md"
printf '%b' "$H"'q,a,0.1,nan,0\n' >"$WORK/bad.csv"
"$G" --md "$WORK/keep.md" "$WORK/bad.csv" >/dev/null 2>&1
[ "$(cat "$WORK/keep.md")" = keep ] && ok "a failed run leaves the old file" || fail "old file changed"

# --md onto a FIFO or a device node made here (a /dev/full-like node): refused, left as it was
mkfifo "$WORK/fifo.md"
"$G" --md "$WORK/fifo.md" "$WORK/good.csv" >/dev/null 2>"$WORK/err"
[ $? -eq 2 ] && [ -p "$WORK/fifo.md" ] && grep -q "fifo.md" "$WORK/err" \
    && ok "--md onto a FIFO refused, the FIFO kept" || fail "--md FIFO: $(cat "$WORK/err")"
if mknod "$WORK/full.md" c 1 7 2>/dev/null; then
    "$G" --md "$WORK/full.md" "$WORK/good.csv" >/dev/null 2>"$WORK/err"
    [ $? -eq 2 ] && [ -c "$WORK/full.md" ] && grep -q "full.md" "$WORK/err" \
        && ok "--md onto a device node refused, the node kept" || fail "--md device: $(cat "$WORK/err")"
fi

if [ "$FAILS" -eq 0 ]; then echo "PASS"; exit 0; else echo "$FAILS failure(s)"; exit 1; fi
