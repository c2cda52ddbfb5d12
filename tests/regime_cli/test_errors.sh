#!/usr/bin/env bash
# Bad input of every class: exit 2, one line naming the key/option and value, no files left.
. "$(dirname "$0")/common.sh"
printf 'gamma 0.3\nrho = abc\n' >"$WORK/bad.cfg"
printf 'gamma 0.3\nthis line is malformed\n' >"$WORK/malformed.cfg"
printf 'gamma 0.3\ncolour blue\n' >"$WORK/unknown.cfg"
check() {   # expected-text args...
    local want=$1; shift
    local out=$WORK/out_$RANDOM
    "$@" --out "$out" >/dev/null 2>"$WORK/err"; local rc=$?
    [ $rc -eq 2 ] || fail "'$*': exit $rc, want 2"
    [ "$(wc -l <"$WORK/err")" -eq 1 ] || fail "'$*': want one error line, got: $(cat "$WORK/err")"
    grep -qF -- "$want" "$WORK/err" || fail "'$*': message does not name '$want': $(cat "$WORK/err")"
    [ ! -e "$out" ] || fail "'$*': left $out behind"
}
check "foo" "$SR" map --set foo=1
check "'1'" "$SR" map --set foo=1
check "gamma" "$SR" map --set gamma=-0.5
check "-0.5" "$SR" map --set gamma=-0.5
check "nan" "$SR" map --set gamma=nan
check "cor" "$SR" map --set cor=sticky
check "sticky" "$SR" map --set cor=sticky
check "abc" "$SR" map --config "$WORK/bad.cfg"
check "bad.cfg:2" "$SR" map --config "$WORK/bad.cfg"
check "malformed.cfg:2" "$SR" map --config "$WORK/malformed.cfg"
check "colour" "$SR" map --config "$WORK/unknown.cfg"
check "no/such.cfg" "$SR" map --config "$WORK/no/such.cfg"
check "--nd: '1'" "$SR" map --nd 1
check "10000 x 10000" "$SR" map --nd 10000 --nv 10000
check "--nv: 'x'" "$SR" map --nv x
check "--dmin: '-1e-5'" "$SR" map --dmin -1e-5
check "--degree: '9'" "$SR" map --degree 9
check "--vmin: 'inf'" "$SR" map --vmin inf
check "--vmax" "$SR" map --vmin 2 --vmax 1
check "--angle: '95'" "$SR" map --angle 95
check "unknown option '--frob'" "$SR" map --frob
# an unsorted or repeated --vt / --angle list: refused (a repeat) or sorted with a note before any map
check "--vt: '0,0.5,0.5,1' gives the value 0.5 twice (items 2 '0.5' and 3 '0.5'): give each value once" "$SR" map --vt 0,0.5,0.5,1
check "--angle: '30,0,30' gives the value 30 twice" "$SR" map --angle 30,0,30
# a list out of order: taken in ascending order (one map per value, the table's
# axis increasing), with a one-line note on stderr
"$SR" map --out "$WORK/vtsort" --vt 0.5,0 --nd 6 --nv 6 --no-plot >/dev/null 2>"$WORK/err" || fail "map --vt 0.5,0: $(cat "$WORK/err")"
[ "$(cat "$WORK/err")" = "snowregime map: note: --vt: '0.5,0' taken in ascending order" ] || fail "map --vt 0.5,0: stderr $(cat "$WORK/err")"
grep -q "^ *obliqueVt *(0 0.5);" "$WORK/vtsort/regime.coeffs" && [ -s "$WORK/vtsort/map-vt0.5.csv" ] || fail "map --vt 0.5,0: no combined table"
# overlapping asperities (hours for one impact): refused before any work
check "asperity_spacing: 1.5e-06 m is below 2 asperity_r = 2e-06 m: the asperities would overlap" \
    "$SR" map --set wall=lattice --set asperity_spacing=1.5e-6
# settings and options the wall or the law does not use are refused, not ignored
# before any work: nothing written
check "--points: only for a rough wall (--set wall=lattice); this wall is flat" \
    "$SR" map --out "$WORK/flatpts" --points 128 --nd 6 --nv 6 --no-plot
