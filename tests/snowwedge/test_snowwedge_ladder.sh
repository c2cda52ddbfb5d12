#!/usr/bin/env bash
# test_snowwedge_ladder.sh - the snowwedge commands of the runs against each other
# (tools/snowwedge/swe_cmd_ladder.c) on synthetic run folders with known answers:
# a run's rung (level.txt) and its rows (St with the spectrum's resolution error,
# the composed regions, the classes), a stored ladder's check and its join with
# the runs, the plot's points and ranges, the cheapest run, two resolutions
# compared (z, change, verdict), the error-time points and plot script, and the
# composition's options and per-class table; bad inputs exit 1 or 2 with one
# line naming the input.
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"
bad() {  # bad RC TEXT args...: exit RC, one line holding TEXT, nothing on stdout
    local want_rc=$1 want=$2; shift 2
    "$S" "$@" > "$tmp/out" 2> "$tmp/err"; local rc=$?
    check "refused ($want): exit $want_rc, one line" "[ $rc -eq $want_rc ] && [ \$(wc -l < '$tmp/err') -eq 1 ] && grep -qF -- \"$want\" '$tmp/err' && [ ! -s '$tmp/out' ]"
}

# ---- a run: level.txt, convergence.md, two composed sprays, the classes
r="$tmp/runA"
mkdir -p "$r/results/off" "$r/results/compose/mvd20" "$r/results/compose/mvd8"
printf 'level -1\nvariant coarse\nrefine_wake 0\nhalfstep 0\nfull 1\ncells 100\nwindow 0.4  0.8\nmean_delta_t 0.001\nwall_flow_s 10\nwall_clouds_s 5\ngate off\nmvd 20\n' > "$r/results/level.txt"
echo 'Forces: mean Cd 0.4; side force (Strouhal number f H/U = 0.185, H = 0.12 m); lift (St 0.06).' > "$r/results/off/convergence.md"
for m in 20 8; do
    { echo '| region | deposit [kg] | +- | x | y |'; echo '|---|---:|---:|---:|---|'
      echo '| left side | 1e-05 | 10.0 % | 1 | no |'; echo '| right side | 2e-05 | 20 % | 1 | no |'
      echo '| centre | 0 | - | 0 | no |'; echo '| edges | 4e-05 | 50 % | 1 | no |'
      echo "| whole face | 0.0001 | 5 % | 1 | - |"; echo; echo '## The halves'
      echo '| left side | 9 | 9 % | 9 | 9 |'; } > "$r/results/compose/mvd$m/regions.md"
done
{ echo '| d [um] | class [um] | w | rear capture [ppm] | +- | share |'; echo '|---:|---|---:|---:|---:|---:|'
  echo '| 5 | 2 - 7 | 0.1 | 28 | 50 % | 1 % |'; echo '| 10 | 7 - 14 | 0.9 | 0 | - | 0 % |'; } > "$r/results/compose/mvd20/classes.md"
cp "$r/results/compose/mvd20/classes.md" "$r/results/compose/mvd8/classes.md"
printf '0.4,0.8\t0.0052900377459\tA,full,-1,100,0.001\t,10,5\t20\tvariant coarse;refine_wake 0;halfstep 0;rear_layers 0;gate off;mvd 20\n' > "$tmp/want"
"$S" ladder-level --name A "$r" > "$tmp/level"
check "ladder-level: window, Cp scale 1/(0.5 x 19.444^2), columns, spray, family (rear_layers 0 when absent)" "cmp -s '$tmp/want' '$tmp/level'"
"$S" ladder-rows --name A "$r" > "$tmp/rows"
check "ladder-rows: St 0.185 +- 0.12 / 19.444 / (0.4 sqrt(12))" "grep -qx 'St,A,full,-1,100,0.001,0.185,0.00445395,10,5' '$tmp/rows'"
check "ladder-rows: the regions of the first table, se = value x error" "grep -qx 'edges-mvd20,A,full,-1,100,0.001,4e-05,2e-05,10,5' '$tmp/rows' && grep -qx 'centre-mvd8,A,full,-1,100,0.001,0,0,10,5' '$tmp/rows' && [ \$(grep -c -- '^[a-z]*-mvd' '$tmp/rows') = 12 ]"
check "ladder-rows: the left/right ratio 1e-5 / 2e-5 = 0.5, se 0.5 sqrt(0.1^2 + 0.2^2)" "grep -qx 'lr-mvd20,A,full,-1,100,0.001,0.5,0.111803,10,5' '$tmp/rows'"
check "ladder-rows: the classes' capture" "grep -qx 'capture-5um,A,full,-1,100,0.001,28,14,10,5' '$tmp/rows' && grep -qx 'capture-10um,A,full,-1,100,0.001,0,0,10,5' '$tmp/rows'"
# a played-back flow: St of the solved library, its error the half-bin as a uniform error
cp "$r/results/off/convergence.md" "$tmp/conv.md"
echo 'The window...: side force Cs rms 0.02, peak 30.0 +- 5.0 Hz (Strouhal number of the solved flow = 0.185, +- 0.031); lift' >> "$r/results/off/convergence.md"
"$S" ladder-rows --name A "$r" > "$tmp/rows"
check "ladder-rows: St of the solved flow 0.185 +- 0.031 / sqrt(3)" "grep -qx 'St,A,full,-1,100,0.001,0.185,0.0178979,10,5' '$tmp/rows'"
cp "$tmp/conv.md" "$r/results/off/convergence.md"
sed -i '/^cells/d' "$r/results/level.txt"
bad 1 "level.txt: no 'cells' line" ladder-level --name A "$r"
bad 1 "no results/level.txt" ladder-rows --name A "$tmp"

