#!/usr/bin/env bash
# test_snowwedge_plot.sh - snowwedge panels and compare (the pictures of
# tutorials/wedge/post) with a stand-in gnuplot on the PATH that keeps its script
# and writes the file of its "set output": the script's size and titles for one
# and for four panels, the picture renamed into place (mode 644, no temporary
# left), an existing non-regular --out refused and kept, a failing gnuplot
# leaving nothing; each refusal of the options with its message and exit
# status; the gate comparison's tables with a stand-in snowphoto.
# shellcheck source=common.sh
. "$(dirname "$0")/common.sh"

mkdir -p "$tmp/bin" "$tmp/w"
cat > "$tmp/bin/gnuplot" <<'EOF'
#!/usr/bin/env bash
# stand-in gnuplot: the script kept in $GP_KEEP, "PNG" into the output; GP_FAIL set: exit 1
cat > "$GP_KEEP"
[ -z "${GP_FAIL:-}" ] || exit 1
out=$(sed -n "s/^set output '\(.*\)'$/\1/p" "$GP_KEEP")
echo PNG > "$out"
EOF
cat > "$tmp/bin/snowphoto" <<'EOF'
#!/usr/bin/env bash
echo "row $*"
EOF
chmod +x "$tmp/bin/gnuplot" "$tmp/bin/snowphoto"
export PATH="$tmp/bin:$PATH" GP_KEEP="$tmp/script.gp"
printf 'y,z,deposit_kg_m2\n-0.05,-0.04,0.1\n0.05,0.06,0.4\n' > "$tmp/a.csv"
printf 'y,z,deposit_kg_m2\n-0.05,-0.04,0\n0.05,0.06,0.8\n' > "$tmp/b.csv"
P() { (cd "$tmp" && "$S" panels --name wedge-panels "$@" > out.txt 2> err.txt; echo $? > rc.txt); }
said() { [ "$(cat "$tmp/rc.txt")" = "$1" ] && [ "$(cat "$tmp/err.txt")" = "$2" ]; }

# ---- one panel: its title below the figure's; three lines: 578 px ------------------------
P --out w/one.png --title "Rear face" a.csv 'snow\nrear total 1 kg'
check "one panel drawn" 'said 0 "" && [ "$(cat "$tmp/w/one.png")" = PNG ]'
check "one panel: size and title" \
    'grep -qx "set terminal pngcairo size 580,578 font '"'DejaVu Sans,11'"'" "$GP_KEEP" &&
     grep -qx "set title \"Rear face\\\\nsnow\\\\nrear total 1 kg\"" "$GP_KEEP"'
check "one panel: scale and outline" \
    'grep -qx "set cbrange \[0:0.4\]" "$GP_KEEP" &&
     grep -qx "set xrange \[-0.1-0.005:0.1+0.005\]; set yrange \[-0.09-0.005:0.11+0.005\]" "$GP_KEEP"'
check "the picture's mode 644, its temporary in its folder and gone" \
    '[ "$(stat -c %a "$tmp/w/one.png")" = 644 ] && grep -q "^set output '"'w/.tmp-one.png."'" "$GP_KEEP" &&
     [ -z "$(ls -A "$tmp/w" | grep -v "^one.png$")" ]'

# ---- four panels: 1960 px; a long figure title wrapped at 256 characters ---------------
long=$(printf 'word %.0s' {1..60})
P --out w/four.png --title "$long" a.csv A b.csv B a.csv C b.csv D
check "four panels drawn" 'said 0 "" && [ "$(grep -c "^plot " "$GP_KEEP")" = 4 ] &&
     grep -q "^set multiplot layout 1,4 title " "$GP_KEEP" && grep -qx "unset multiplot" "$GP_KEEP"'
check "four panels: 1960 px, two title lines and the panels' line: 578 px" \
    'grep -q "size 1960,578 " "$GP_KEEP" && grep -qx "set cbrange \[0:0.8\]" "$GP_KEEP"'

# ---- the output contract ---------------------------------------------------------------
# refused RC MESSAGE ARGS...: the command ($run: P or C) exits RC saying MESSAGE
refused() { local rc=$1 msg=$2; shift 2; "$run" "$@"; check "$msg ($rc)" "said $rc $(printf %q "$msg")"; }
run=P
mkdir "$tmp/w/dir"; ln -s one.png "$tmp/w/link"; mkfifo "$tmp/w/fifo"
refused 2 "wedge-panels: --out: 'w/dir' exists and is not a regular file" --out w/dir --title T a.csv A
refused 2 "wedge-panels: --out: 'w/fifo' exists and is not a regular file" --out w/fifo --title T a.csv A
check "the FIFO kept" '[ -p "$tmp/w/fifo" ]'
refused 2 "wedge-panels: --out: 'w/link' is a symbolic link: give the file itself" --out w/link --title T a.csv A
refused 2 "wedge-panels: --out: folder 'no/such' does not exist" --out no/such/o.png --title T a.csv A
rm -f "$tmp/w/fifo"
echo old > "$tmp/w/keep.png"
GP_FAIL=1 P --out w/keep.png --title T a.csv A
check "gnuplot failing: exit 1, nothing written, no temporary" \
    'said 1 "wedge-panels: gnuplot failed" && [ "$(cat "$tmp/w/keep.png")" = old ] &&
     [ -z "$(ls -A "$tmp/w" | grep "^\.")" ]'

