#!/usr/bin/env bash
# snowregime map writes the kernel's rebound of the bouncing impacts as tables in
# regime.coeffs: e_n(d, v_n), and with --vt e_n and e_t over (v_t, d,
# v_n); the wall-model core reads them back and its rebound is checked against
# the kernel at random off-grid points (rebound_check).
# Tolerances (absolute, in cells whose nodes all bounce): e_n 0.01, e_t 0.05;
# over every bouncing point (cells that hold the interface, where e_n falls to
# 0, included) e_n 0.03. Measured (this grid, 400 points): see the log.
. "$(dirname "$0")/common.sh"
RC=$SW_BUILD/tests/regime_cli/rebound_check
num() { sed -n "s/.*$1 max \([0-9.e+-]*\) .*/\1/p" | head -n1; }
# 1. a plain map: e_n(d, v_n)
"$SR" map --out "$WORK/m" --nd 20 --nv 30 --no-plot >"$WORK/m.log" 2>&1 || { cat "$WORK/m.log"; fail "map exit $?"; }
f=$WORK/m/regime.coeffs
for k in reboundD reboundVn reboundEn; do grep -q "^ *$k " "$f" || fail "regime.coeffs lacks $k"; done
for k in reboundVt reboundEt; do ! grep -q "^ *$k " "$f" || fail "a map without --vt has $k"; done
"$RC" "$f" 400 7 >"$WORK/c1.txt" || fail "rebound_check exit $?"
cat "$WORK/c1.txt"
en_in=$(grep '^inside' "$WORK/c1.txt" | num "e_n error|")
en_all=$(grep '^all bouncing' "$WORK/c1.txt" | num "e_n error|")
n_in=$(sed -n 's/.*all bounce: \([0-9]*\)$/\1/p' "$WORK/c1.txt")
[ "${n_in:-0}" -ge 150 ] || fail "only ${n_in:-0} points inside bouncing cells"
fcmp "${en_in:-1}" "<" 0.01 || fail "e_n error $en_in >= 0.01 (inside)"
fcmp "${en_all:-1}" "<" 0.03 || fail "e_n error $en_all >= 0.03 (all bouncing points)"
# 2. --vt: e_n and e_t over (v_t, d, v_n)
"$SR" map --out "$WORK/o" --vt 0,0.25,0.5,1,2,4,8 --max-slide 100e-6 --nd 20 --nv 30 --no-plot \
    >"$WORK/o.log" 2>&1 || { cat "$WORK/o.log"; fail "map --vt exit $?"; }
f=$WORK/o/regime.coeffs
for k in reboundD reboundVn reboundVt reboundEn reboundEt; do grep -q "^ *$k " "$f" || fail "regime.coeffs lacks $k"; done
"$RC" "$f" 400 9 >"$WORK/c2.txt" || fail "rebound_check exit $?"
cat "$WORK/c2.txt"
en_in=$(grep '^inside' "$WORK/c2.txt" | num "e_n error|")
et_in=$(grep '^inside' "$WORK/c2.txt" | sed 's/.*e_t/e_t/' | num "e_t error|")
fcmp "${en_in:-1}" "<" 0.01 || fail "oblique e_n error $en_in >= 0.01 (inside)"
fcmp "${et_in:-1}" "<" 0.05 || fail "oblique e_t error $et_in >= 0.05 (inside)"
# 3. the combined file's interface still agrees with the v_t = 0 map's (regime_coeffs_check)
"$CHECK" "$f" "$WORK/o/interface-vt0.csv" >"$WORK/chk.txt" 2>&1 || { cat "$WORK/chk.txt"; fail "regime_coeffs_check exit"; }
finish
