#!/usr/bin/env bash
# validation/rough-reference.sh --quick (the reference study's wall of
# 1 um spheres): the table's structure (every wall x asperity_yield x p row, every
# diameter, the CSV) and the orderings the physics fixes: elastic asperity
# contacts (only the JKR hysteresis dissipates) give the lowest v_crit of the
# three plastic treatments, and the flat wall (R* = R, more adhesion) is above
# every elastic-asperity rough wall. Nothing timing-based.
. "$(dirname "$0")/common.sh"
RR=$SW_TOP/validation/rough-reference.sh
# usage errors: named, exit 2, nothing written
expect2() { local msg=$1; shift; SNOWREGIME=$SR "$RR" "$@" >"$WORK/e.out" 2>"$WORK/e.err"; local rc=$?
    [ $rc -eq 2 ] || fail "$* : exit $rc (want 2)"; grep -q -- "$msg" "$WORK/e.err" || { cat "$WORK/e.err"; fail "$* : message lacks '$msg'"; }; }
expect2 "--out DIR is required" --quick
expect2 "unknown option '--bogus'" --out "$WORK/x1" --bogus
expect2 "--points: 'x'" --out "$WORK/x2" --points x
expect2 "--threads: '0'" --out "$WORK/x3" --threads 0
expect2 "--out needs a folder" --out
expect2 "parent folder" --out "$WORK/no/such/x4"
for k in 1 2 3; do [ ! -e "$WORK/x$k" ] || fail "a usage error left $WORK/x$k"; done
SNOWREGIME=$SR "$RR" --help | grep -q "^Usage: validation/rough-reference.sh --out DIR" || fail "--help: no usage line"
SNOWREGIME=$SR "$RR" --out "$WORK/rr" --quick >"$WORK/rr.log" 2>&1 || { cat "$WORK/rr.log"; fail "rough-reference.sh --quick exit $?"; finish; }
for f in reference.md reference.csv times.txt logs/flat.txt; do [ -s "$WORK/rr/$f" ] || fail "no $f"; done
for t in "$WORK"/.rough-reference.*; do [ ! -e "$t" ] || fail "the temporary folder $t was left behind"; done
# structure: 1 flat row + 3 walls x 3 yields x 3 levels, 4 diameters each, numbers
md=$WORK/rr/reference.md
grep -q '^| wall | asperity_yield | p | 10 um | 20 um | 50 um | 100 um |$' "$md" || fail "reference.md: no v_crit header"
n=$(grep -c '^| \(flat\|default\|1 um spheres\).* | \(-\|0\.[159]\) |\( [0-9.e+-]* |\)\{4\}$' "$md")
[ "$n" -eq 28 ] || fail "reference.md: $n v_crit rows (want 28)"
n=$(grep -c '^| \(default\|1 um spheres\)[^|]*| \(contact\|particle\|elastic\) |\( [0-9.e+-]* ([0-9.e+-]* - [0-9.e+-]*) |\)\{4\}$' "$md")
[ "$n" -eq 9 ] || fail "reference.md: $n ratio rows (want 9)"
csv=$WORK/rr/reference.csv
[ "$(head -1 "$csv")" = "wall,asperity_yield,p,d_um,vcrit_m_s,ratio_to_flat" ] || fail "reference.csv: header"
awk -F, 'NR > 1 && NF == 6 && $5 + 0 > 0 && $5 != "nan"' "$csv" | wc -l | grep -qx 112 || fail "reference.csv: not 112 rows with a v_crit > 0"
for w in default touching random; do for y in contact particle elastic; do for p in 0.9 0.5 0.1; do
    [ "$(grep -c "^$w,$y,$p,\(10\|20\|50\|100\)," "$csv")" -eq 4 ] || fail "reference.csv: $w $y $p: not 4 diameters"
done; done; done
# physics: elastic asperities lowest; the flat wall above every elastic-asperity rough wall
awk -F, 'NR > 1 { v[$1 "," $2 "," $3 "," $4] = $5 }
    END {
        bad = 0
        split("default touching random", W, " "); split("0.9 0.5 0.1", P, " "); split("10 20 50 100", D, " ")
        for (i = 1; i <= 3; i++) for (j = 1; j <= 3; j++) for (k = 1; k <= 4; k++) {
            key = W[i] "," "%s" "," P[j] "," D[k]
            e = v[sprintf(key, "elastic")]; c = v[sprintf(key, "contact")]; q = v[sprintf(key, "particle")]
            f = v["flat,-,-," D[k]]
            if (!(e < c && e < q)) { print "elastic not lowest: " W[i] " p " P[j] " d " D[k] ": " e " " q " " c; bad++ }
            if (!(f > e)) { print "flat " f " not above elastic " W[i] " p " P[j] " d " D[k] ": " e; bad++ }
        }
        exit bad > 0 }' "$csv" >"$WORK/phys.txt" || { cat "$WORK/phys.txt"; fail "physics ordering"; }
ok "rough-reference.sh --quick: 28 v_crit rows, 9 ratio rows, 112 CSV rows, orderings hold"
finish
