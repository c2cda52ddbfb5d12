#!/usr/bin/env bash
# snowladder (series, total) and the wedge's ladder collector
# (tutorials/wedge/post/wedge-ladder) on fabricated run folders with known
# answers: the batch-means mean of a series, the difference of two series, a
# monotone ladder of three levels with two designs (the reference, every run's
# total error, the cheapest run per target), the collector's table (Cd, Cp_b,
# St, regions and classes), its plot and its mesh-family settings; --with (a run
# judged against stored rows as in the whole ladder, a quantity the file lacks
# left out); every bad input refused with one line (two mesh families, a name
# clash, a foreign header, another family in --with), a non-zero exit and
# nothing written; Allrun -level's refusals.
set -u
: "${SW_TOP:?SW_TOP not set (run through ctest)}"
: "${SW_BUILD:?SW_BUILD not set (run through ctest)}"
L=$SW_BUILD/validation/convergence/snowladder
G=$SW_BUILD/validation/convergence/snowgci
C=$SW_TOP/tutorials/wedge/post/wedge-ladder
[ -x "$L" ] || { echo "SKIP: $L not built"; exit 77; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/snowladder.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
FAILS=0
fail() { echo "FAIL: $*"; FAILS=$((FAILS + 1)); }
ok() { echo "ok: $*"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
# refused: exit code $1, one line on stderr naming $2, nothing on stdout
refused() {
    local want=$1 name=$2; shift 2
    "$@" >"$WORK/r.out" 2>"$WORK/r.err"
    local rc=$?
    if [ "$rc" = "$want" ] && [ "$(wc -l <"$WORK/r.err")" = 1 ] && grep -qF -- "$name" "$WORK/r.err" &&
        [ ! -s "$WORK/r.out" ]; then ok "refused ($rc): $(cat "$WORK/r.err")"
    else fail "expected exit $want naming '$name' from '$*': exit $rc, stderr '$(cat "$WORK/r.err")'"; fi
}

"$L" --help >"$WORK/help" && grep -q "^SYNOPSIS" "$WORK/help" && grep -q "^EXIT STATUS" "$WORK/help" &&
    ok "--help" || fail "--help"

# ---- series: t = 1..16, x = t, 4 batches: 8.5 +- sqrt(80/3)/2 ---------------
{ echo "# Time value other"; for i in $(seq 1 16); do echo "$i $i $((2 * i))"; done; } >"$WORK/s.dat"
read -r m se n nb _ < <("$L" series --window 0,16 --batches 4 "$WORK/s.dat")
near "$m" 8.5 1e-12 && near "$se" "$(awk 'BEGIN { print sqrt(80 / 3) / 2 }')" 1e-5 && [ "$n" = 16 ] && [ "$nb" = 4 ] &&
    ok "series: 8.5 +- 2.582 over 16 samples" || fail "series: got $m $se $n $nb"
# column 3 minus column 2 of a second file, x 0.5: (2i - i) / 2 = i / 2 over (4, 12]
read -r m se n _ < <("$L" series --window 4,12 --batches 2 --column 3 --minus "$WORK/s.dat" --scale 0.5 "$WORK/s.dat")
near "$m" 4.25 1e-12 && near "$se" 1 1e-9 && [ "$n" = 8 ] && ok "series --minus --scale: 4.25 +- 1" ||
    fail "series --minus: got $m $se $n"
{ echo "# t"; for i in $(seq 1 16); do echo "$i.5 0"; done; } >"$WORK/shifted.dat"
refused 2 "at time" "$L" series --window 0,16 --minus "$WORK/shifted.dat" "$WORK/s.dat"
refused 2 "--window" "$L" series --window 3,1 "$WORK/s.dat"
refused 2 "--window" "$L" series "$WORK/s.dat"
refused 2 "fewer than 2 per batch" "$L" series --window 0,16 --batches 9 "$WORK/s.dat"
refused 2 "--batches" "$L" series --window 0,16 --batches 1 "$WORK/s.dat"
refused 2 "no column 5" "$L" series --window 0,16 --column 5 "$WORK/s.dat"
printf '1 1\n2 nan\n' >"$WORK/nan.dat"
refused 2 "nan.dat:2" "$L" series --window 0,2 "$WORK/nan.dat"
refused 2 "cannot open" "$L" series --window 0,2 "$WORK/none.dat"
refused 2 "unknown command" "$L" nothing

# ---- total: face = 1.2 + 24 h^2, h = cells^(-1/3), three levels, two designs --
# levels -1, 0, 1: 1000, 8000, 64000 cells (h 0.1, 0.05, 0.025): 1.44, 1.26, 1.215;
# se 2 % (default) and 0.7 % (full); flow 100 x 2.83^level s, clouds 50 or 300 s
awk 'BEGIN {
    print "quantity,run,design,level,cells,step,value,se,t_flow,t_clouds"
    split("1000 8000 64000", c, " "); split("1.44 1.26 1.215", v, " ")
    for (i = 1; i <= 3; i++) for (k = 0; k < 2; k++) {
        lv = i - 2; se = v[i] * (k ? 0.007 : 0.02)
        printf "face,r%d%s,%s,%d,%s,%g,%s,%.10g,%.10g,%s\n", lv + 1, k ? "f" : "d", k ? "full" : "default", lv, c[i],
            1e-3 * 2 ^ (-lv / 2), v[i], se, 100 * 2.83 ^ lv, k ? 300 : 50 }
    # a quantity that oscillates: the finest value is the reference
    print "Cd,r0d,default,-1,1000,,0.40,0.001,100,50"
    print "Cd,r1d,default,0,8000,,0.36,0.001,283,50"
    print "Cd,r2d,default,1,64000,,0.38,0.001,801,50"
}' >"$WORK/ladder.csv"
"$L" total --out "$WORK/out" "$WORK/ladder.csv" >"$WORK/t.out" 2>"$WORK/t.err" || fail "total: $(cat "$WORK/t.err")"
cat "$WORK/t.out"
for f in ladder.md total_error.csv gci.csv .snowwall-output; do
    [ -s "$WORK/out/$f" ] && ok "total wrote $f" || fail "total: no $f"
done
grep -q "^face: 3 levels, monotone, reference 1.2 (extrapolated)" "$WORK/t.out" && ok "face: monotone, phi_ext 1.2" ||
    fail "face: not monotone to 0.6"
grep -q "^Cd: 3 levels, oscillatory, reference 0.38 (bound)" "$WORK/t.out" && ok "Cd: oscillatory, a bound about the finest 0.38" ||
    fail "Cd: not oscillatory with a bound about the finest value"
# every run's total error against the closed form sqrt(se^2 + (v - 1.2)^2 + u^2) / 1.2,
# u = (1.25 - 1) |1.215 - 1.2| the extrapolated reference's own uncertainty
awk -F, 'NR > 1 && $1 == "face" { want = sqrt($8 ^ 2 + ($7 - 1.2) ^ 2 + 0.00375 ^ 2) / 1.2; d = $11 - want
    if (d < 0) d = -d; if (d > 1e-5 || $13 != "extrapolated") bad++; n++ }
    END { exit !(n == 6 && !bad) }' "$WORK/out/total_error.csv" &&
    ok "face: the six runs' total errors" || fail "face: total errors: $(cat "$WORK/out/total_error.csv")"