# ---- a stored ladder: its check, its join with the runs
hdr=quantity,run,design,level,cells,step,value,se,t_flow,t_clouds
{ echo '# setting variant coarse'; echo '# setting gate off'; echo; echo "$hdr"
  echo 'St,B,default,0,400,0.0005,0.2,0.004,20,9'; echo 'Cd,B,default,0,400,0.0005,0.4,0.01,20,9'; } > "$tmp/stored.csv"
"$S" ladder-stored --what "--check x" "$tmp/stored.csv" > "$tmp/rows2"
check "ladder-stored: the two rows" "[ \$(wc -l < '$tmp/rows2') = 2 ] && grep -q '^Cd,B,' '$tmp/rows2'"
printf '%s\nCd,B,default,zero,400,1,1,1,1,1\n' "$hdr" > "$tmp/bad.csv"
bad 2 "--check x: line 2: not a row of ten fields" ladder-stored --what "--check x" "$tmp/bad.csv"
printf '# c\nquantity,run\n' > "$tmp/bad.csv"
bad 2 "line 2: not the header" ladder-stored --what w "$tmp/bad.csv"
printf '%s\n' "$hdr" > "$tmp/bad.csv"
bad 2 "w: no row" ladder-stored --what w "$tmp/bad.csv"
bad 2 'line 5: run' ladder-stored --what w --names " A B " "$tmp/stored.csv"
{ echo "$hdr"; echo 'St,A,full,-1,100,0.001,0.185,0.004,10,5'; echo 'Cp_b,A,full,-1,100,0.001,-0.3,0.01,10,5'; } > "$tmp/runs.csv"
"$S" ladder-join --with "$tmp/stored.csv" --family "variant coarse;gate off;mvd 20" --names " A " "$tmp/runs.csv" > "$tmp/joined" 2> "$tmp/err"
check "ladder-join: the runs' St, the stored rows after them" "[ \"\$(cut -d, -f1,2 '$tmp/joined' | tr '\n' ' ')\" = 'quantity,run St,A St,B Cd,B ' ]"
check "ladder-join: Cp_b, not on the stored ladder, left out with a note" "grep -qx 'snowwedge: note: quantity Cp_b is not on the ladder of --with $tmp/stored.csv: not judged' '$tmp/err'"
bad 2 "its runs have 'variant coarse', the --run runs 'variant fine'" ladder-join --with "$tmp/stored.csv" --family "variant fine" --names " A " "$tmp/runs.csv"

# ---- the plot of the total error and the cheapest run
{ echo 'quantity,run,design,level,cells,t_total_s,value,se,disc,total,rel_total,reference,reference_kind'
  echo 'Cd,A,default,-1,100,10,0.4,0.01,0.01,0.02,0.05,0.39,finest'
  echo 'Cd,B,default,0,400,1000,0.39,0.01,0,0.01,0.5,0.39,finest'
  echo 'St,B,default,0,400,1000,0.2,0.004,0,0.004,,0.2,finest'; } > "$tmp/te.csv"
