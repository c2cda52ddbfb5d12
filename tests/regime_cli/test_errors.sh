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
# an unsorted or repeated --vt / --angle list (issue 22: found after the maps, exit 1)
check "--vt: '0,0.5,0.5,1': value 0.5 (item 3) is not above 0.5 (item 2)" "$SR" map --vt 0,0.5,0.5,1
check "--vt: '0,1,0.5': value 0.5 (item 3) is not above 1 (item 2)" "$SR" map --vt 0,1,0.5
check "--angle: '30,0': value 0 (item 2) is not above 30" "$SR" map --angle 30,0
# overlapping asperities (issue 22: one impact ran for hours): refused before any work
check "asperity_spacing: 1.5e-06 m is below 2 asperity_r = 2e-06 m: the asperities would overlap" \
    "$SR" map --set wall=lattice --set asperity_spacing=1.5e-6
# settings and options the wall or the law does not use are refused, not ignored
# (issue 22, item 3), before any work: nothing written
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
# rough-wall settings on a flat wall (hostile sweep, issue 22: the flat answer without a word)
check "settings: asperity_r: 2e-06 is not used on a flat wall (wall flat); set wall=lattice" \
    "$SR" map --set asperity_r=2e-6
check "settings: lattice: hex is not used on a flat wall" "$SR" map --set lattice=hex
check "settings: gamma: 0.5 is not used with adhesion none" "$SR" map --set adhesion=none --set gamma=0.5
printf 'rough_hold 50\n' >"$WORK/hold.cfg"
check "settings: rough_hold: 50 is not used on a flat wall" "$SR" sensitivity --config "$WORK/hold.cfg"
# a key given twice in one config file (hostile sweep, issue 22: the later one won silently)
printf 'gamma 0.3\n# comment\ngamma = 0.4\n' >"$WORK/twice.cfg"
check "twice.cfg:3: key 'gamma' is given twice (first at line 1)" "$SR" map --config "$WORK/twice.cfg"
# messages that named the wrong thing (issue 22, item 4)
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
check "--accuracy: '20,10,10': value 10 (item 2) is not above 20 (item 1)" "$SR" convergence --accuracy 20,10,10
check "--accuracy: '10,20,20': value 20 (item 3) is not above 20 (item 2)" "$SR" convergence --accuracy 10,20,20
check "--d: 'nan'" "$SR" convergence --d nan
# commands without --out
for a in "vcrit --d -2e-5|--d: '-2e-5'" "vcrit --d 1e-5,,2e-5|empty item" "vcrit --d 1e-5 --tol 0|--tol: '0'" \
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
# a trace onto a folder or a FIFO (as root, --trace-csv /dev/full renamed a regular file
# over the device): exit 1 naming it, the FIFO left as it was (hostile sweep, issue 22)
mkdir -p "$WORK/tracedir"; rm -f "$WORK/fifo"; mkfifo "$WORK/fifo"
for t in "$WORK/tracedir" "$WORK/fifo"; do
    "$SR" collide --d 5e-5 --vn 1 --trace-csv "$t" >/dev/null 2>"$WORK/err"; rc=$?
    [ $rc -eq 1 ] && grep -qF -- "cannot write '$t': it exists and is not a regular file" "$WORK/err" \
        || fail "--trace-csv $t: exit $rc, $(cat "$WORK/err")"
done
[ -p "$WORK/fifo" ] || fail "--trace-csv onto a FIFO replaced it"
[ -z "$(ls -A "$WORK/tracedir")" ] && [ -z "$(ls -A "$WORK" | grep '^\.tmp-')" ] || fail "--trace-csv onto a folder left files"
# --version with more words: refused, not dropped (hostile sweep, issue 22)
"$SR" --version map >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF -- "--version takes no arguments, got 'map'" "$WORK/err" || fail "--version map: exit $rc, $(cat "$WORK/err")"
# --out naming an existing file
: >"$WORK/plainfile"
"$SR" map --out "$WORK/plainfile" --nd 4 --nv 4 >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] && grep -qF -- "--out: '$WORK/plainfile'" "$WORK/err" || fail "--out on a file: exit $rc, $(cat "$WORK/err")"
[ ! -s "$WORK/plainfile" ] || fail "--out on a file changed the file"
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
# the slowest accepted impacts get the physical answer (issue 13, item 3): stick with adhesion
for v in 1e-60 1e-90 1e-300; do
    "$SR" collide --d 50e-6 --vn $v | grep -q '^outcome: stick' || fail "collide --vn $v: not a stick"
done
"$SR" collide --d 5e-5 --vn 1e-60 --set adhesion=none | grep -q '^e_n: 1$' || fail "collide --vn 1e-60, Hertz: not an elastic rebound"
# binary data as a config: a named error with no raw bytes on stderr (issue 13, item 6)
head -c 400 /dev/urandom | tr -d '\n#' | head -c 300 >"$WORK/garbage.cfg"
"$SR" vcrit --d 1e-5 --config "$WORK/garbage.cfg" >/dev/null 2>"$WORK/err"; rc=$?
[ $rc -eq 2 ] || fail "garbage config: exit $rc, want 2"
grep -q "garbage.cfg:1" "$WORK/err" || fail "garbage config: message does not name the file and line"
LC_ALL=C grep -q '[^[:print:]]' "$WORK/err" && fail "garbage config: raw bytes on stderr"
# an interrupted map leaves nothing (issue 13, item 6): killed while its new folder
# holds temporaries, the folder (and the parent it created) is removed
( cd "$WORK" && exec "$SR" map --set wall=lattice --points 4096 --nd 40 --nv 40 --vmin 0.1 --vmax 10 --force --out int/deep >/dev/null 2>&1 ) &
pid=$!
for _ in $(seq 300); do [ -d "$WORK/int/deep" ] && break; sleep 0.1; done
[ -d "$WORK/int/deep" ] || fail "interrupt test: the map never created its folder"
kill -TERM "$pid"; wait "$pid"; rc=$?
[ $rc -eq 143 ] || fail "interrupted map: exit $rc, want 143 (SIGTERM)"
[ ! -e "$WORK/int" ] || fail "interrupted map left $(find "$WORK/int" | head -3)"
# ... and while gnuplot draws its PNG (issue 22, item 5): the plotting child is stopped
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