# Cd: a bound over the finest value 0.38 (its last change 0.02) and the extrapolation
# with order 2, 0.38 + 0.02 / 3 (+- 0.0067); here the finest reading is the larger at
# every level: sqrt(|phi_i - 0.38|^2 + 0.02^2)
awk -F, 'NR > 1 && $1 == "Cd" { w[$2] = $9 } function off(a, b) { return (a > b ? a - b : b - a) > 1e-6 }
    END { exit off(w["r2d"], 0.02) || off(w["r1d"], sqrt(0.0008)) || off(w["r0d"], sqrt(0.0008)) }' \
    "$WORK/out/total_error.csv" && ok "Cd: the finest level's error is its last change, in every level's" || fail "Cd: discretization errors: $(grep '^Cd' "$WORK/out/total_error.csv")"
# the picks by the closed form: 10 %: level 0 default (discretization 5 %, se 2 %:
# 5.4 %, 150 s); 30 %: level -1 default (20.1 %, 85 s)
want10=$(awk -F, 'NR > 1 && $1 == "face" && $11 <= 0.10 { if (b == "" || $6 < t) { b = $2; t = $6 } } END { print b }' "$WORK/out/total_error.csv")
want30=$(awk -F, 'NR > 1 && $1 == "face" && $11 <= 0.30 { if (b == "" || $6 < t) { b = $2; t = $6 } } END { print b }' "$WORK/out/total_error.csv")
[ "$want10" = r1d ] && [ "$want30" = r0d ] && ok "closed form: r1d under 10 %, r0d under 30 %" ||
    fail "closed form picks $want10 / $want30"
