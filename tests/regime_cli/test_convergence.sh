#!/usr/bin/env bash
# snowregime convergence: table, plot, finite numbers, finer steps not worse by much.
. "$(dirname "$0")/common.sh"
out=$WORK/conv
"$SR" convergence --out "$out" --d 3e-05 --accuracy 15,60 --ref-factor 4 --min-time 0 >"$WORK/log" 2>&1 \
    || { cat "$WORK/log"; fail "convergence exit $?"; }
for f in convergence.csv convergence.md convergence.png; do [ -s "$out/$f" ] || fail "missing $f"; done
rows=$(grep -v '^#' "$out/convergence.csv" | grep -c '^[0-9]')
[ "$rows" -eq 2 ] || fail "want 2 rows, got $rows"
grep -v '^#' "$out/convergence.csv" | grep '^[0-9]' | awk -F, '
    { if (!($5 >= 0 && $5 < 0.2 && $6 > 0 && $7 > 0 && $8 > 0 && $9 > 0)) { print "bad row: " $0; bad = 1 } e[NR] = $5; s[NR] = $7 }
    END { if (!(s[2] > s[1])) { print "more accuracy must take more steps"; bad = 1 }
          if (!(e[2] <= e[1] + 1e-3)) { print "error grew with accuracy: " e[1] " -> " e[2]; bad = 1 }
          exit bad }' || fail "convergence table"
ok "convergence checks done"
finish