[ ! -e "$WORK/flatpts" ] || fail "map --points on a flat wall left $WORK/flatpts"
check "--seed: only for a rough wall" "$SR" sensitivity --out "$WORK/flatseed" --seed 3
check "--level: only for a rough wall" "$SR" sensitivity --level 0.3
check "dashpot: both is not used by cor elastic, which has no dashpot" \
    "$SR" map --set cor=elastic --set dashpot=both
check "dashpot: loading is not used by cor thornton-ning" \
    "$SR" sensitivity --set dashpot=loading --set cor=thornton-ning
check "asperity_dz: 1e-06 m is not below the asperity's height 1e-06 m (asperity_shape hemisphere, asperity_r 1e-06 m): asperities sunk that deep are level with the base plane or below it" \
    "$SR" map --set wall=lattice --set asperity_dz=1e-6
# rough-wall settings on a flat wall: refused, not the flat answer without a word
check "settings: asperity_r: 2e-06 is not used on a flat wall (wall flat); set wall=lattice" \
    "$SR" map --set asperity_r=2e-6
check "settings: lattice: hex is not used on a flat wall" "$SR" map --set lattice=hex
check "settings: gamma: 0.5 is not used with adhesion none" "$SR" map --set adhesion=none --set gamma=0.5
printf 'rough_hold 50\n' >"$WORK/hold.cfg"
check "settings: rough_hold: 50 is not used on a flat wall" "$SR" sensitivity --config "$WORK/hold.cfg"
# a key given twice in one config file: an error naming both lines (no silent winner)
printf 'gamma 0.3\n# comment\ngamma = 0.4\n' >"$WORK/twice.cfg"
check "twice.cfg:3: key 'gamma' is given twice (first at line 1)" "$SR" map --config "$WORK/twice.cfg"
# each message names the thing that is wrong
printf 'gamma 0.3\0\n' >"$WORK/nul.cfg"
check "--config: $WORK/nul.cfg:1: the line holds a NUL byte" "$SR" map --config "$WORK/nul.cfg"
check "--set: gamma: '0x1' is not a finite decimal number" "$SR" map --set gamma=0x1
check "--points: '1e9' is out of range [1, 100000]" "$SR" map --set wall=lattice --points 1e9
check "--nd: '99999999999999999999' is out of range" "$SR" map --nd 99999999999999999999
check "--dmin: '0x1p-14' is not a decimal number" "$SR" map --dmin 0x1p-14
# a --vt list too long for the d_crit(v_n, v_t) table: refused before any map (it
# used to coarsen the table's speeds silently)
long=$(seq -s, 0 1 59)
check "--vt: 60 values x 100 speed nodes (the map's --nv 50 spacing" \
    "$SR" map --out "$WORK/longvt" --vt "$long" --no-plot