grep -E "^\| face \|" "$WORK/out/ladder.md" | grep -q "| $want10 (level 0, .*| $want30 (level -1," &&
    ok "ladder.md: the cheapest runs under 10 and 30 %" || fail "ladder.md picks: $(grep -E '^\| face \|' "$WORK/out/ladder.md")"
# gci.csv: the levels' best runs, read back by snowgci
"$G" "$WORK/out/gci.csv" >"$WORK/g.out" 2>&1 && grep -A8 "^quantity face" "$WORK/g.out" | grep -q "verdict: monotone" &&
    ok "gci.csv read by snowgci: monotone" || fail "gci.csv: $(cat "$WORK/g.out")"
awk -F, '$1 == "face" && $5 < 0.011 { n++ } END { exit n != 3 }' "$WORK/out/gci.csv" && ok "gci.csv: the full design (smaller se) represents every level" ||
    fail "gci.csv: not the full runs"
# a second run into the same output folder is fine
"$L" total --out "$WORK/out" --targets 5,50 "$WORK/ladder.csv" >/dev/null 2>&1 && grep -q "cheapest run <= 5 %" "$WORK/out/ladder.md" &&
    ok "total: rewrites its own folder" || fail "total: second run"

# bad tables and folders: nothing written
bad() {  # bad NAME CONTENT MESSAGE
    printf '%b' "$2" >"$WORK/$1.csv"
    refused 2 "$3" "$L" total --out "$WORK/bad_$1" "$WORK/$1.csv"
    [ ! -e "$WORK/bad_$1" ] || fail "$1: output folder created"
}
H="quantity,run,design,level,cells,value,se,t_flow,t_clouds\n"
bad nocol "quantity,run,level,cells,value,se,t_flow\nq,a,0,10,1,0,1\n" "no column 't_clouds'"
bad dup "$H q,a,d,0,10,1,0,1,1\nq,a,d,1,20,1,0,1,1\n" "run 'a' given twice"
bad cells "$H q,a,d,0,10,1,0,1,1\nq,b,d,0,20,1,0,1,1\n" "level '0' with 20 cells"
bad same "$H q,a,d,0,10,1,0,1,1\nq,b,d,1,10,1,0,1,1\n" "have the same cells"
bad one "$H q,a,d,0,10,1,0,1,1\nq,b,e,0,10,1.1,0,1,1\n" "has 1 level"
bad nan "$H q,a,d,0,10,nan,0,1,1\nq,b,d,1,20,1,0,1,1\n" "value 'nan'"
bad negse "$H q,a,d,0,10,1,-1,1,1\nq,b,d,1,20,1,0,1,1\n" "se -1"
bad negt "$H q,a,d,0,10,1,0,-1,1\nq,b,d,1,20,1,0,1,1\n" "wall times"
bad fields "$H q,a,d,0,10,1,0,1\n" "8 fields"
bad empty "" "empty"
refused 2 "--targets" "$L" total --out "$WORK/bad_t" --targets 10,,30 "$WORK/ladder.csv"
refused 2 "--out" "$L" total "$WORK/ladder.csv"
mkdir "$WORK/foreign" && echo keep >"$WORK/foreign/mine.txt"
refused 2 "not a SnowWall output folder" "$L" total --out "$WORK/foreign" "$WORK/ladder.csv"
[ "$(ls -A "$WORK/foreign")" = mine.txt ] && ok "a foreign folder untouched" || fail "foreign folder changed"