"$S" ladder-plot --quantity Cd --targets 10,30 --points "$tmp/pts" --png x.png "$tmp/te.csv" > "$tmp/gp"
check "ladder-plot: the points (error in %)" "[ \"\$(cat '$tmp/pts')\" = \"\$(printf '10 5 A(default)\n1000 50 B(default)')\" ]"
check "ladder-plot: ranges 5:2000 and 5/1.5:75, the targets as lines" "grep -qx 'set xrange \[5:2000\]' '$tmp/gp' && grep -qx 'set yrange \[3.33333:75\]' '$tmp/gp' && [ \$(grep -c '^set arrow from graph 0, first [13]0 to graph 1' '$tmp/gp') = 2 ]"
check "ladder-plot: every run its own key entry, the key outside the data, no label over a point" "grep -qx 'set key outside right top vertical Left reverse' '$tmp/gp' && grep -q 'title \"A(default)\"' '$tmp/gp' && grep -q 'title \"B(default)\"' '$tmp/gp' && ! grep -q 'with labels' '$tmp/gp'"
bad 2 "--plot St: no such quantity with a relative error" ladder-plot --quantity St --targets 10 --points "$tmp/pts" --png x.png "$tmp/te.csv"
{ echo '## Runs'; echo '| Cd | a | b |'; echo '## Discretization'; echo '| q | x | <= 10 % | <= 30 % |'
  echo '| Cd | 3 | converged | none | B (level 0, 1000 s, 5 %) |'; } > "$tmp/ladder.md"
check "ladder-cheapest: the last columns of the quantity's row" "[ \"\$('$S' ladder-cheapest --quantity Cd --targets 10,30 '$tmp/ladder.md')\" = 'wedge-ladder: Cd, the cheapest run: <= 10 %: none; <= 30 %: B (level 0, 1000 s, 5 %);' ]"

# ---- two resolutions: left B 100 +- 3 %, R 110 +- 4 %; face 200 +- 1 %, 300 +- 1 %
for d in base ref; do mkdir -p "$tmp/$d/compose/mvd20"; done
mk() {  # mk DIR LEFT ERR FACE ERR: regions.md and classes.md
    { echo '| region | deposit [kg] | +- | a | b |'; echo '|---|---:|---:|---:|---|'
      echo "| left side | $2 | $3 % | 1 | no |"; echo '| edges | 0 | - | 0 | no |'; echo "| whole face | $4 | $5 % | 1 | - |"; } > "$1/compose/mvd20/regions.md"
    { echo '| d [um] | class | w | capture | +- | share |'; echo '|---|---|---|---|---|---|'; echo "| 5 | x | 1 | $2 | $3 % | 1 |"; } > "$1/compose/mvd20/classes.md"
}
mk "$tmp/base" 100 3 200 1; mk "$tmp/ref" 110 4 300 1
"$S" resolution --base "$tmp/base" --refined "$tmp/ref" > "$tmp/res"
check "resolution: left agrees: +10.0 % +- 5.5 % (1.1 x 5 %), z = 10 / 5.33 = +1.9, within +-21 %" "grep -qxF '| left side | 100 | 3 % | 110 | 4 % | +10.0 % | 5.5 % | +1.9 | agrees (change within +-21 % at 2 sigma) |' '$tmp/res'"
check "resolution: the face differs (z = 100 / sqrt(13) = +27.7), bare edges no deposit" "grep -qxF '| whole face | 200 | 1 % | 300 | 1 % | +50.0 % | 2.1 % | +27.7 | differs |' '$tmp/res' && grep -qxF '| edges | 0 | - | 0 | - | - | - | - | no deposit |' '$tmp/res'"
check "resolution: the counts" "grep -qxF 'Rows with snow (regions and face): 2; differing by more than 2 standard errors: 1.' '$tmp/res' && grep -qxF 'Classes with snow: 1; differing by more than 2 standard errors: 0.' '$tmp/res'"
bad 1 "compose missing" resolution --base "$tmp/base" --refined "$tmp"
bad 1 "cannot read $tmp/base/compose/mvd8/regions.md" resolution --base "$tmp/base" --refined "$tmp/ref" --mvd 8
bad 2 "--mvd needs diameters" resolution --base "$tmp/base" --refined "$tmp/ref" --mvd 2x