# ---- the refusals of the options --------------------------------------------------------
: > "$tmp/empty.csv"; echo header > "$tmp/head.csv"
need="wedge-panels: --out and at least one CSV TITLE pair are required"
refused 2 "$need"
refused 2 "$need" --out o.png --title T
refused 2 "wedge-panels: --out needs a file (see --help)" --out
refused 2 "wedge-panels: --out needs a file (see --help)" --out ""
refused 2 "wedge-panels: --title needs a text (see --help)" --title
refused 2 "wedge-panels: unknown option '--frob' (see --help)" --frob
refused 2 "wedge-panels: map 'a.csv' has no title" --out o.png --title T a.csv
refused 1 "wedge-panels: map 'no.csv' missing or empty" --out o.png --title T no.csv A
refused 1 "wedge-panels: map 'empty.csv' missing or empty" --out o.png --title T empty.csv A
refused 1 "wedge-panels: map 'head.csv' missing or empty" --out o.png --title T head.csv A
P --out o.png a.csv --help
check "a title may start with --" 'said 0 ""'
P --out o.png --help
check "--help" 'said 0 "" && grep -q "^Usage: wedge-panels --out PNG" "$tmp/out.txt"'

# ---- compare -------------------------------------------------------------------------------
r="$tmp/res"
for g in off tangential shear regime; do
    mkdir -p "$r/$g"; cp "$tmp/a.csv" "$r/$g/rear_deposit.csv"
    printf 'patch,area_m2,deposit_kg\nrear,0.0144,1e-4\n' > "$r/$g/deposit_per_patch.csv"
done
cp "$tmp/b.csv" "$r/shear/rear_deposit.csv"
printf 'parcel_mass = 2e-9\nsplit = no\n' > "$r/off/mass_balance.txt"
C() { (cd "$tmp" && "$S" compare --name wedge-compare "$@" > out.txt 2> err.txt; echo $? > rc.txt); }
C --results res --snowphoto bin/snowphoto --rel 0.5
check "compare: the picture of four panels on one scale" \
    'said 0 "" && [ -f "$r/gates_compare.png" ] && grep -qx "set cbrange \[0:0.8\]" "$GP_KEEP" &&
     grep -qx "set title \"+ tangential + shear gate\\\\nrear face total 1e-4 kg\"" "$GP_KEEP" &&
     grep -qx "wedge-compare: res/gates_compare.png" "$tmp/out.txt"'
rows() { grep -x "row regions --sim res/$1/rear_deposit.csv --sim-threshold 0.4 --label $1$2" "$r/regions.md"; }
check "compare: gates_per_patch.md and regions.md written and shown" \
    'grep -q "^| patch | off: deposit" "$r/gates_per_patch.md" && grep -q "^| patch | off: deposit" "$tmp/out.txt" &&
     rows off " --parcel-mass 2e-9" && rows regime "" && grep -q "Threshold = 0.5 x the$" "$r/regions.md" &&
     grep -q "four settings (0.8 kg/m2)" "$tmp/out.txt"'
run=C
refused 2 "wedge-compare: --results is required"
refused 2 "wedge-compare: --results needs a folder (see --help)" --results
refused 2 "wedge-compare: --rel '0' outside (0, 1]" --results res --rel 0
refused 2 "wedge-compare: --rel 'x' outside (0, 1]" --results res --rel x
refused 2 "wedge-compare: --rel '1.5' outside (0, 1]" --results res --rel 1.5
refused 2 "wedge-compare: unknown option '--frob' (see --help)" --results res --frob
refused 1 "wedge-compare: no/exe not found (run ./Allwmake)" --results res --snowphoto no/exe
refused 1 "wedge-compare: missing no/off/rear_deposit.csv (run Allrun -compare)" \
    --results no --snowphoto bin/snowphoto
# a text that awk's test passes as a string but is no number: refused as snowwedge map-max did
refused 1 "snowwedge: --rel: '0.5abc' is not a number" --results res --snowphoto bin/snowphoto --rel 0.5abc
rm -f "$r/regions.md"; mkdir "$r/regions.md"
C --results res --snowphoto bin/snowphoto
check "compare: a folder where regions.md goes refused (2), no temporary left" \
    "said 2 \"wedge-compare: 'res/regions.md' exists and is not a regular file: not replaced\" &&
     [ -z \"\$(ls -A \"\$r\" | grep '^\.')\" ]"
finish