# ---- the collector on fabricated run folders ----------------------------------
# three levels of one design: Cd 0.40 + small alternation (mean exact), Cp_b
# -0.30 - level / 100 exactly, St 0.125, regions and classes of known values
fab() {  # fab NAME LEVEL CELLS FACE [refine_wake]
    local d=$WORK/runs/$1 lv=$2
    mkdir -p "$d/results/off" "$d/results/compose/mvd20" "$d/results/compose/mvd8" \
        "$d/postProcessing/forceCoeffs/0" "$d/postProcessing/basePressure/0" "$d/postProcessing/inletPressure/0"
    printf '# written by a test\nlevel %s\nvariant test\nrefine_wake %s\nhalfstep 0\nfull 0\nstep_scale 1\ncells %s\n' \
        "$lv" "${5:-0}" "$3" >"$d/results/level.txt"
    printf 'max_delta_t 0.001\nreplay_interval 0.001\ntime_steps 400\nwindow 0.1 0.2\nwindow_steps 100\nmean_delta_t 0.001\n' >>"$d/results/level.txt"
    printf 'wall_flow_s %s\nwall_clouds_s 20\ngate off\nmvd 20\n' "$((10 * (lv + 2)))" >>"$d/results/level.txt"
    awk -v lv="$lv" 'BEGIN { print "# Time Cd Cs"; for (i = 1; i <= 200; i++) printf "%.4f %.10g 0\n", i * 0.001, 0.40 + 0.01 * lv + ((i % 2) ? 0.05 : -0.05) }' \
        >"$d/postProcessing/forceCoeffs/0/coefficient.dat"
    awk 'BEGIN { print "# Time areaAverage(p)"; for (i = 1; i <= 200; i++) printf "%.4f %.10g\n", i * 0.001, 5 + i }' \
        >"$d/postProcessing/inletPressure/0/surfaceFieldValue.dat"
    awk -v lv="$lv" 'BEGIN { print "# Time areaAverage(p)"; for (i = 1; i <= 200; i++) printf "%.4f %.12g\n", i * 0.001, 5 + i + (-0.30 - lv / 100) * 0.5 * 19.444 ^ 2 }' \
        >"$d/postProcessing/basePressure/0/surfaceFieldValue.dat"
    echo "Forces on the wedge (reference: rear face 0.0144 m2, 19.444 m/s): mean Cd 0.4; side force Cs rms 0.01, dominant frequency 20.3 Hz (Strouhal number f H/U = 0.125, H = 0.12 m); lift" >"$d/results/off/convergence.md"
    for m in 20 8; do
        { echo "# regions"; echo; echo "| region | deposit [kg] | +- | deposit per area over the face's | stands out |"
          echo "|---|---:|---:|---:|---|"
          echo "| left side | 0.1 | 10.0 % | 0.8 | no |"; echo "| right side | 0.1 | 10.0 % | 0.8 | no |"
          echo "| centre | 0 | - | 0 | no |"; echo "| edges | 0.3 | 5.0 % | 1.4 | no |"
          echo "| whole face | $4 | 2.0 % | 1 | - |"; echo; echo "## The halves"
          echo "| whole face | 9 | 1 % | 9 | 1 % | 0 |"; } >"$d/results/compose/mvd$m/regions.md"
    done
    { echo "| d [um] | class [um] | mass share w | rear capture [ppm] | +- | share of the rear deposit |"
      echo "|---:|---|---:|---:|---:|---:|"
      echo "| 10 | 7.07 - 14.1 | 0.5 | 400 | 10 % | 50 % |"; echo "| 20 | 14.1 - 28.3 | 0.5 | 150 | 20 % | 50 % |"; } \
        >"$d/results/compose/mvd20/classes.md"
}
if command -v gnuplot >/dev/null; then
    fab lA -1 1000 0.84; fab lB 0 8000 0.66; fab lC 1 64000 0.615
    "$C" --snowladder "$L" --run "$WORK/runs/lA" --run "$WORK/runs/lB" --run "$WORK/runs/lC" --out "$WORK/lad" \
        >"$WORK/c.out" 2>"$WORK/c.err" || fail "wedge-ladder: $(cat "$WORK/c.err")"
    cat "$WORK/c.out"
    for f in ladder.csv ladder.md total_error.csv gci.csv total_error.png; do
        [ -s "$WORK/lad/$f" ] && ok "wedge-ladder wrote $f" || fail "wedge-ladder: no $f"
    done
    row() { awk -F, -v q="$1" -v r="$2" '$1 == q && $2 == r { print $7, $8 }' "$WORK/lad/ladder.csv"; }
    read -r v s < <(row Cd lB); near "$v" 0.40 1e-9 && near "$s" 0.001 0.001 && ok "Cd of lB: 0.40 (an even alternation)" || fail "Cd of lB: $v $s"
    read -r v s < <(row Cp_b lC); near "$v" -0.31 1e-7 && ok "Cp_b of lC: -0.31" || fail "Cp_b of lC: $v"
    read -r v s < <(row St lA); near "$v" 0.125 0 && near "$s" "$(awk 'BEGIN { print 0.12 / 19.444 / (0.1 * sqrt(12)) }')" 1e-6 &&
        ok "St of lA: 0.125 +- H/(U W sqrt 12)" || fail "St of lA: $v $s"
    read -r v s < <(row face-mvd20 lC); near "$v" 0.615 0 && near "$s" 0.0123 1e-9 && ok "face-mvd20 of lC: 0.615 +- 2 %" || fail "face of lC: $v $s"
    read -r v s < <(row centre-mvd8 lA); near "$v" 0 0 && near "$s" 0 0 && ok "centre-mvd8 (no deposit): 0 +- 0" || fail "centre: $v $s"
    read -r v s < <(row capture-20um lB); near "$v" 150 0 && near "$s" 30 1e-9 && ok "capture-20um: 150 +- 20 %" || fail "capture: $v $s"
    awk -F, '$1 == "Cd" && $2 == "lA" { exit !($9 == 10 && $10 == 20 && $4 == -1 && $5 == 1000) } ' "$WORK/lad/ladder.csv" &&
        ok "times, level and cells of lA" || fail "lA's times: $(grep '^Cd,lA' "$WORK/lad/ladder.csv")"
    grep -q "^face-mvd20: 3 levels, monotone, reference 0.6 (extrapolated)" "$WORK/c.out" && ok "collector -> face monotone to 0.6" ||
        fail "collector: face verdict"
    # the picks (closed form: lC 3.2 % at 50 s; lB 10.2 % at 40 s; lA 40 %)
    grep -q "^wedge-ladder: face-mvd20, the cheapest run: <= 10 %: lC (level 1, 50 s, .*<= 30 %: lB (level 0, 40 s," "$WORK/c.out" &&
        ok "collector: the cheapest runs under 10 and 30 %" || fail "collector picks: $(tail -1 "$WORK/c.out")"
    # ladder.csv names the runs' family; --with: the stored rows of lA and lB joined
    # with the run lC give lC the same total errors as the three-run ladder
    grep -qx '# setting variant test' "$WORK/lad/ladder.csv" && grep -qx '# setting refine_wake 0' "$WORK/lad/ladder.csv" &&
        grep -qx '# setting rear_layers 0' "$WORK/lad/ladder.csv" && ok "ladder.csv: the family's settings" ||
        fail "ladder.csv: no family settings: $(head -8 "$WORK/lad/ladder.csv")"
    grep -v ',lC,' "$WORK/lad/ladder.csv" >"$WORK/stored.csv"
    "$C" --snowladder "$L" --run "$WORK/runs/lC" --with "$WORK/stored.csv" --out "$WORK/with" >"$WORK/w.out" 2>"$WORK/w.err" &&
        diff <(grep ',lC,' "$WORK/lad/total_error.csv") <(grep ',lC,' "$WORK/with/total_error.csv") >/dev/null &&
        ok "--with: lC judged against the stored lA, lB as in the three-run ladder" || fail "--with: $(cat "$WORK/w.err")"
    # a quantity the stored ladder lacks: left out with a note, the others judged
    grep -v '^capture-20um,' "$WORK/stored.csv" >"$WORK/stored2.csv"
    "$C" --snowladder "$L" --run "$WORK/runs/lC" --with "$WORK/stored2.csv" --out "$WORK/with2" >"$WORK/w2.out" 2>"$WORK/w2.err" &&
        grep -q 'note: quantity capture-20um is not on the ladder' "$WORK/w2.err" && ! grep -q '^capture-20um,' "$WORK/with2/total_error.csv" &&
        grep -q '^capture-10um,lC,' "$WORK/with2/total_error.csv" && ok "--with: a quantity the ladder lacks left out with a note" ||
        fail "--with, a missing quantity: $(cat "$WORK/w2.err")"
    refused 2 "run \"lC\" is also the name of a --run folder" "$C" --snowladder "$L" --run "$WORK/runs/lC" --with "$WORK/lad/ladder.csv" --out "$WORK/lad2"
    sed 's/^quantity,run,/quantity,name,/' "$WORK/stored.csv" >"$WORK/bad.csv"
    refused 2 "not the header of post/wedge-ladder" "$C" --snowladder "$L" --run "$WORK/runs/lC" --with "$WORK/bad.csv" --out "$WORK/lad2"
    sed 's/^# setting refine_wake 0$/# setting refine_wake 1/' "$WORK/stored.csv" >"$WORK/other.csv"
    refused 2 "not one mesh family" "$C" --snowladder "$L" --run "$WORK/runs/lC" --with "$WORK/other.csv" --out "$WORK/lad2"
    refused 2 "--with needs at least one --run" "$C" --snowladder "$L" --with "$WORK/stored.csv" --out "$WORK/lad2"
    # refusals: runs of two mesh families (one -refine-wake), a missing level.txt, a name twice, no --out
    fab lW 0 3000 0.7 1
    refused 2 "not the mesh family of --run $WORK/runs/lA (variant test, refine_wake 1" "$C" --snowladder "$L" --run "$WORK/runs/lA" --run "$WORK/runs/lW" --out "$WORK/lad2"
    mkdir -p "$WORK/runs/empty"
    refused 1 "no results/level.txt" "$C" --snowladder "$L" --run "$WORK/runs/lA" --run "$WORK/runs/empty" --out "$WORK/lad2"
    mkdir -p "$WORK/other" && cp -r "$WORK/runs/lA" "$WORK/other/lA"
    refused 2 "a second run named 'lA'" "$C" --snowladder "$L" --run "$WORK/runs/lA" --run "$WORK/other/lA" --out "$WORK/lad2"
    refused 2 "--out" "$C" --snowladder "$L" --run "$WORK/runs/lA" --run "$WORK/runs/lB"
    [ ! -e "$WORK/lad2" ] && ok "nothing written on refusal" || fail "lad2 written"
else
    echo "gnuplot missing: the collector part skipped"
fi

# ---- Allrun -level: refused before anything is done (no OpenFOAM needed) -------
A=$SW_TOP/tutorials/wedge/Allrun
for v in 4 -4 1.5 x ""; do
    refused 2 "-level needs a whole number from -3 to 3" "$A" -test -level "$v"
done
"$A" --help | grep -q -- "-level N" && ok "Allrun --help names -level" || fail "Allrun --help: no -level"

[ "$FAILS" = 0 ] && echo "all passed" || echo "$FAILS failed"
[ "$FAILS" = 0 ]