# ---- error against run time: points and plot
{ echo 'design,wall_s,face,left,right,centre,edges'; echo 'flow,250,,,,,'; echo 'spray,40,20,30,30,40,'; echo 'classes,0,5,8,9,12,'; } > "$tmp/cost.csv"
"$S" errortime-points --region left "$tmp/cost.csv" run > "$tmp/p"
check "errortime-points: spray only (flow and no time left out)" "[ \"\$(cat '$tmp/p')\" = \"\$(printf 'spray\trun\t40\t30')\" ]"
"$S" errortime-plot --region left --title T --dir "$tmp" "$tmp/p" > "$tmp/gp"
check "errortime-plot: the design's series, its line e sqrt(t / x)" "[ -s '$tmp/d_spray' ] && grep -qF \"'$tmp/d_spray' using 3:4 with points pt 7 ps 1.5 title 'spray', (40) * (30 / x) ** 2 > 0 ? 30 * sqrt(40 / x)\" '$tmp/gp'"
bad 2 "--region: 'top' is not" errortime-points --region top "$tmp/cost.csv" run
# its files are its own: a design's file already there, a design that is a path, a run or
# title that would end a gnuplot string, a time that is not a number: refused, nothing written
bad 2 "$tmp/d_spray exists: not replaced" errortime-plot --region left --title T --dir "$tmp" "$tmp/p"
mkdir "$tmp/et"
printf 'spray\trun\t40\t30\n../x\trun\t40\t30\n' > "$tmp/p2"
bad 2 "design '../x' is not a name" errortime-plot --region left --title T --dir "$tmp/et" "$tmp/p2"
printf "spray\trun\t40\t30\nspray\tru'n\t40\t30\n" > "$tmp/p2"
bad 2 "run 'ru'n' holds a quote" errortime-plot --region left --title T --dir "$tmp/et" "$tmp/p2"
printf 'spray\trun\t40\tsystem(1)\n' > "$tmp/p2"
bad 2 "error 'system(1)' is not a number" errortime-plot --region left --title T --dir "$tmp/et" "$tmp/p2"
bad 2 "--title 'it's' holds a quote" errortime-plot --region left --title "it's" --dir "$tmp/et" "$tmp/p"
check "errortime-plot: nothing written by the refusals" "[ -z \"\$(ls -A '$tmp/et')\" ]"
printf 'spray\tA\t40\t30\nspray\tB\t80\t20\n' > "$tmp/p2"
"$S" errortime-plot --region left --title T --dir "$tmp/et" "$tmp/p2" > /dev/null
check "errortime-plot: a design's points in one file, in order" "[ \"\$(cut -f2 '$tmp/et/d_spray' | tr '\n' ' ')\" = 'A B ' ]"
# ladder-plot --points: never over a folder or a device
mkdir "$tmp/ptsdir"
bad 2 "cannot write '$tmp/ptsdir': it exists and is a folder" ladder-plot --quantity Cd --targets 10 --points "$tmp/ptsdir" --png x.png "$tmp/te.csv"
bad 2 "cannot write '/dev/null': it exists and is a character device" ladder-plot --quantity Cd --targets 10 --points /dev/null --png x.png "$tmp/te.csv"

# ---- the composition: its options and the classes' table
bad 2 "--mvd: 'abc' is not a diameter in [0.1, 1000] um" compose-check --mvd abc --sigma-g 1.8 --range 2,150 --freeze 1.03 --sampled 1
bad 2 "--range: '5' is not MIN,MAX" compose-check --mvd 20 --sigma-g 1.8 --range 5 --freeze 1.03 --sampled 1
bad 2 "--sampled: '-1' is not in (0, 1]" compose-check --sampled -1
check "compose-check: good options, silent" "[ -z \"\$('$S' compose-check --mvd 20 --sigma-g 1.8 --range 2,150, --freeze 1.03 --sampled 0.5 2>&1)\" ]"
c="$tmp/sizes/d5um"; mkdir -p "$c"
printf 'injected = 4\n' > "$c/mass_balance.txt"; printf 'patch,a,deposit_kg\nrear,1,0.002\n' > "$c/deposit_per_patch.csv"
w='| 1 sticks, 1 origins, 2 kg, n_eff 1.0, +- 100 % | 0 | 0 | 0 | 4 sticks, 2 origins, 0.5 kg, n_eff 1.5, +- 82 % |'
printf '| period | l | r | c | e | f |\n| window 0.4 .. 0.8 s %s\n| first half %s\n' "$w" "$w" > "$c/rear_statistics.md"
"$S" compose-table --sampled 0.5 "$tmp/sizes" 5 > "$tmp/ct"
check "compose-table: injected x sampled, the rear deposit, mass and n_eff per region, no halves without both" "[ \"\$(cat '$tmp/ct')\" = '5 2 0.002 2 1 0 0 0 0 0 0 0.5 1.5  ' ]"
bad 1 "d7um: no injected mass" compose-table --sampled 1 "$tmp/sizes" 7

finish