[ ! -e "$WORK/longvt" ] || fail "map with a too long --vt list left $WORK/longvt"
check "--set: gamma" "$SR" sensitivity --set gamma=1e9
check "--nd: '0'" "$SR" sensitivity --nd 0
check "--accuracy: '-3'" "$SR" convergence --accuracy -3
check "--accuracy: '20,10,10' gives the value 10 twice (items 2 '10' and 3 '10')" "$SR" convergence --accuracy 20,10,10
check "--accuracy: '10,20,20.0' gives the value 20 twice" "$SR" convergence --accuracy 10,20,20.0
check "--vt: '0,,1' has an empty item" "$SR" map --vt 0,,1
check "--angle: '30,' has an empty item" "$SR" map --angle 30,
check "--d: 'nan'" "$SR" convergence --d nan
# commands without --out
for a in "vcrit --d -2e-5|--d: '-2e-5'" "vcrit --d 1e-5,,2e-5|--d: '1e-5,,2e-5' has an empty item" \
         "vcrit --d ,1e-5|--d: ',1e-5' has an empty item" "vcrit --d 1e-5,|--d: '1e-5,' has an empty item" \
         "vcrit --d 2e-5,1e-5,2e-5|--d: '2e-5,1e-5,2e-5' gives the value 2e-05 twice" "vcrit --d 1e-5 --tol 0|--tol: '0'" \
         "vcrit --d 1e-5 --set mu=-1|mu" "collide --d 1e-5 --vn -1|--vn: '-1'" "collide --vn 1|--d: missing" \
         "collide --d 1e-5 --vn 1 --set E=abc|abc" "vcrit --d|--d: missing value" \
         "collide --d 5e-5 --vn 5000|--vn: '5000'" "vcrit --d 1e-5 --vmax 1e4|--vmax: '1e4'" \
         "collide --d 5e-5 --vn 1e-90 --set adhesion=none|--vn = 1e-90 is invalid" "collide --d 0.5 --vn 1|--d: '0.5'" \
         "collide --d 1e-3 --vn 1 --set wall=lattice --set asperity_spacing=1e-9|asperity_spacing: 1e-09 m is below 2 asperity_r" \
         "vcrit --d 1e-5 --level 0.3|--level: only for a rough wall" \
         "collide --d 5e-5 --vn 1e-310|--vn: '1e-310' is too small: the smallest accepted value is 1e-300" \
         "collide --d 0x1p-14 --vn 1|--d: '0x1p-14' is not a decimal number" \
         "vcrit --d 1e-5 --set cor=elastic --set dashpot=both|dashpot: both is not used by cor elastic" \
         "vcrit --d 1e-5 --set wall=lattice --set lattice=hex --set asperity_r=2e-6 --set asperity_spacing=3e-6|below 2 asperity_r = 4e-06 m" \
         "collide --d 5e-5 --vn 1 --x 1e-7|--x, --y: only for a rough wall" \
         "collide --d 5e-5 --vn 1 --y 1e-7|--x, --y: only for a rough wall" \
         "collide --d 5e-5 --vn 1 --stride 5|--stride: only with --trace-csv or --trace-vtk" \
         "collide --d 5e-5 --vn 1 --trace-csv $WORK/t --trace-vtk $WORK/t|the same file '$WORK/t' for both traces"; do
    args=${a%%|*}; want=${a#*|}
    "$SR" $args >/dev/null 2>"$WORK/err"; rc=$?
    [ $rc -eq 2 ] || fail "'$args': exit $rc, want 2"
    grep -qF -- "$want" "$WORK/err" || fail "'$args': message does not name '$want': $(cat "$WORK/err")"
done
# a trace onto a folder, a FIFO, a link or a /dev/full-like node made here (as
# root, --trace-csv /dev/full once renamed a regular file over the device):
# refused before the run, exit 2 naming it, each left as it was
mkdir -p "$WORK/tracedir"; rm -f "$WORK/fifo" "$WORK/tlink" "$WORK/tdev"; mkfifo "$WORK/fifo"
echo keep >"$WORK/ttarget"; ln -s "$WORK/ttarget" "$WORK/tlink"
tdev=; mknod "$WORK/tdev" c 1 7 2>/dev/null && tdev=$WORK/tdev
for t in "$WORK/tracedir|a folder" "$WORK/fifo|a FIFO" "$WORK/tlink|a symbolic link" ${tdev:+"$tdev|a character device"}; do
    what=${t#*|}; t=${t%%|*}
    for o in --trace-csv --trace-vtk; do
        "$SR" collide --d 5e-5 --vn 1 $o "$t" >/dev/null 2>"$WORK/err"; rc=$?
        [ $rc -eq 2 ] && grep -qF -- "cannot write '$t': it exists and is $what" "$WORK/err" \
            || fail "$o $t: exit $rc, $(cat "$WORK/err")"
    done
done
[ -p "$WORK/fifo" ] || fail "--trace-csv onto a FIFO replaced it"
[ -L "$WORK/tlink" ] && [ "$(cat "$WORK/ttarget")" = keep ] || fail "--trace-csv onto a link replaced it"
[ -z "$tdev" ] || [ -c "$tdev" ] || fail "--trace-csv onto a device node replaced it"
[ -z "$(ls -A "$WORK/tracedir")" ] && [ -z "$(ls -A "$WORK" | grep '^\.tmp-')" ] || fail "--trace-csv onto a folder left files"
# --version with more words: refused, not dropped
"$SR" --version map >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF -- "--version takes no arguments, got 'map'" "$WORK/err" || fail "--version map: exit $rc, $(cat "$WORK/err")"
# --out naming an existing file
: >"$WORK/plainfile"
"$SR" map --out "$WORK/plainfile" --nd 4 --nv 4 >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF -- "--out: '$WORK/plainfile'" "$WORK/err" || fail "--out on a file: exit $rc, $(cat "$WORK/err")"
[ ! -s "$WORK/plainfile" ] || fail "--out on a file changed the file"
# the output folder (doc/snowregime.md, "Output folders"): one that holds a file
# of someone else's and no .snowwall-output marker is refused before any work
# (exit 2, the folder and one entry named); --force writes its files beside it
# and deletes nothing; a folder the tool made gets the marker; a link is refused
mkdir -p "$WORK/foreign" && echo mine >"$WORK/foreign/notes.txt"
"$SR" map --out "$WORK/foreign" --nd 6 --nv 6 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF -- "snowregime map: --out: '$WORK/foreign' is not empty and not a SnowWall output folder (holds 'notes.txt'); give --force to write into it" "$WORK/err" \
    || fail "foreign --out: exit $rc, $(cat "$WORK/err")"
[ "$(ls -A "$WORK/foreign")" = notes.txt ] || fail "foreign --out: files written: $(ls -A "$WORK/foreign")"
"$SR" map --out "$WORK/foreign" --nd 6 --nv 6 --no-plot --force >/dev/null 2>"$WORK/err" || fail "foreign --out --force: $(cat "$WORK/err")"
grep -qF -- "note: --force: writing into '$WORK/foreign'" "$WORK/err" || fail "foreign --out --force: no note"
[ "$(cat "$WORK/foreign/notes.txt")" = mine ] && [ -s "$WORK/foreign/map.csv" ] && [ ! -e "$WORK/foreign/.snowwall-output" ] \
    || fail "foreign --out --force: $(ls -A "$WORK/foreign")"
"$SR" convergence --out "$WORK/foreign" --d 1e-5 --accuracy 20 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF "holds 'fit.txt'" "$WORK/err" || fail "convergence into a foreign folder: exit $rc, $(cat "$WORK/err")"
"$SR" map --out "$WORK/own" --nd 6 --nv 6 --no-plot >/dev/null 2>&1 || fail "map into a new folder"
head -1 "$WORK/own/.snowwall-output" | grep -qx "SnowWall output folder" && grep -qx "tool: snowregime map" "$WORK/own/.snowwall-output" \
    || fail "no marker in a folder map made"
echo mine >"$WORK/own/notes.txt"
"$SR" sensitivity --out "$WORK/own" --nd 4 --nv 4 --no-plot >/dev/null 2>"$WORK/err" || fail "sensitivity into an output folder: $(cat "$WORK/err")"
[ "$(cat "$WORK/own/notes.txt")" = mine ] && [ -s "$WORK/own/sensitivity.csv" ] && [ -s "$WORK/own/map.csv" ] || fail "own folder: $(ls -A "$WORK/own")"
ln -s "$WORK/own" "$WORK/ownlink"
"$SR" map --out "$WORK/ownlink" --nd 6 --nv 6 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF "is a symbolic link" "$WORK/err" || fail "--out a link: exit $rc, $(cat "$WORK/err")"
# an output name taken by a FIFO or a /dev/full-like node: refused before the work, left as it was
rm -f "$WORK/own/fit.txt"; mkfifo "$WORK/own/fit.txt"
"$SR" map --out "$WORK/own" --nd 6 --nv 6 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF "cannot write '$WORK/own/fit.txt': it exists and is a FIFO" "$WORK/err" && [ -p "$WORK/own/fit.txt" ] \
    || fail "fit.txt a FIFO: exit $rc, $(cat "$WORK/err")"
rm -f "$WORK/own/sensitivity.md"
if mknod "$WORK/own/sensitivity.md" c 1 7 2>/dev/null; then
    "$SR" sensitivity --out "$WORK/own" --nd 4 --nv 4 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
    [ $rc -eq 2 ] && grep -qF "it exists and is a character device" "$WORK/err" && [ -c "$WORK/own/sensitivity.md" ] \
        || fail "sensitivity.md a device node: exit $rc, $(cat "$WORK/err")"
fi
[ -z "$(ls -A "$WORK/own" | grep '^\.tmp-')" ] || fail "temporaries left in $WORK/own"
# a list out of order is taken in ascending order, with a note
"$SR" vcrit --d 3e-5,1e-5 >"$WORK/vc" 2>"$WORK/err" || fail "vcrit --d 3e-5,1e-5: $(cat "$WORK/err")"
grep -qx "snowregime vcrit: note: --d: '3e-5,1e-5' taken in ascending order" "$WORK/err" || fail "no ascending note: $(cat "$WORK/err")"
[ "$(grep -v '^#' "$WORK/vc" | cut -f1 | tr '\n' ' ')" = "1e-05 3e-05 " ] || fail "vcrit --d 3e-5,1e-5: not ascending: $(cat "$WORK/vc")"
# a failure after the folder exists leaves the old files untouched and no temporaries
mkdir -p "$WORK/keep" && echo old >"$WORK/keep/fit.txt"
"$SR" map --out "$WORK/keep" --set gamma=abc >/dev/null 2>&1
[ "$(cat "$WORK/keep/fit.txt")" = old ] || fail "existing output changed by a failed run"
[ "$(ls -A "$WORK/keep")" = fit.txt ] || fail "failed run left files: $(ls -A "$WORK/keep")"
# a computation failure (no interface in an explicit range) leaves nothing (exit 1)
"$SR" map --out "$WORK/none/deep" --nd 4 --nv 4 --vmin 20 --vmax 40 --no-plot >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 1 ] || fail "no-interface map: exit $rc, want 1 ($(cat "$WORK/err"))"
[ ! -e "$WORK/none" ] || fail "no-interface map left $WORK/none behind"
ok "error checks done"
# the slowest accepted impacts get the physical answer: stick with adhesion
for v in 1e-60 1e-90 1e-300; do
    "$SR" collide --d 50e-6 --vn $v | grep -q '^outcome: stick' || fail "collide --vn $v: not a stick"
done
"$SR" collide --d 5e-5 --vn 1e-60 --set adhesion=none | grep -q '^e_n: 1$' || fail "collide --vn 1e-60, Hertz: not an elastic rebound"
# binary data as a config: a named error with no raw bytes on stderr
head -c 400 /dev/urandom | tr -d '\n#' | head -c 300 >"$WORK/garbage.cfg"
"$SR" vcrit --d 1e-5 --config "$WORK/garbage.cfg" >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] || fail "garbage config: exit $rc, want 2"
grep -q "garbage.cfg:1" "$WORK/err" || fail "garbage config: message does not name the file and line"
LC_ALL=C grep -q '[^[:print:]]' "$WORK/err" && fail "garbage config: raw bytes on stderr"
# an interrupted map leaves nothing: killed while its new folder
# holds temporaries, the folder (and the parent it created) is removed
( cd "$WORK" && exec "$SR" map --set wall=lattice --points 4096 --nd 40 --nv 40 --vmin 0.1 --vmax 10 --force --out int/deep >/dev/null 2>&1 ) &
pid=$!
for _ in $(seq 300); do [ -d "$WORK/int/deep" ] && break; sleep 0.1; done
[ -d "$WORK/int/deep" ] || fail "interrupt test: the map never created its folder"
kill -TERM "$pid"; wait "$pid"; rc=$?
[ $rc -eq 143 ] || fail "interrupted map: exit $rc, want 143 (SIGTERM)"
[ ! -e "$WORK/int" ] || fail "interrupted map left $(find "$WORK/int" | head -3)"
# ... and while gnuplot draws its PNG: the plotting child is stopped
# before the temporaries go. A stand-in gnuplot on PATH signals that it runs, then
# writes its output 3 s later unless it is stopped.
mkdir -p "$WORK/fakebin"
cat >"$WORK/fakebin/gnuplot" <<'GP'
#!/bin/sh
out=$(sed -n "s/^set output '\(.*\)'/\1/p" "$1")   # read first, as gnuplot does
touch "$GP_MARK"
sleep 3
echo png >"$out"
GP
chmod +x "$WORK/fakebin/gnuplot"
mkdir -p "$WORK/plot"   # a folder that exists: the map removes only what it made
( cd "$WORK" && GP_MARK="$WORK/gp.started" PATH="$WORK/fakebin:$PATH" \
    exec "$SR" map --nd 6 --nv 6 --out plot >/dev/null 2>&1 ) &
pid=$!
for _ in $(seq 300); do [ -e "$WORK/gp.started" ] && break; sleep 0.1; done
[ -e "$WORK/gp.started" ] || fail "interrupt test: the stand-in gnuplot never ran"
kill -TERM "$pid"; wait "$pid"; rc=$?
[ $rc -eq 143 ] || fail "map interrupted while plotting: exit $rc, want 143 (SIGTERM)"
sleep 4
[ -z "$(ls -A "$WORK/plot")" ] || fail "map interrupted while plotting left $(ls -A "$WORK/plot" | head -3)"
finish
