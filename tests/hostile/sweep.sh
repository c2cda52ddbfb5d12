#!/usr/bin/env bash
# sweep.sh - the hostile-input sweep (run on demand; not part of ./Alltest).
#
# Usage: tests/hostile/sweep.sh [--out FILE] [--only SURFACE-REGEX]
#
# Runs every case below against the built tools of this tree (bin/, the release build,
# platforms/lib for OpenFOAM), each in a fresh folder, under `timeout 60`, and
# classifies its outcome:
#   clean     refused as expected: a named error (exit 2; exit 1 for an output failure
#             where that is the documented status; an OpenFOAM FatalIOError, exit 1),
#             whose message holds the expected words, nothing left in the case folder;
#             or, for a case expected to be accepted, exit 0 (documented behaviour)
#   crash     a signal (exit > 128)
#   hang      still running after 60 s
#   silent    accepted (exit 0) where a refusal or a warning was expected
#   leftover  refused, but a file or folder was left behind in the output location
#   unnamed   refused, but with the wrong exit status or a message that does not name
#             the input (the words expected)
# and writes the table (case, surface, input, expected, outcome, first line of the
# message) to doc/hostile-sweep.md (default; --out FILE) through a temporary file.
# Exit status 0 when every case is clean, 1 otherwise, 2 on bad usage.
# Needs: the release build (bin/, build/release), cc; OpenFOAM v1912 with
# platforms/lib/libsnowWallInteraction.so for the OpenFOAM surfaces (skipped with a
# note otherwise). Takes about 6-9 min on 2 cores (549 s for 712 cases, the cores shared).
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
out="$top/doc/hostile-sweep.md"
only=.
while [ $# -gt 0 ]; do
    case "$1" in
        --out) [ $# -ge 2 ] || { echo "sweep.sh: --out needs a file" >&2; exit 2; }; out=$2; shift ;;
        --only) [ $# -ge 2 ] || { echo "sweep.sh: --only needs a regex" >&2; exit 2; }; only=$2; shift ;;
        -h|--help) sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "sweep.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
    shift
done
case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
cmdline="${SW_OPENFOAM_TOP:+SW_OPENFOAM_TOP=$SW_OPENFOAM_TOP }tests/hostile/sweep.sh${*:+ $*}"
start=$(date +%s)
work=$(mktemp -d /tmp/sw-hostile-XXXXXX)
trap 'rm -rf "$work"' EXIT
rows="$work/rows.tsv"; : > "$rows"
fx="$work/fx"; mkdir -p "$fx"
SR="$top/bin/snowregime"; SP="$top/bin/snowphoto"; SD="$top/bin/snowdeposit"
W="$work/wedge"   # a copy of the wedge case's source files
export SR SP SD W fx top
export SNOWWALL_TOP=$top   # the wedge post scripts, run from a copy of the case, find etc/outdir.sh here

n=0
# hc SURFACE KIND PATTERN EXPECTED CMD: one case. KIND err (exit 2), fail (exit 1, an
# output failure), fatal (OpenFOAM FatalIOError), ok (accepted, exit 0), warn (exit 0
# with PATTERN in the output, or exit 2), keep (exit 2 at a script's commit, the run's
# results kept in the work folder that the message names: nothing else may change). PATTERN: ERE the message must hold (case
# insensitive). CMD: bash text run in a fresh folder after $SETUP (bash text).
SETUP=
hc() {
    local surface=$1 kind=$2 pat=$3 expected=$4 cmd=$5 setup=$SETUP
    SETUP=
    n=$((n + 1))
    printf '%s' "$surface" | grep -qE -- "$only" || return 0
    local d="$work/c$n" log="$work/log$n" rc outcome msg
    mkdir -p "$d"
    (cd "$d" && eval "$setup") > "$work/setup$n" 2>&1 || {
        printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$n" "$surface" "$cmd" "$expected" "setup-failed" \
            "$(head -1 "$work/setup$n")" >> "$rows"; return 0; }
    (cd "$d" && find . -printf '%p %y\n' | sort) > "$work/before$n"
    (cd "$d" && timeout -k 5 60 bash -c "$cmd" > "$log" 2>&1 < /dev/null); rc=$?
    if grep -q "FOAM FATAL" "$log"; then
        msg=$(awk '/FOAM FATAL/ { on = 1; next } on && NF { print; exit }' "$log")
    else
        msg=$(grep -v '^\s*$' "$log" | head -1)
    fi
    local left; left=$( (cd "$d" && find . -printf '%p %y\n' | sort) | diff "$work/before$n" - | grep '^[<>]' | head -3 | tr '\n' ' ')
    if [ -n "${ACCEPT_RE:-}" ] && [ "$rc" != 0 ] && [ "$rc" -le 128 ] && grep -qE -- "$ACCEPT_RE" "$log"; then
        rc=0; msg="accepted: $msg"
    fi
    if [ "$kind" = keep ]; then
        # refused at the commit with the run's results kept in a work folder that the
        # message names ("the results are kept in 'DIR'"): only that folder may be new
        local kept; kept=$(sed -n "s/.*results are kept in '\([^']*\)'.*/\1/p" "$log" | head -1)
        [ -z "$kept" ] || left=$( (cd "$d" && find . -printf '%p %y\n' | sort) | diff "$work/before$n" - | grep '^[<>]' \
            | grep -vF -- "./${kept#"$d"/}" | head -3 | tr '\n' ' ')
        kind=err
    fi
    local named=1
    [ -z "$pat" ] || grep -qiE -- "$pat" "$log" || named=0
    if [ "$rc" = 124 ] || [ "$rc" = 137 ]; then outcome=hang
    elif [ "$rc" -gt 128 ]; then outcome="crash"; msg="signal $((rc - 128)): $msg"
    else
        case "$kind:$rc" in
            err:2|fail:1|warn:2)
                if [ -n "$left" ]; then outcome=leftover; msg="left: $left| $msg"
                elif [ "$named" = 1 ] && [ -n "$msg" ]; then outcome=clean
                else outcome=unnamed; fi ;;
            fatal:1)
                if ! grep -q "FOAM FATAL" "$log"; then outcome=unnamed; msg="not an OpenFOAM fatal error: $msg"
                elif [ -n "$left" ]; then outcome=leftover; msg="left: $left| $msg"
                elif [ "$named" = 1 ]; then outcome=clean
                else outcome=unnamed; fi ;;
            ok:0) outcome=clean; [ -n "$pat" ] && [ "$named" = 0 ] && outcome=unnamed ;;
            warn:0) if [ "$named" = 1 ]; then outcome=clean; else outcome=silent; fi ;;
            err:0|fail:0|fatal:0) outcome=silent ;;
            *) outcome=unnamed; msg="exit $rc: $msg" ;;
        esac
    fi
    [ "$kind" = ok ] && [ "$outcome" = clean ] && [ -z "$msg" ] && msg="(exit 0)"
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$n" "$surface" "$cmd" "$expected" "$outcome" "$msg" >> "$rows"
    [ "$outcome" = clean ] || echo "case $n ($surface): $outcome: $cmd -- $msg" >&2
    rm -rf "$d"
}

# ---------------------------------------------------------------- fixtures
for exe in "$SR" "$SP" "$SD"; do [ -x "$exe" ] || { echo "sweep.sh: $exe not built (./Allwmake)" >&2; exit 1; }; done
printf 'gamma 0.3\n' > "$fx/ok.cfg"
printf '# only a comment\n\n' > "$fx/comment.cfg"
: > "$fx/empty.cfg"
printf 'gamma 0.3\ngamma 0.4\n' > "$fx/dup.cfg"
printf 'gamma\n' > "$fx/novalue.cfg"
printf 'gamma 0.3 0.4\n' > "$fx/twovalues.cfg"
printf 'gamma = \n' > "$fx/eqempty.cfg"
printf 'gamma 0x1p-2\n' > "$fx/hex.cfg"
printf 'gamma 0.3\r\n' > "$fx/crlf.cfg"
printf '\xef\xbb\xbfgamma 0.3\n' > "$fx/bom.cfg"
printf 'gam\0ma 0.3\n' > "$fx/nul.cfg"
{ printf 'gamma '; head -c 100000 /dev/zero | tr '\0' '1'; printf '\n'; } > "$fx/long.cfg"
printf 'gamma 1e-400\n' > "$fx/subnormal.cfg"
printf 'gamma 1e400\n' > "$fx/overflow.cfg"
printf 'gamma 0.3\n--set rho=1\n' > "$fx/option.cfg"
printf 'wall lattice\nasperity_r 1e-6\nasperity_spacing 1e-6\n' > "$fx/overlap.cfg"
printf '\xff\xfe\x00\x01' > "$fx/binary.cfg"
mkdir -p "$fx/dir.cfg"
# regime.coeffs variants: the fixture with one line replaced (sed expression) or added
base="$top/tests/wallmodel/fixtures/regime.coeffs"
cp "$base" "$fx/ok.coeffs"
rc_var() {  # rc_var NAME SED-EXPR: fx/NAME.coeffs
    sed -e "$2" "$base" > "$fx/$1.coeffs"
}
rc_add() {  # rc_add NAME TEXT: the fixture with TEXT before the regime's closing brace
    awk -v t="$2" '/^}/ { print "    " t } { print }' "$base" > "$fx/$1.coeffs"
}
: > "$fx/empty.coeffs"
printf 'version 1;\n' > "$fx/noregime.coeffs"
mkdir -p "$fx/dir.coeffs"
rc_add unknown 'colour 3;'
rc_var misspelt 's/yieldVelocity/yieldVelocty/'
rc_var vnswap 's/vnMin *0.2;/vnMin 7;/'
rc_var dswap 's/dMin *1e-05;/dMin 9e-4;/'
rc_var degree 's/degree *3;/degree 4;/'
rc_var nan 's/vnMax *6.0;/vnMax nan;/'
rc_var inf 's/vnMax *6.0;/vnMax inf;/'
rc_var hex 's/vnMax *6.0;/vnMax 0x6;/'
rc_var subnormal 's/gamma *0.2;/gamma 1e-310;/'
rc_var nosemi 's/vnMax *6.0;/vnMax 6.0/'
rc_var opencomment 's|/\* power-law|/* power-law unterminated|; s|\*/||'
rc_var openstring 's/"test fixture: dry snow on ABS"/"unterminated/'
rc_var twice 's/^}/}\nregime { version 1; }/'
rc_add dupkey 'vnMax 5.0;'
rc_var version 's/version *1;/version 2;/'
rc_var repr 's/representation *polynomial;/representation spline;/'
rc_var basis 's/basis *log;/basis ln;/'
rc_var coeffsempty 's/coeffs *(.*);/coeffs ();/'
rc_var coeffsopen 's/coeffs *(\(.*\));/coeffs (\1;/'
rc_var negative 's/gamma *0.2;/gamma -0.2;/'
rc_var rhozero 's/rhoParticle *920;/rhoParticle 0;/'
rc_var munan 's/mu *0.05;/mu -0.05;/'
rc_var novalue 's/vnMax *6.0;/vnMax;/'
rc_var words 's/vnMax *6.0;/vnMax six;/'
rc_var noclose 's/^}//'
rc_var nokey 's/^ *representation.*//'
rc_var label 's/"test fixture: dry snow on ABS"/"two\\nlines"/'
sed 's/$/\r/' "$base" > "$fx/crlf.coeffs"
{ printf '\xef\xbb\xbf'; cat "$base"; } > "$fx/bom.coeffs"
{ head -5 "$base"; printf 'vnMax 6.0;\0\n'; tail -n +6 "$base"; } > "$fx/nul.coeffs"
{ cat "$base"; printf '// '; head -c 200000 /dev/zero | tr '\0' 'x'; printf '\n'; } > "$fx/longline.coeffs"
rc_add include '#include "other.coeffs"'
rc_add nested 'sub { a 1; }'
rc_add biglist "vn ($(seq -s ' ' 1 5000));"
rc_add oblcount 'obliqueVt (0 0.5 1); obliqueVn (0.1 1 10); obliqueDCrit (1e-4 3e-5 1e-5 5e-5);'
rc_add oblsort 'obliqueVt (0 1 0.5); obliqueVn (0.1 1 10); obliqueDCrit (1e-4 3e-5 1e-5 5e-5 2e-5 8e-6 2e-5 1e-5 5e-6);'
rc_add oblneg 'obliqueVt (0 0.5 1); obliqueVn (0.1 1 10); obliqueDCrit (1e-4 3e-5 1e-5 5e-5 -2e-5 8e-6 2e-5 1e-5 5e-6);'
rc_add obltwo 'obliqueVt (0 0.5 1); obliqueVn (0.1 1 10);'
rc_add oblrise 'obliqueVt (0 0.5 1); obliqueVn (0.1 1 10); obliqueDCrit (1e-4 3e-5 1e-5 5e-5 2e-5 8e-6 2e-4 1e-5 5e-6);'
rc_add rbcount 'reboundD (1e-6 1e-4); reboundVn (0.1 10); reboundEn (0.5 0.5 0.5);'
rc_add rbrange 'reboundD (1e-6 1e-4); reboundVn (0.1 10); reboundEn (0.5 1.5 0.5 0.5);'
rc_add rbvt 'reboundD (1e-6 1e-4); reboundVn (0.1 10); reboundEn (0.5 0.5 0.5 0.5); reboundVt (0 1);'
rc_add rbnan 'reboundD (1e-6 1e-4); reboundVn (0.1 10); reboundEn (0.5 nan 0.5 0.5);'
rc_add pcount 'probabilityD (1e-6 1e-4); probabilityVn (0.1 10); probabilityStick (1 0.5 0);'
rc_add prange 'probabilityD (1e-6 1e-4); probabilityVn (0.1 10); probabilityStick (1 0.5 0 1.2);'
rc_add ppoints 'probabilityD (1e-6 1e-4); probabilityVn (0.1 10); probabilityStick (1 0.5 0 0.2); probabilityPoints 2.5;'
rc_add pone 'probabilityD (1e-6); probabilityVn (0.1 10); probabilityStick (1 0.5);'
rc_add pdneg 'probabilityD (-1e-6 1e-4); probabilityVn (0.1 10); probabilityStick (1 0.5 0 0.2);'
rc_add slopes 'vn (0.2 6); dCrit (1e-5 2e-5);'
rc_var slopepos 's/slopeLow *-1.2;/slopeLow 1.2;/'
rc_var vnminneg 's/vnMin *0.2;/vnMin -0.2;/'
printf 'regime\n{\n    version 1;\n    representation table;\n    vn (0.2 1 0.5 6);\n    dCrit (1e-4 5e-5 3e-5 1e-5);\n    vnMin 0.2; vnMax 6; dMin 1e-5; dMax 1e-4;\n}\n' > "$fx/tablesort.coeffs"
printf 'regime\n{\n    version 1;\n    representation table;\n    vn (0.2 1 6);\n    dCrit (1e-4 5e-5);\n    vnMin 0.2; vnMax 6; dMin 1e-5; dMax 1e-4;\n}\n' > "$fx/tablecount.coeffs"
# the C API driver: load a regime file, then the calls given on the command line
cat > "$work/drv.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sww.h"
static double num(const char *s) { return strtod(s, NULL); }
int main(int argc, char **argv)
{
    sww_model *m = sww_alloc();
    if (!m) return 1;
    int rc = sww_regime_load(m, argv[1]);
    for (int a = 2; rc == SWW_OK && a < argc; a++) {
        const char *op = argv[a];
        if (!strcmp(op, "tgate") && a + 3 < argc) { rc = sww_set_tangential_gate(m, num(argv[a+1]), num(argv[a+2]), num(argv[a+3])); a += 3; }
        else if (!strcmp(op, "tregime")) rc = sww_set_tangential_regime(m);
        else if (!strcmp(op, "shearc") && a + 1 < argc) { rc = sww_set_shear_gate_constant(m, num(argv[++a])); }
        else if (!strcmp(op, "sheara") && a + 1 < argc) { rc = sww_set_shear_gate_adhesion(m, num(argv[++a])); }
        else if (!strcmp(op, "et") && a + 1 < argc) { rc = sww_set_rebound_tangential(m, num(argv[++a])); }
        else if (!strcmp(op, "rbmodel") && a + 1 < argc) { rc = sww_set_rebound_model(m, atoi(argv[++a])); }
        else if (!strcmp(op, "slide") && a + 1 < argc) { rc = sww_check_oblique_slide(m, num(argv[++a])); }
        else if (!strcmp(op, "decide") && a + 5 < argc) {
            sww_impact in = { num(argv[a+1]), num(argv[a+2]), num(argv[a+3]), num(argv[a+4]), num(argv[a+5]) };
            sww_outcome o; rc = sww_decide(m, &in, &o); a += 5;
            if (rc == SWW_OK) printf("decided: p_stick %g d_crit %g\n", o.p_stick, o.d_crit);
            else { fprintf(stderr, "sww_decide: code %d (SWW_EINVAL %d): bad impact\n", rc, SWW_EINVAL); sww_free(m); return 2; }
        } else { fprintf(stderr, "drv: bad call %s\n", op); return 3; }
    }
    if (rc != SWW_OK) { fprintf(stderr, "%s\n", sww_errmsg(m)); sww_free(m); return 2; }
    sww_free(m);
    return 0;
}
C
blib="$top/build/release"
cc -std=c11 -O1 -I"$top/wallmodel/core" -o "$work/drv" "$work/drv.c" \
    "$blib/wallmodel/core/libsnowwall.a" "$blib/regime/libswphysics.a" -lm 2> "$work/drv.log" \
    || { echo "sweep.sh: cannot build the C API driver:" >&2; cat "$work/drv.log" >&2; exit 1; }
DRV="$work/drv"; export DRV
# a photo (PNG of the repository) and simulated rear-face maps for snowphoto
cp "$top/doc/img/snowregime-map.png" "$fx/photo.png"
awk 'BEGIN { print "y,z,deposit_kg_m2"; for (i = 0; i < 10; i++) for (j = 0; j < 10; j++)
    printf "%.4f,%.4f,%g\n", -0.06 + 0.006 + 0.012 * i, -0.06 + 0.006 + 0.012 * j, (i + j) * 1e-3 }' > "$fx/sim.csv"
head -1 "$fx/sim.csv" > "$fx/simempty.csv"
sed '5s/,[^,]*$/,nan/' "$fx/sim.csv" > "$fx/simnan.csv"
sed '5s/,[^,]*$/,-1/' "$fx/sim.csv" > "$fx/simneg.csv"
sed '7d' "$fx/sim.csv" > "$fx/simhole.csv"
sed '5s/.*/0.1,0.2/' "$fx/sim.csv" > "$fx/simcols.csv"
head -c 200 "$fx/photo.png" > "$fx/trunc.png"
printf 'not an image\n' > "$fx/text.png"
pw=$(file "$fx/photo.png" | sed -n 's/.* \([0-9]*\) x \([0-9]*\).*/\1/p'); ph=$(file "$fx/photo.png" | sed -n 's/.* \([0-9]*\) x \([0-9]*\).*/\2/p')
C_OK="10,10,$((pw - 10)),10,$((pw - 10)),$((ph - 10)),10,$((ph - 10))"
# a deposition.sh result table (one row) and a three-level ladder for snowgci
printf 'mesh,model,tau_plus,a,b,dep,c,e,f,vplus,se,wood\nwf,nearwall,1,0,0,3,0,1,0,1e-3,5e-4,4.5e-4\n' > "$fx/vplus.csv"
printf 'quantity,level,h,value,se\nCd,L1,1,0.31,0\nCd,L2,2,0.34,0\nCd,L3,4,0.40,0\n' > "$fx/gci.csv"
export C_OK pw ph

# ---------------------------------------------------------------- snowregime: command line
S=snowregime-cli
hc $S err 'command' 'no command: usage error' '$SR'
hc $S err 'mapp' 'unknown command named' '$SR mapp --out out'
hc $S err 'frobnicate' 'unknown global option named' '$SR --frobnicate'
hc $S err 'version' '--version with an extra word refused' '$SR --version extra'
hc $S err '' 'empty command word refused' '$SR "" --out out'
hc $S err 'out' 'map without --out refused' '$SR map --no-plot'
hc $S err 'out' 'map --out with no value' '$SR map --out'
hc $S err 'out' 'map --out "" refused' '$SR map --out "" --no-plot'
SETUP='touch f'; hc $S err 'f/sub' 'map --out under a regular file: named, nothing left' '$SR map --out f/sub --nd 4 --nv 4 --no-plot'
hc $S err 'proc' 'map --out in /proc: named' '$SR map --out /proc/swhostile --nd 4 --nv 4 --no-plot'
hc $S err 'nd' '--nd 0' '$SR map --out out --nd 0 --no-plot'
hc $S err 'nd' '--nd 1 (one diameter cannot make a map)' '$SR map --out out --nd 1 --no-plot'
hc $S err 'nd' '--nd 2.5 not an integer' '$SR map --out out --nd 2.5 --no-plot'
hc $S err 'nd' '--nd -4' '$SR map --out out --nd -4 --no-plot'
hc $S err 'nd' '--nd 1e9 (over 1e6 cells)' '$SR map --out out --nd 1e9 --no-plot'
hc $S err '2000' '--nd 2000 --nv 2000: 4e6 cells over the cap' '$SR map --out out --nd 2000 --nv 2000 --no-plot'
hc $S err 'nv' '--nv abc' '$SR map --out out --nv abc --no-plot'
hc $S err 'nv' '--nv 0x10 (hexadecimal refused)' '$SR map --out out --nv 0x10 --no-plot'
hc $S err 'nv' '--nv "" empty' '$SR map --out out --nv "" --no-plot'
hc $S err 'dmin' '--dmin 0' '$SR map --out out --dmin 0 --no-plot'
hc $S err 'dmin|dmax' '--dmin > --dmax' '$SR map --out out --dmin 1e-4 --dmax 1e-5 --no-plot'
hc $S err 'dmin|dmax' '--dmin = --dmax' '$SR map --out out --dmin 1e-5 --dmax 1e-5 --no-plot'
hc $S err 'dmax' '--dmax 1 m (above 0.1)' '$SR map --out out --dmax 1 --no-plot'
hc $S err 'dmin' '--dmin nan' '$SR map --out out --dmin nan --no-plot'
hc $S err 'vmin' '--vmin 0' '$SR map --out out --vmin 0 --no-plot'
hc $S err 'vmin|vmax' '--vmin > --vmax' '$SR map --out out --vmin 5 --vmax 1 --no-plot'
hc $S err 'vmax' '--vmax inf' '$SR map --out out --vmax inf --no-plot'
hc $S err 'vmax' '--vmax 1e5 (above the kernel range)' '$SR map --out out --vmax 1e5 --no-plot'
hc $S err 'vlog' '--vlog 2' '$SR map --out out --vlog 2 --no-plot'
hc $S err 'vlog' '--vlog yes' '$SR map --out out --vlog yes --no-plot'
hc $S err 'degree' '--degree 0' '$SR map --out out --degree 0 --no-plot'
hc $S err 'degree' '--degree 9' '$SR map --out out --degree 9 --no-plot'
hc $S err 'degree' '--degree 3.5' '$SR map --out out --degree 3.5 --no-plot'
hc $S warn 'ascending' '--vt unsorted: taken in ascending order, said so (the same map)' '$SR map --out out --vt 0,0.5,0.2 --no-plot'
hc $S err 'vt' '--vt duplicated' '$SR map --out out --vt 0,0.5,0.5 --no-plot'
hc $S err 'vt' '--vt negative' '$SR map --out out --vt -1,0 --no-plot'
hc $S err 'vt' '--vt nan' '$SR map --out out --vt 0,nan --no-plot'
hc $S err 'vt' '--vt empty item' '$SR map --out out --vt 0,,1 --no-plot'
hc $S err 'vt' '--vt trailing comma' '$SR map --out out --vt 0,1, --no-plot'
hc $S err 'vt' '--vt of 500 speeds: over the 4096-value table, refused before any map' '$SR map --out out --vt $(seq -s, 0 0.01 4.99) --max-slide 1e-4 --no-plot'
hc $S err 'angle' '--angle 90' '$SR map --out out --angle 0,90 --no-plot'
hc $S err 'angle' '--angle -10' '$SR map --out out --angle -10,0 --no-plot'
hc $S err 'angle|vt' '--angle with --vt' '$SR map --out out --angle 0,10 --vt 0,1 --no-plot'
hc $S err 'omega' '--omega inf' '$SR map --out out --omega inf --no-plot'
hc $S err 'refine' '--refine 2' '$SR map --out out --refine 2 --no-plot'
hc $S err 'tol' '--tol 0' '$SR map --out out --tol 0 --no-plot'
hc $S err 'tol' '--tol -1' '$SR map --out out --tol -1 --no-plot'
hc $S err 'tol' '--tol 2' '$SR map --out out --tol 2 --no-plot'
hc $S err 'points' '--points on a flat wall (unused: refused)' '$SR map --out out --points 8 --no-plot'
hc $S err 'seed' '--seed on a flat wall (unused: refused)' '$SR map --out out --seed 3 --no-plot'
hc $S err 'threads' '--threads 0' '$SR map --out out --threads 0 --no-plot'
hc $S err 'threads' '--threads 100000' '$SR map --out out --threads 100000 --no-plot'
hc $S err 'max-slide' '--max-slide -1' '$SR map --out out --max-slide -1 --no-plot'
hc $S err 'max-slide' '--max-slide nan' '$SR map --out out --max-slide nan --no-plot'
hc $S err 'no-plot' '--no-plot=1 (a flag takes no value)' '$SR map --out out --no-plot=1'
hc $S err 'full-stick' '--full-stick=yes' '$SR map --out out --full-stick=yes --no-plot'
hc $S err 'frob' 'unknown map option' '$SR map --out out --frob --no-plot'
hc $S ok '' '--nd twice: the last one counts (the usual convention of command lines)' '$SR map --out out --nd 4 --nd 5 --no-plot'
hc $S err 'points' '--points 1e9 on a lattice: work beyond the limit refused' '$SR map --out out --set wall=lattice --points 1000000000 --no-plot'
hc $S fail 'fit' 'a rough map over a --vt list (valid) on a grid too coarse for the v_t = 0 fit: exit 1 naming the fit' '$SR map --out out --set wall=lattice --vt 0,0.5 --nd 4 --nv 4 --no-plot'
hc $S ok '' 'a small map is made (control)' '$SR map --out out --nd 8 --nv 8 --degree 1 --no-plot'
SETUP='touch out'; hc $S err 'out' 'map --out an existing file' '$SR map --out out --nd 4 --nv 4 --no-plot'
# vcrit
hc $S err 'd' 'vcrit without --d' '$SR vcrit'
hc $S err 'd' 'vcrit --d ""' '$SR vcrit --d ""'
hc $S err 'd' 'vcrit --d empty item' '$SR vcrit --d 1e-5,,2e-5'
hc $S err 'd' 'vcrit --d 1e-9 (below 1e-7)' '$SR vcrit --d 1e-9'
hc $S err 'd' 'vcrit --d 1 (above 0.1)' '$SR vcrit --d 1'
hc $S err 'd' 'vcrit --d -1e-5' '$SR vcrit --d -1e-5'
hc $S err 'd' 'vcrit --d nan' '$SR vcrit --d nan'
hc $S err 'd' 'vcrit --d 1e-5x' '$SR vcrit --d 1e-5x'
hc $S err 'd' 'vcrit --d 1e-400 (underflow)' '$SR vcrit --d 1e-400'
hc $S err 'vt' 'vcrit --vt -1' '$SR vcrit --d 1e-5 --vt -1'
hc $S err 'vt' 'vcrit --vt inf' '$SR vcrit --d 1e-5 --vt inf'
hc $S err 'angle' 'vcrit --angle 90' '$SR vcrit --d 1e-5 --angle 90'
hc $S err 'angle|vt' 'vcrit --angle and --vt' '$SR vcrit --d 1e-5 --angle 10 --vt 1'
hc $S err 'points' 'vcrit --points on a flat wall' '$SR vcrit --d 1e-5 --points 4'
hc $S err 'level' 'vcrit --level on a flat wall' '$SR vcrit --d 1e-5 --level 0.5'
hc $S err 'seed' 'vcrit --seed on a flat wall' '$SR vcrit --d 1e-5 --seed 2'
hc $S err 'level' 'vcrit --level 0 on a lattice' '$SR vcrit --d 1e-5 --set wall=lattice --level 0'
hc $S err 'level' 'vcrit --level 1.5 on a lattice' '$SR vcrit --d 1e-5 --set wall=lattice --level 1.5'
hc $S err 'points' 'vcrit --points 0 on a lattice' '$SR vcrit --d 1e-5 --set wall=lattice --points 0'
hc $S err 'points' 'vcrit --points 1e9 on a lattice (work bound)' '$SR vcrit --d 1e-5 --set wall=lattice --points 1000000000'
hc $S err 'seed' 'vcrit --seed -1 on a lattice' '$SR vcrit --d 1e-5 --set wall=lattice --seed -1'
hc $S err 'tol' 'vcrit --tol 0' '$SR vcrit --d 1e-5 --tol 0'
hc $S err 'vmin|vmax' 'vcrit --vmin > --vmax' '$SR vcrit --d 1e-5 --vmin 10 --vmax 1'
hc $S err 'vmin' 'vcrit --vmin 0' '$SR vcrit --d 1e-5 --vmin 0'
hc $S err 'scan-ratio' 'vcrit --scan-ratio 1' '$SR vcrit --d 1e-5 --scan-ratio 1'
hc $S err 'scan-ratio' 'vcrit --scan-ratio 0.5' '$SR vcrit --d 1e-5 --scan-ratio 0.5'
hc $S err 'threads' 'vcrit --threads -1' '$SR vcrit --d 1e-5 --threads -1'
hc $S err 'max-slide' 'vcrit --max-slide -1' '$SR vcrit --d 1e-5 --max-slide -1'
hc $S err 'out' 'vcrit --out (a map option)' '$SR vcrit --d 1e-5 --out out'
hc $S ok '' 'vcrit --d of 10001 diameters: accepted, bounded work (one bisection each)' '$SR vcrit --d $(seq -s, 1e-5 1e-8 1.1e-4 | cut -d, -f1-100001)'
# collide
hc $S err 'd' 'collide without --d' '$SR collide --vn 1'
hc $S err 'vn' 'collide without --vn' '$SR collide --d 5e-5'
hc $S err 'd' 'collide --d 0' '$SR collide --d 0 --vn 1'
hc $S err 'd' 'collide --d 0.2' '$SR collide --d 0.2 --vn 1'
hc $S ok '' 'collide --d " 5e-5": a leading blank, the same number' '$SR collide --d " 5e-5" --vn 1'
hc $S err 'd' 'collide --d 5e-5,1e-5 (a list)' '$SR collide --d 5e-5,1e-5 --vn 1'
hc $S err 'vn' 'collide --vn 0' '$SR collide --d 5e-5 --vn 0'
hc $S err 'vn' 'collide --vn -1' '$SR collide --d 5e-5 --vn -1'
hc $S err 'vn' 'collide --vn 2000' '$SR collide --d 5e-5 --vn 2000'
hc $S err 'vn' 'collide --vn 1e-320 (subnormal: out of range, not "not finite")' '$SR collide --d 5e-5 --vn 1e-320'
hc $S err 'vn' 'collide --vn 1e400' '$SR collide --d 5e-5 --vn 1e400'
hc $S err 'vn' 'collide --vn 0x1p0 (hexadecimal)' '$SR collide --d 5e-5 --vn 0x1p0'
hc $S err 'vt' 'collide --vt nan' '$SR collide --d 5e-5 --vn 1 --vt nan'
hc $S err 'omega' 'collide --omega -inf' '$SR collide --d 5e-5 --vn 1 --omega -inf'
hc $S err 'stride' 'collide --stride 0' '$SR collide --d 5e-5 --vn 1 --stride 0'
hc $S err 'stride' 'collide --stride 1.5' '$SR collide --d 5e-5 --vn 1 --stride 1.5'
hc $S err 'stride' 'collide --stride without a trace (unused)' '$SR collide --d 5e-5 --vn 1 --stride 5'
hc $S err 'x' 'collide --x on a flat wall (unused)' '$SR collide --d 5e-5 --vn 1 --x 1e-7'
hc $S err 'trace|no/such' 'collide --trace-csv into a missing folder: refused before the impact, named' '$SR collide --d 5e-5 --vn 1 --trace-csv no/such/t.csv'
hc $S err 'trace' 'collide --trace-vtk ""' '$SR collide --d 5e-5 --vn 1 --trace-vtk ""'
SETUP='mkfifo p'; hc $S err "'p'.*FIFO" 'collide --trace-csv onto a FIFO: refused before the impact, named, the FIFO kept (it was replaced by a file: as root, /dev/full became one)' '$SR collide --d 5e-5 --vn 1 --trace-csv p'
SETUP='mkdir d'; hc $S err "'d'.*folder" 'collide --trace-csv onto a folder: refused before the impact, named' '$SR collide --d 5e-5 --vn 1 --trace-csv d'
hc $S err 'trace' 'collide: the same file for both traces' '$SR collide --d 5e-5 --vn 1 --trace-csv t --trace-vtk t'
# sensitivity and convergence
hc $S err 'out' 'sensitivity without --out' '$SR sensitivity --no-plot'
hc $S err 'nd' 'sensitivity --nd 0' '$SR sensitivity --out out --nd 0 --no-plot'
hc $S err 'threads' 'sensitivity --threads 0' '$SR sensitivity --out out --threads 0 --no-plot'
hc $S err 'points' 'sensitivity --points on a flat wall' '$SR sensitivity --out out --points 4 --no-plot'
hc $S err 'gamma' 'sensitivity --set gamma=-1' '$SR sensitivity --out out --set gamma=-1 --no-plot'
hc $S err 'frob' 'sensitivity unknown option' '$SR sensitivity --out out --frob'
hc $S err 'out' 'convergence without --out' '$SR convergence --no-plot'
hc $S err 'accuracy' 'convergence --accuracy 5 (below 10)' '$SR convergence --out out --accuracy 5 --no-plot'
hc $S err 'accuracy' 'convergence --accuracy 1e9 (work bound)' '$SR convergence --out out --accuracy 1000000000 --no-plot'
hc $S err 'accuracy' 'convergence --accuracy unsorted or duplicated' '$SR convergence --out out --accuracy 20,10,10 --no-plot'
hc $S err 'ref-factor' 'convergence --ref-factor 0' '$SR convergence --out out --ref-factor 0 --no-plot'
hc $S err 'ref-factor' 'convergence --ref-factor 1e9 (work bound)' '$SR convergence --out out --ref-factor 1e9 --no-plot'
hc $S err 'tol' 'convergence --tol 0' '$SR convergence --out out --tol 0 --no-plot'
hc $S err 'min-time' 'convergence --min-time -1' '$SR convergence --out out --min-time -1 --no-plot'
hc $S err 'min-time' 'convergence --min-time 1e9 (time bound)' '$SR convergence --out out --min-time 1e9 --no-plot'
hc $S err 'd' 'convergence --d ""' '$SR convergence --out out --d "" --no-plot'
hc $S err 'points' 'convergence --points (not its option)' '$SR convergence --out out --points 4 --no-plot'

# ---------------------------------------------------------------- snowregime: settings and config files
S=snowregime-settings
for kv in rho=0 rho=-920 rho=nan E=0 E=-1 nu=0.6 nu=-1.1 sigma_y=0 E_wall=inf nu_wall=0.51 rho_wall=0 \
          gamma=-0.2 gamma=inf adhesion=dmt z0=0 z0=-1e-10 cor=0 cor=1.5 cor=thornton-nin cor_pair=plate \
          mu=-0.1 mu=nan xi_crit=0 accuracy=5 accuracy=1e9 wall=rough lattice=triangle \
          asperity_r=0 asperity_jitter=0.6 wall_seed=1.5 wall_seed=-1 rough_hold=0 dashpot=never \
          rough_step=fast asperity_shape=cube asperity_yield=soft; do
    hc $S err "${kv%%=*}" "--set $kv out of range / unknown value" "\$SR vcrit --d 1e-5 --set $kv"
done
# rough-wall keys on a flat wall, a whole sphere sunk by its diameter, a
# rough map of hours (refused unless --force), a rough table over v_t beyond 4096
for kv in rough_step=fixed asperity_shape=sphere asperity_yield=elastic; do
    hc $S err "${kv%%=*}" "--set $kv on a flat wall" "\$SR vcrit --d 1e-5 --set $kv"
done
hc $S err 'asperity_dz' 'whole spheres sunk by their diameter' '$SR vcrit --d 1e-5 --set wall=lattice --set asperity_shape=sphere --set asperity_dz=2e-6'
hc $S err 'force' 'a rough map of hours without --force' '$SR map --out long --set wall=lattice --points 100000 --nd 60 --nv 60 --threads 1'
hc $S err 'vt' 'a rough map over v_t beyond the 4096-value table' '$SR map --out big --set wall=lattice --vt 0,1,2'
hc $S err 'angle' 'a rough map over impact angles' '$SR map --out ang --set wall=lattice --angle 0,30'
hc $S err 'rhoo' '--set rhoo=920 unknown key' '$SR vcrit --d 1e-5 --set rhoo=920'
hc $S err 'rho' '--set rho (no =)' '$SR vcrit --d 1e-5 --set rho'
hc $S err 'set|=' '--set =5 (no key)' '$SR vcrit --d 1e-5 --set =5'
hc $S err 'rho' '--set rho= (no value)' '$SR vcrit --d 1e-5 --set rho='
hc $S err 'rho' '--set rho=920=1' '$SR vcrit --d 1e-5 --set rho=920=1'
hc $S ok '' '--set "rho = 920": blanks around =, the same setting' '$SR vcrit --d 1e-5 --set "rho = 920"'
hc $S err 'gamma' '--set gamma=0x1p-2 (hexadecimal)' '$SR vcrit --d 1e-5 --set gamma=0x1p-2'
hc $S err 'gamma' '--set gamma=1e-400 (underflows to 0)' '$SR vcrit --d 1e-5 --set gamma=1e-400'
hc $S err 'dashpot' 'dashpot with cor elastic (unused setting refused)' '$SR vcrit --d 1e-5 --set cor=elastic --set dashpot=both'
hc $S err 'dashpot' 'dashpot with cor thornton-ning (unused)' '$SR vcrit --d 1e-5 --set cor=thornton-ning --set dashpot=both'
hc $S err 'thornton-ning|lattice' 'cor thornton-ning on a lattice' '$SR vcrit --d 1e-5 --set wall=lattice --set cor=thornton-ning'
hc $S err 'asperity|lattice' 'asperity_r on a flat wall (unused setting)' '$SR vcrit --d 1e-5 --set asperity_r=2e-6'
hc $S err 'lattice' 'lattice hex on a flat wall (unused setting)' '$SR vcrit --d 1e-5 --set lattice=hex'
hc $S err 'asperity_spacing' 'asperity_spacing below 2 r (overlapping)' '$SR vcrit --d 1e-5 --set wall=lattice --set asperity_spacing=1e-6'
hc $S err 'asperity_dz' 'asperity_dz >= asperity_r (below the plane)' '$SR vcrit --d 1e-5 --set wall=lattice --set asperity_dz=2e-6'
hc $S err 'adhesion|gamma' 'adhesion none with gamma given (unused)' '$SR vcrit --d 1e-5 --set adhesion=none --set gamma=0.5'
hc $S ok '' 'config with gamma (control)' '$SR vcrit --d 1e-5 --config $fx/ok.cfg'
hc $S ok '' 'config of only a comment: accepted, the defaults' '$SR vcrit --d 1e-5 --config $fx/comment.cfg'
hc $S ok '' 'empty config: accepted, the defaults' '$SR vcrit --d 1e-5 --config $fx/empty.cfg'
hc $S err 'dup.cfg|gamma' 'config: a key set twice' '$SR vcrit --d 1e-5 --config $fx/dup.cfg'
hc $S err 'novalue.cfg' 'config: key without value' '$SR vcrit --d 1e-5 --config $fx/novalue.cfg'
hc $S err 'twovalues.cfg' 'config: two values' '$SR vcrit --d 1e-5 --config $fx/twovalues.cfg'
hc $S err 'eqempty.cfg' 'config: "gamma = " no value' '$SR vcrit --d 1e-5 --config $fx/eqempty.cfg'
hc $S err 'hex.cfg' 'config: hexadecimal number' '$SR vcrit --d 1e-5 --config $fx/hex.cfg'
hc $S ok '' 'config with CRLF line ends: read as written' '$SR vcrit --d 1e-5 --config $fx/crlf.cfg'
hc $S err 'bom.cfg' 'config with a UTF-8 BOM' '$SR vcrit --d 1e-5 --config $fx/bom.cfg'
hc $S err 'nul.cfg' 'config with a NUL byte (named as such)' '$SR vcrit --d 1e-5 --config $fx/nul.cfg'
hc $S err 'long.cfg' 'config with a 100 kB line' '$SR vcrit --d 1e-5 --config $fx/long.cfg'
hc $S err 'subnormal.cfg' 'config gamma 1e-400' '$SR vcrit --d 1e-5 --config $fx/subnormal.cfg'
hc $S err 'overflow.cfg' 'config gamma 1e400' '$SR vcrit --d 1e-5 --config $fx/overflow.cfg'
hc $S err 'option.cfg' 'config with a command-line option line' '$SR vcrit --d 1e-5 --config $fx/option.cfg'
hc $S err 'overlap.cfg|asperity_spacing' 'config: overlapping asperities' '$SR vcrit --d 1e-5 --config $fx/overlap.cfg'
hc $S err 'binary.cfg' 'config: binary bytes' '$SR vcrit --d 1e-5 --config $fx/binary.cfg'
hc $S err 'dir.cfg' 'config: a folder' '$SR vcrit --d 1e-5 --config $fx/dir.cfg'
hc $S err 'no/such' 'config: missing file' '$SR vcrit --d 1e-5 --config $fx/no/such.cfg'
hc $S err 'config' 'config: no value' '$SR vcrit --d 1e-5 --config'
hc $S err 'config|/dev/zero' 'config /dev/zero (endless NULs)' '$SR vcrit --d 1e-5 --config /dev/zero'
hc $S err 'config|/dev/urandom' 'config /dev/urandom (endless bytes)' '$SR vcrit --d 1e-5 --config /dev/urandom'
hc $S ok '' 'config /dev/stdin, empty: accepted as an empty config, no hang' '$SR vcrit --d 1e-5 --config /dev/stdin'

# ---------------------------------------------------------------- the C API: regime.coeffs loader and calls
S=c-api
hc $S ok '' 'the fixture loads (control)' '$DRV $fx/ok.coeffs'
hc $S err 'no/such' 'missing file' '$DRV $fx/no/such.coeffs'
hc $S err 'dir.coeffs' 'a folder' '$DRV $fx/dir.coeffs'
hc $S err 'empty.coeffs' 'empty file' '$DRV $fx/empty.coeffs'
hc $S err 'regime' 'no regime block' '$DRV $fx/noregime.coeffs'
for v in unknown misspelt vnswap dswap degree nan inf hex nosemi opencomment openstring twice dupkey \
         version repr basis coeffsempty coeffsopen negative rhozero munan novalue words noclose nokey \
         bom nul include nested biglist oblcount oblsort oblneg obltwo oblrise rbcount rbrange \
         rbvt rbnan pcount prange ppoints pone pdneg slopes slopepos vnminneg tablesort tablecount; do
    hc $S err "$v.coeffs" "regime.coeffs variant '$v' refused, naming the file" "\$DRV \$fx/$v.coeffs"
done
hc $S ok '' 'gamma 1e-310: positive and finite, taken as given (no change of meaning)' '$DRV $fx/subnormal.coeffs'
hc $S ok '' 'a label holding a backslash-n: text' '$DRV $fx/label.coeffs'
hc $S ok '' 'CRLF line ends: read as written' '$DRV $fx/crlf.coeffs'
hc $S ok '' 'a 200 kB comment line: a comment' '$DRV $fx/longline.coeffs'
hc $S err 'binary|line|byte|r\.coeffs:[0-9]+' '/dev/urandom as regime file (bounded read, no hang; named by file and line)' 'head -c 100000 /dev/urandom > r.coeffs; $DRV r.coeffs; rc=$?; rm -f r.coeffs; exit $rc'
hc $S err 'zero|/dev/zero|NUL|line' '/dev/zero as regime file' '$DRV /dev/zero'
hc $S err 'vtMax|vt' 'tangential gate vtMax nan' '$DRV $fx/ok.coeffs tgate nan 5e-5 0'
hc $S err 'vtMax|vt' 'tangential gate vtMax -1' '$DRV $fx/ok.coeffs tgate -1 5e-5 0'
hc $S err 'dRef|d_ref|ref' 'tangential gate dRef 0' '$DRV $fx/ok.coeffs tgate 0.5 0 0'
hc $S err 'exponent' 'tangential gate exponent inf' '$DRV $fx/ok.coeffs tgate 0.5 5e-5 inf'
hc $S err 'oblique|table' 'regime tangential gate without an oblique table' '$DRV $fx/ok.coeffs tregime'
hc $S err 'tau' 'shear gate constant tau -1' '$DRV $fx/ok.coeffs shearc -1'
hc $S err 'tau' 'shear gate constant tau nan' '$DRV $fx/ok.coeffs shearc nan'
hc $S err 'rough' 'shear gate adhesion roughness 0' '$DRV $fx/ok.coeffs sheara 0'
hc $S err 'rough' 'shear gate adhesion roughness 2 (above 1)' '$DRV $fx/ok.coeffs sheara 2'
hc $S err 'e_t|tangential' 'rebound e_t 1.5' '$DRV $fx/ok.coeffs et 1.5'
hc $S err 'e_t|tangential' 'rebound e_t -0.1' '$DRV $fx/ok.coeffs et -0.1'
hc $S err 'model|rebound' 'rebound model 7' '$DRV $fx/ok.coeffs rbmodel 7'
hc $S err 'slide|oblique' 'oblique slide check without a table' '$DRV $fx/ok.coeffs slide 1e-4'
hc $S err 'EINVAL' 'decide with d nan (sww_decide returns SWW_EINVAL, no message: documented)' '$DRV $fx/ok.coeffs decide nan 1 0 0 0.5'
hc $S err 'EINVAL' 'decide with d 0' '$DRV $fx/ok.coeffs decide 0 1 0 0 0.5'
hc $S err 'EINVAL' 'decide with v_n inf' '$DRV $fx/ok.coeffs decide 1e-5 inf 0 0 0.5'
hc $S err 'EINVAL' 'decide with v_n -1' '$DRV $fx/ok.coeffs decide 1e-5 -1 0 0 0.5'
hc $S err 'EINVAL' 'decide with v_t nan' '$DRV $fx/ok.coeffs decide 1e-5 1 nan 0 0.5'
hc $S err 'EINVAL' 'decide with u 1 (outside [0, 1))' '$DRV $fx/ok.coeffs decide 1e-5 1 0 0 1'
hc $S err 'EINVAL' 'decide with u nan' '$DRV $fx/ok.coeffs decide 1e-5 1 0 0 nan'
hc $S ok '' 'decide with tau_w nan, the shear gate off: not read (documented in sww.h)' '$DRV $fx/ok.coeffs decide 1e-5 1 0 nan 0.5'
hc $S err 'EINVAL' 'decide with tau_w -1, the shear gate on' '$DRV $fx/ok.coeffs shearc 1 decide 1e-5 1 0 -1 0.5'
hc $S err 'EINVAL' 'decide with tau_w inf, the adhesion shear gate on' '$DRV $fx/ok.coeffs sheara 0.01 decide 1e-5 1 0 inf 0.5'

# ---------------------------------------------------------------- snowdeposit
S=snowdeposit
hc $S err 'command|usage' 'no command' '$SD'
hc $S err 'chanel' 'unknown command' '$SD chanel'
hc $S err 'tau-plus' 'channel --tau-plus 0' '$SD channel --tau-plus 0'
hc $S warn 'ascending' 'channel --tau-plus unsorted: taken in ascending order, said so' '$SD channel --tau-plus 1,0.5 --particles 10 --t-warm 0 --t-run 1'
hc $S err 'tau-plus' 'channel --tau-plus duplicated' '$SD channel --tau-plus 1,1'
hc $S err 'tau-plus' 'channel --tau-plus nan' '$SD channel --tau-plus nan'
hc $S err 'tau-plus' 'channel --tau-plus 1e5' '$SD channel --tau-plus 1e5'
hc $S err 'tau-plus' 'channel --tau-plus ""' '$SD channel --tau-plus ""'
hc $S err 'tau-plus' 'channel --tau-plus with no value' '$SD channel --tau-plus'
hc $S err 'closure' 'channel --closure foo' '$SD channel --closure foo'
hc $S err 'law' 'calibrate --law foo' '$SD calibrate --out c.coeffs --law foo'
hc $S err 'out' 'calibrate without --out' '$SD calibrate'
hc $S err 'no/such' 'calibrate --out into a missing folder: named, nothing left' '$SD calibrate --out no/such/c.coeffs --particles 10 --t-warm 0 --t-run 1 --tau-plus 1'
hc $S err 'out' 'channel --out (calibrate only: unused)' '$SD channel --out x.coeffs'
hc $S err 'law' 'channel --law (calibrate only: unused)' '$SD channel --law wood --particles 10 --t-warm 0 --t-run 1 --tau-plus 1'
hc $S err 'closure' 'calibrate --closure (channel only: unused)' '$SD calibrate --out c.coeffs --closure wood --particles 10 --t-warm 0 --t-run 1 --tau-plus 1'
hc $S err 'sublayer' '--sublayer 0' '$SD channel --sublayer 0'
hc $S err 'sublayer' '--sublayer 1000 (above layerYPlus)' '$SD channel --sublayer 1000'
hc $S err 're-tau' '--re-tau 10' '$SD channel --re-tau 10'
hc $S err 're-tau' '--re-tau 1e6' '$SD channel --re-tau 1e6'
hc $S err 'particles' '--particles 0' '$SD channel --particles 0'
hc $S err 'particles' '--particles 1e9' '$SD channel --particles 1e9'
hc $S err 'particles' '--particles 2.5' '$SD channel --particles 2.5'
hc $S err 't-warm' '--t-warm -1' '$SD channel --t-warm -1'
hc $S err 't-run' '--t-run 0' '$SD channel --t-run 0'
hc $S err 'dt-max' '--dt-max 0' '$SD channel --dt-max 0'
hc $S err 'c-tl' '--c-tl 2' '$SD channel --c-tl 2'
hc $S err 'c-y' '--c-y 0' '$SD channel --c-y 0'
hc $S err 'scheme' '--scheme euler' '$SD channel --scheme euler'
hc $S err 'seed' '--seed -1' '$SD channel --seed -1'
hc $S err 'seed' '--seed 1.5' '$SD channel --seed 1.5'
hc $S err 'layerYPlus' '--set layerYPlus=1 (below its range)' '$SD channel --set layerYPlus=1'
hc $S err 'foo' '--set foo=1 unknown key' '$SD channel --set foo=1'
hc $S err 'CT' '--set CT=nan' '$SD channel --set CT=nan'
hc $S err 'frob' 'unknown option' '$SD channel --frob'
hc $S err 'particles|t-run|work|steps|limit' '1e8 particles over t+ 1e9: work beyond any limit refused' '$SD channel --particles 1e8 --t-run 1e9 --tau-plus 1'
hc $S err 'particle steps|force' 'calibrate with 1e6 particles (3.3e11 steps, about a day): refused, --force named' '$SD calibrate --out c.coeffs --particles 1e6'
hc $S err 'particle steps|force' 'channel --closure with 1e7 particles: the closure runs counted in the estimate' '$SD channel --closure wood --particles 1e7 --tau-plus 1,10'
hc $S err "unknown option '1'" '--force takes no value: the stray value named' '$SD channel --force 1 --tau-plus 1'

# ---------------------------------------------------------------- snowphoto
S=snowphoto
P='--photo $fx/photo.png --corners $C_OK --sim $fx/sim.csv'
hc $S ok '' 'compare of a valid photo and map (control)' "\$SP compare $P --res 20"
hc $S ok '' 'regions of a valid map (control)' '$SP regions --sim $fx/sim.csv'
hc $S err 'command|usage' 'no command' '$SP'
hc $S err 'compair' 'unknown command' '$SP compair'
hc $S err 'photo' 'compare without --photo' '$SP compare --corners $C_OK --sim $fx/sim.csv'
hc $S err 'no/such' 'compare --photo missing' '$SP compare --photo no/such.png --corners $C_OK --sim $fx/sim.csv'
hc $S err 'text.png' 'compare --photo of text' '$SP compare --photo $fx/text.png --corners $C_OK --sim $fx/sim.csv'
hc $S err 'trunc.png' 'compare --photo truncated PNG' '$SP compare --photo $fx/trunc.png --corners 1,1,50,1,50,50,1,50 --sim $fx/sim.csv'
hc $S err 'photo|/dev/zero' 'compare --photo /dev/zero' '$SP compare --photo /dev/zero --corners $C_OK --sim $fx/sim.csv'
hc $S err 'corners' '--corners of 7 numbers' '$SP compare --photo $fx/photo.png --corners 10,10,700,10,700,600,10 --sim $fx/sim.csv'
hc $S err 'corners' '--corners of 9 numbers' '$SP compare --photo $fx/photo.png --corners $C_OK,5 --sim $fx/sim.csv'
hc $S err 'corners' '--corners outside the image' '$SP compare --photo $fx/photo.png --corners 10,10,9000,10,9000,600,10,600 --sim $fx/sim.csv'
hc $S err 'corners' '--corners bow-tie' '$SP compare --photo $fx/photo.png --corners 10,10,700,600,700,10,10,600 --sim $fx/sim.csv'
hc $S err 'corners' '--corners counter-clockwise (mirrored)' '$SP compare --photo $fx/photo.png --corners 10,10,10,600,700,600,700,10 --sim $fx/sim.csv'
hc $S err 'corners' '--corners degenerate (all one point)' '$SP compare --photo $fx/photo.png --corners 5,5,5,5,5,5,5,5 --sim $fx/sim.csv'
hc $S err 'corners' '--corners nan' '$SP compare --photo $fx/photo.png --corners nan,10,700,10,700,600,10,600 --sim $fx/sim.csv'
hc $S err 'sim' 'compare without --sim' '$SP compare --photo $fx/photo.png --corners $C_OK'
hc $S err 'simempty.csv' '--sim with no faces' '$SP regions --sim $fx/simempty.csv'
hc $S err 'simnan.csv' '--sim with a nan deposit' '$SP regions --sim $fx/simnan.csv'
hc $S err 'simneg.csv' '--sim with a negative deposit' '$SP regions --sim $fx/simneg.csv'
hc $S err 'simhole.csv' '--sim not a regular grid (a face missing)' '$SP regions --sim $fx/simhole.csv'
hc $S err 'simcols.csv' '--sim with a short row' '$SP regions --sim $fx/simcols.csv'
hc $S err 'sim|/dev/urandom' '--sim /dev/urandom' '$SP regions --sim /dev/urandom'
hc $S err 'photo-threshold' '--photo-threshold 2' "\$SP compare $P --photo-threshold 2"
hc $S err 'sim-threshold' '--sim-threshold -1' "\$SP compare $P --sim-threshold -1"
hc $S err 'sim-rel-threshold' '--sim-rel-threshold 0' "\$SP compare $P --sim-rel-threshold 0"
hc $S ok '' 'both thresholds: --sim-threshold is used (documented)' "\$SP compare $P --sim-threshold 0.1 --sim-rel-threshold 0.2"
hc $S err 'res' '--res 1' "\$SP compare $P --res 1"
hc $S err 'res' '--res 5000' "\$SP compare $P --res 5000"
hc $S err 'res' '--res 20.5' "\$SP compare $P --res 20.5"
hc $S err 'no/such' '--out into a missing folder: refused before any work, named' "\$SP compare $P --res 20 --out no/such/o.png"
hc $S err 'band' 'regions --band 0.3' '$SP regions --sim $fx/sim.csv --band 0.3'
hc $S err 'band' 'regions --band 0' '$SP regions --sim $fx/sim.csv --band 0'
hc $S err 'hold' 'regions --hold 0' '$SP regions --sim $fx/sim.csv --hold 0'
hc $S err 'hold' 'regions --hold 1.5' '$SP regions --sim $fx/sim.csv --hold 1.5'
hc $S err 'parcel-mass' 'regions --parcel-mass 1e-300' '$SP regions --sim $fx/sim.csv --parcel-mass 1e-300'
hc $S err 'parcel-mass' 'regions --parcel-mass 1e300' '$SP regions --sim $fx/sim.csv --parcel-mass 1e300'
hc $S err 'parcel-mass' 'regions --parcel-mass 0x1p-30' '$SP regions --sim $fx/sim.csv --parcel-mass 0x1p-30'
hc $S ok '' 'regions --label with control characters: escaped (documented)' "\$SP regions --sim \$fx/sim.csv --label \$'a|b\\\\nc\\x01'"
hc $S err 'photo' 'regions --photo (a compare option, unused)' '$SP regions --sim $fx/sim.csv --photo $fx/photo.png'
hc $S err 'band' 'compare --band (a regions option, unused)' "\$SP compare $P --band 0.1"
hc $S err 'parcel-mass' 'compare --parcel-mass (a regions option, unused)' "\$SP compare $P --parcel-mass 1e-9"
hc $S err 'out' 'regions --out (a compare option, unused)' '$SP regions --sim $fx/sim.csv --out o.png'
hc $S err 'frob' 'unknown option' '$SP regions --sim $fx/sim.csv --frob'
hc $S err 'sim' '--sim without a value' '$SP regions --sim'

# ---------------------------------------------------------------- the wedge: Allrun options and post scripts
# Allrun runs in a copy of the case's source files with SNOWWALL_TOP a stand-in
# repository whose bin/ holds only snowwedge (it checks Allrun's options): an option that
# is accepted stops at the pre-run check ('bin/snowregime missing', exit 1) instead of
# running the case
mkdir -p "$W" "$work/fake/etc"
(cd "$top/tutorials/wedge" && git ls-files -co --exclude-standard . | tar cf - -T -) | (cd "$W" && tar xf -)
printf '. "%s/etc/openfoam-env.sh"\n' "$top" > "$work/fake/etc/openfoam-env.sh"
cp "$top/etc/outdir.sh" "$work/fake/etc/"   # the list and output-folder rules Allrun sources
mkdir -p "$work/fake/bin" && ln -s "$top/bin/snowwedge" "$work/fake/bin/"
AR="SNOWWALL_TOP=$work/fake $W/Allrun"; export AR
S=wedge-Allrun
ACCEPT_RE='\(run etc/setup.sh|\(run ./Allwmake\)'
hc $S ok '' 'a valid option set reaches the pre-run checks (control)' 'eval "$AR -test -gate shear"'
for a in "-parallel 999" "-parallel 0" "-parallel abc" "-parallel 1.5" "-parallel" "-gate on" "-gate" "-sizes 0" \
         "-sizes 2000" "-sizes 5,,10" "-sizes 5.5" "-sizes" "-dispersion foo" "-dispersion nearwall,nearwall" \
         "-dispersion" "-oversubscribe" "-parallell 2" "--steady" "-steady -sizes 5" "-steady -feedback" \
         "-steady -rough" "-steady -rebound" "-rebound 2" "-steady -dispersion nearwall,crw" "-parallel 2 -test -parallel 99"; do
    hc $S err "${a%% *}|Allrun" "Allrun $a refused before anything is written" "eval \"\$AR $a\""
done
hc $S err 'sizes' 'Allrun -sizes 5,5 (a diameter twice)' 'eval "$AR -sizes 5,5"'
hc $S ok '' 'Allrun -sizes 10,5: unsorted, the same clouds' 'eval "$AR -sizes 10,5"'
hc $S err 'fine|test' 'Allrun -fine -test (two mesh levels)' 'eval "$AR -fine -test"'
hc $S ok '' 'Allrun -gate shear -gate off: the last one counts' 'eval "$AR -gate shear -gate off"'
hc $S ok '' 'Allrun -compare -gate shear: the main gate plus the three others (documented)' 'eval "$AR -compare -gate shear"'
hc $S ok '' 'Allrun -split without -sizes: splitting in every cloud (documented)' 'eval "$AR -split"'
ACCEPT_RE=
S=wedge-post
for a in "--case" "--case $W --out" "--case $W --out out --gate" "--case $W --out out --window 1e-,2,3" \
         "--case $W --out out --window 0,2,1" "--case $W --out out --window 0,1" "--case $W --out out --window nan,1,2" \
         "--out out" "--case $W" "--case $W --out out --frob" \
         "--case $W --out out --cloud"; do
    hc $S err "wedge-post" "wedge-post $a refused, --out not created" "\$W/post/wedge-post $a"
done
hc $S fail 'missing' 'wedge-post on a case without results: exit 1 (a missing result, documented), --out not created' '$W/post/wedge-post --case $W --out out'
hc $S fail 'no/such' 'wedge-post --case missing: exit 1 named' '$W/post/wedge-post --case no/such --out out'
hc $S fail 'no/such|missing' 'wedge-post --snowphoto missing: exit 1 named' '$W/post/wedge-post --case $W --out out --snowphoto no/such/exe'
for a in "" "--results" "--results . --frob" "--results . --sampled 0" "--results . --sampled 2" "--results . --sampled x"; do
    hc $S err "wedge-capture" "wedge-capture $a" "\$W/post/wedge-capture $a"
done
hc $S fail "wedge-capture: no no/such" "wedge-capture --results no/such: exit 1 (no results, documented), named" "\$W/post/wedge-capture --results no/such"
for a in "" "--results" "--results . --rel 0" "--results . --rel x" "--results . --frob"; do
    hc $S err "wedge-compare" "wedge-compare $a" "\$W/post/wedge-compare $a"
done
for a in "--results no/such --snowphoto \$SP" "--results . --snowphoto no/such/exe"; do
    hc $S fail "wedge-compare" "wedge-compare $a: exit 1 named" "\$W/post/wedge-compare $a"
done
for a in "" "--results . --out out" "--results . --out out --mvd 0" "--results . --out out --mvd 30 --sigma-g 0.5" \
         "--results . --out out --mvd 30 --range 50,10" "--results . --out out --mvd 30 --freeze 3" \
         "--results . --out out --masses no/such.csv" "--results . --out out --mvd 30 --masses m.csv" \
         "--results . --out out --mvd 30 --sampled 0" "--results . --out out --mvd x" "--results . --mvd 30"; do
    hc $S err "wedge-compose" "wedge-compose $a" "\$W/post/wedge-compose $a"
done
for a in "" "--results . --others crw" "--results . --main nearwall --others crw --frob"; do
    hc $S err "wedge-dispersion" "wedge-dispersion $a" "\$W/post/wedge-dispersion $a"
done
for a in "--results . --main nearwall" "--results no/such --main nearwall --others crw"; do
    hc $S fail "wedge-dispersion: no main" "wedge-dispersion $a: exit 1 (no results, documented), named" "\$W/post/wedge-dispersion $a"
done
hc $S fail "wedge-compose: no" "wedge-compose without results: exit 1 (documented), named, --out not created" "\$W/post/wedge-compose --results . --out out --mvd 30"
hc $S err "no/such" "wedge-panels --out into a missing folder: refused before any work, named" "\$W/post/wedge-panels --out no/such/o.png --title T \$fx/sim.csv A"
for a in "--out o.png --title T no/such.csv A" "--out o.png --title T \$fx/simempty.csv A"; do
    hc $S fail "no/such|simempty" "wedge-panels $a: exit 1 (a missing or empty map, documented)" "\$W/post/wedge-panels $a"
done
for a in "" "--out o.png" "--out o.png --title T" "--out o.png --title T a.csv"; do
    hc $S err "wedge-panels" "wedge-panels $a" "\$W/post/wedge-panels $a"
done
for a in "" "--variant foo --results . --gate off" "--variant rough --results . --gate" "--variant rough --results . --gate off --rel 0" "--variant rebound --results . --gate off --rel 2"; do
    hc $S err "wedge-variant" "wedge-variant $a" "\$W/post/wedge-variant $a"
done

# ---------------------------------------------------------------- OpenFOAM: snowWallInteraction, parcelSplitting, snowNearWall
# The box case (tests/openfoam/box) with one time step; each case edits its
# kinematicCloudProperties (the model's coefficients, the cloud functions) or its
# regime files and runs icoUncoupledKinematicParcelFoam: a bad input must stop it at
# set-up with a FatalIOError. SW_OPENFOAM_TOP: the tree whose platforms/lib holds the
# built wrapper (default this one).
oftop=${SW_OPENFOAM_TOP:-$top}
if [ -x /usr/bin/icoUncoupledKinematicParcelFoam ] && [ -f "$oftop/platforms/lib/libsnowWallInteraction.so" ] \
   && printf 'openfoam' | grep -qE -- "$only"; then
(
. "$oftop/etc/openfoam-env.sh" > /dev/null 2>&1
export FOAM_USER_LIBBIN="$oftop/platforms/lib"
B="$work/ofbase"; export B
cp -r "$top/tests/openfoam/box" "$B"
cp "$base" "$B/constant/regime.coeffs"
cp "$base" "$B/constant/regime-snow.coeffs"
(cd "$B" && blockMesh > log.blockMesh 2>&1 && foamDictionary -entry endTime -set 0.005 system/controlDict > /dev/null \
    && foamDictionary -entry libs -set '("libsnowWallInteraction.so" "libparcelSplitting.so")' system/controlDict > /dev/null \
    && rm -f log.blockMesh) || { echo "sweep.sh: cannot prepare the OpenFOAM base case" >&2; exit 1; }
python3 - "$B/constant/kinematicCloudProperties" <<'PY'
import re, sys
p = sys.argv[1]; s = open(p).read()
i = s.index("    snowWallInteractionCoeffs")
j = s.index("cloudFunctions {}")
s = s[:i] + "    snowWallInteractionCoeffs\n    {\n@BODY@\n    }\n}\n\ncloudFunctions\n{\n@CF@\n}\n"
open(p + ".in", "w").write(s)
PY
rm "$B/constant/kinematicCloudProperties"
# ofc BODY [CF] [DISPERSION]: the base case here, the coefficients body BODY (the fixture
# #included, the patches as in the box unless BODY has its own), the cloud functions CF
ofc() {
    cp -r "$B/." .
    OF_BODY="$1" OF_CF="${2:-}" python3 - constant/kinematicCloudProperties <<'PY'
import os, sys
p = sys.argv[1]; s = open(p + ".in").read()
body = os.environ["OF_BODY"]
if "patches" not in body.split("buildUp")[0].split("wallRegimes")[0]:
    body = 'patches ( wall { type snow; } "(top|sides)" { type escape; } );\n' + body
body = body.replace('#include "regime-snow.coeffs" ', '#include "regime-snow.coeffs"\n')
if '#include "regime.coeffs"' not in body and "@NOREGIME@" not in body:
    body = '#include "regime.coeffs"\n' + body
body = body.replace("@NOREGIME@", "")
s = s.replace("@BODY@", body).replace("@CF@", os.environ["OF_CF"])
open(p, "w").write(s)
PY
    rm -f constant/kinematicCloudProperties.in
}
export -f ofc
SOLVE='icoUncoupledKinematicParcelFoam'
of() {  # of PATTERN EXPECTED BODY [CF]: a case expected to stop with a FatalIOError
    SETUP="ofc $(printf '%q' "$3") $(printf '%q' "${4:-}")"
    hc "$S" fatal "$1" "$2 | $3${4:+ | cloudFunctions: $4}" "$SOLVE"
}
ofok() {  # ofok EXPECTED BODY [CF]: a control case that runs
    SETUP="ofc $(printf '%q' "$2") $(printf '%q' "${3:-}")"
    hc "$S" ok '' "$1 | $2${3:+ | cloudFunctions: $3}" "$SOLVE"
}
S=openfoam-snowWallInteraction
ofok 'the box with the fixture, no gates (control)' ''
of 'randomSeed' 'randomSeed -1' 'randomSeed -1;'
of 'randomSeed' 'randomSeed 1.5' 'randomSeed 1.5;'
of 'randomSeed' 'randomSeed abc' 'randomSeed abc;'
of 'randomSeed' 'randomSeed 1e30' 'randomSeed 1e30;'
of 'rebound' 'rebound foo' 'rebound foo;'
of 'rebound' 'rebound table without tables' 'rebound table;'
ofok 'rebound given twice: the last one counts (OpenFOAM merges a repeated key: its convention)' 'rebound auto; rebound classic;'
of 'reboundTangential' 'reboundTangential 2' 'reboundTangential 2;'
of 'reboundTangential' 'reboundTangential -0.1' 'reboundTangential -0.1;'
of 'reboundTangential' 'reboundTangential nan' 'reboundTangential nan;'
of 'stuckParcels' 'stuckParcels foo' 'stuckParcels foo;'
of 'stickParcels' 'unknown key, with the accepted keys' 'stickParcels keep;'
of 'tangentialgate|tangentialGate' 'misspelt gate tangentialgate' 'tangentialgate { vtMax 0.5; }'
of 'patches' 'patches ()' 'patches ();'
of 'patches|sides|top' 'a patch without an entry' 'patches ( wall { type snow; } );'
of 'nowhere' 'a patches entry matching no patch' 'patches ( wall { type snow; } "(top|sides)" { type escape; } nowhere { type snow; } );'
of 'sticky|type' 'patch type sticky' 'patches ( wall { type sticky; } "(top|sides)" { type escape; } );'
of 'patches' 'patches as a word' 'patches wall;'
of 'regime' 'no regime at all' '@NOREGIME@'
of 'tangentialGate' 'tangentialGate as a value' 'tangentialGate 0.5;'
of 'model|tangentialGate' 'tangentialGate model foo' 'tangentialGate { model foo; vtMax 0.5; }'
of 'vtMax' 'tangentialGate vtMax -1' 'tangentialGate { vtMax -1; }'
of 'vtMax' 'tangentialGate vtMax nan' 'tangentialGate { vtMax nan; }'
of 'dRef' 'tangentialGate dRef 0' 'tangentialGate { vtMax 0.5; dRef 0; }'
of 'exponent' 'tangentialGate exponent 1e300' 'tangentialGate { vtMax 0.5; exponent 1e300; }'
of 'vtMax|tangentialGate' 'tangentialGate without vtMax' 'tangentialGate { dRef 5e-5; }'
of 'oblique|regime' 'tangentialGate model regime without an oblique table' 'tangentialGate { model regime; }'
of 'slideLength' 'tangentialGate model constant with slideLength (unused)' 'tangentialGate { vtMax 0.5; slideLength 1e-4; }'
of 'vtTable' 'tangentialGate model constant with vtTable (unused)' 'tangentialGate { vtMax 0.5; vtTable (0 1); }'
of 'active' 'tangentialGate active maybe' 'tangentialGate { active maybe; vtMax 0.5; }'
of 'shearGate' 'shearGate as a value' 'shearGate 1;'
of 'model|shearGate' 'shearGate model foo' 'shearGate { model foo; }'
of 'roughnessFactor' 'shearGate roughnessFactor 0' 'shearGate { model adhesion; roughnessFactor 0; rhoAir 1; }'
of 'roughnessFactor' 'shearGate roughnessFactor -1' 'shearGate { model adhesion; roughnessFactor -1; rhoAir 1; }'
of 'tauCrit' 'shearGate constant tauCrit -1' 'shearGate { model constant; tauCrit -1; rhoAir 1; }'
of 'tauCrit' 'shearGate constant without tauCrit' 'shearGate { model constant; rhoAir 1; }'
of 'roughnessFactor' 'shearGate constant with roughnessFactor (unused)' 'shearGate { model constant; tauCrit 1; roughnessFactor 0.01; rhoAir 1; }'
of 'rhoAir' 'shearGate rhoAir 0' 'shearGate { model adhesion; roughnessFactor 0.01; rhoAir 0; }'
of 'rhoAir' 'shearGate rhoAir 1e300' 'shearGate { model adhesion; roughnessFactor 0.01; rhoAir 1e300; }'
of 'noSuchField|field' 'shearGate field noSuchField' 'shearGate { model adhesion; roughnessFactor 0.01; rhoAir 1; field noSuchField; }'
of 'buildUp' 'buildUp as a value' 'buildUp 1;'
of 'coverDiameter' 'buildUp coverDiameter 0' 'buildUp { #include "regime-snow.coeffs" coverDiameter 0; }'
of 'coverMass' 'buildUp coverMass -1' 'buildUp { #include "regime-snow.coeffs" coverMass -1; }'
of 'coverMass|coverDiameter' 'buildUp coverMass and coverDiameter' 'buildUp { #include "regime-snow.coeffs" coverMass 0.01; coverDiameter 3e-5; }'
of 'coverMass|coverDiameter' 'buildUp without coverMass or coverDiameter' 'buildUp { #include "regime-snow.coeffs" }'
of 'coverDiamter' 'buildUp misspelt coverDiamter' 'buildUp { #include "regime-snow.coeffs" coverDiamter 3e-5; }'
of 'patches' 'buildUp patches ()' 'buildUp { #include "regime-snow.coeffs" coverMass 0.01; patches (); }'
of 'top|snow|patches' 'buildUp on an escape patch' 'buildUp { #include "regime-snow.coeffs" coverMass 0.01; patches (top); }'
of 'nowhere|patches' 'buildUp patch that does not exist' 'buildUp { #include "regime-snow.coeffs" coverMass 0.01; patches (nowhere); }'
of 'regime' 'buildUp without a regime' 'buildUp { coverMass 0.01; }'
of 'wallRegimes' 'wallRegimes as a value' 'wallRegimes 1;'
ofok 'wallRegimes {} empty: no per-patch regime, as written' 'wallRegimes { }'
of 'patches' 'wallRegimes entry without patches' 'wallRegimes { r1 { #include "regime-snow.coeffs" } }'
of 'patches' 'wallRegimes entry patches ()' 'wallRegimes { r1 { patches (); #include "regime-snow.coeffs" } }'
of 'regime' 'wallRegimes entry without a regime' 'wallRegimes { r1 { patches (wall); } }'
of 'stickRecords' 'stickRecords ()' 'stickRecords ();'
of 'top|snow|stickRecords' 'stickRecords on an escape patch' 'stickRecords (top);'
of 'nowhere|stickRecords' 'stickRecords patch that does not exist' 'stickRecords (nowhere);'
of 'stickRecords' 'stickRecords as a word, not a list' 'stickRecords wall;'
ofok 'stickRecords (wall): the sticks on wall recorded' 'stickRecords (wall);'
of 'wall|twice|two' 'a patch in two wallRegimes entries' 'wallRegimes { r1 { patches (wall); #include "regime-snow.coeffs" } r2 { patches (wall); #include "regime-snow.coeffs" } }'
of 'top|snow' 'wallRegimes on an escape patch' 'wallRegimes { r1 { patches (top); #include "regime-snow.coeffs" } }'
of 'colour' 'wallRegimes entry with an unknown key' 'wallRegimes { r1 { patches (wall); colour red; #include "regime-snow.coeffs" } }'
of 'r1|dictionary' 'wallRegimes entry as a value' 'wallRegimes { r1 1; }'
# the regime file, #included: errors name that file and line
for v in unknown misspelt vnswap dswap degree nan hex nosemi twice dupkey version repr coeffsempty negative words oblcount oblsort rbcount rbrange pcount prange slopes; do
    SETUP="ofc '' && cp \$fx/$v.coeffs constant/regime.coeffs"
    hc "$S" fatal 'regime.coeffs' "the #included regime.coeffs: variant '$v', named with its file" "$SOLVE"
done
SETUP="ofc 'buildUp { #include \"regime-snow.coeffs\" coverMass 0.01; }' && cp \$fx/vnswap.coeffs constant/regime-snow.coeffs"
hc "$S" fatal 'regime-snow.coeffs' 'a bad regime file #included in buildUp: the error names regime-snow.coeffs' "$SOLVE"
SETUP="ofc 'wallRegimes { r1 { patches (wall); #include \"regime-snow.coeffs\" } }' && cp \$fx/nan.coeffs constant/regime-snow.coeffs"
hc "$S" fatal 'regime-snow.coeffs' 'a bad regime file #included in wallRegimes: the error names regime-snow.coeffs' "$SOLVE"
S=openfoam-parcelSplitting
L='regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 4; } );'
ofok 'parcelSplitting with one region (control)' '' "split { type parcelSplitting; $L }"
of 'factor' 'factor 0.5' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 0.5; } ); }'
of 'factor' 'factor 1e6' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 1e6; } ); }'
of 'factor' 'factor nan' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor nan; } ); }'
ofok 'factor 2.5: accepted, F is real (n = round(m F / m_ref) copies, doc/wallmodel.md)' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 2.5; } ); }'
of 'factor' 'region without factor' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); } ); }'
of 'maxCopies' 'maxCopies 1' '' "split { type parcelSplitting; maxCopies 1; $L }"
of 'maxParcels' 'maxParcels 0' '' "split { type parcelSplitting; maxParcels 0; $L }"
of 'maxParcels' 'maxParcels -5' '' "split { type parcelSplitting; maxParcels -5; $L }"
of 'box' 'box min > max' '' 'split { type parcelSplitting; regions ( lower { box (1 0.025 -1) (-1 0.06 1); factor 4; } ); }'
of 'box' 'box of one point' '' 'split { type parcelSplitting; regions ( lower { box (1 0.025 -1); factor 4; } ); }'
of 'boxes' 'boxes with 3 points' '' 'split { type parcelSplitting; regions ( lower { boxes ((0 0 0) (1 1 1) (2 2 2)); factor 4; } ); }'
of 'box' 'box and boxes' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); boxes ((0 0 0) (1 1 1)); factor 4; } ); }'
of 'regions' 'regions as a dictionary' '' 'split { type parcelSplitting; regions { lower { box (-1 0.025 -1) (1 0.06 1); factor 4; } } }'
of 'regions' 'regions as a word' '' 'split { type parcelSplitting; regions lower; }'
of 'regions' 'regions missing' '' 'split { type parcelSplitting; }'
of 'regions' 'regions ()' '' 'split { type parcelSplitting; regions (); }'
of 'lower' 'a region as a value' '' 'split { type parcelSplitting; regions ( lower 4 ); }'
of 'region name|4' 'a number where a region name belongs' '' 'split { type parcelSplitting; regions ( 4 ); }'
of 'region name|box' 'a second region without its name' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 4; } { box (-1 0 -1) (1 0.01 1); factor 2; } ); }'
of 'lower' 'a region named twice' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factor 4; } lower { box (-1 0.025 -1) (1 0.06 1); factor 2; } ); }'
of 'factr' 'a misspelt key in a region' '' 'split { type parcelSplitting; regions ( lower { box (-1 0.025 -1) (1 0.06 1); factr 4; factor 4; } ); }'
of 'maxCopy' 'a misspelt key of parcelSplitting' '' "split { type parcelSplitting; maxCopy 10; $L }"
S=openfoam-snowNearWall
of 'colour' 'snowNearWall: unknown key' '' 'nw { type snowNearWall; patches (wall); colour red; }'
of 'layerYPlus' 'snowNearWall: layerYPlus 1 (out of range)' '' 'nw { type snowNearWall; patches (wall); layerYPlus 1; }'
of 'CT' 'snowNearWall: CT nan' '' 'nw { type snowNearWall; patches (wall); CT nan; }'
of 'Cmu' 'snowNearWall: Cmu -1' '' 'nw { type snowNearWall; patches (wall); Cmu -1; }'
of 'patches' 'snowNearWall: patches ()' '' 'nw { type snowNearWall; patches (); }'
of 'nowhere|patches' 'snowNearWall: a patch that does not exist' '' 'nw { type snowNearWall; patches (nowhere); }'
of 'closure' 'snowNearWall: closure maybe' '' 'nw { type snowNearWall; patches (wall); closure maybe; }'
of 'depositionClosure' 'snowNearWall: depositionClosure as a value' '' 'nw { type snowNearWall; patches (wall); depositionClosure 1; }'
of 'tauPlus|vPlusSublayer' 'snowNearWall: closure lists of different lengths' '' 'nw { type snowNearWall; patches (wall); depositionClosure { layerYPlus 100; blendYPlus 150; CT 0.3; Cmu 0.09; tauPlus (1 2); vPlusSublayer (0.1); } }'
of 'turbulence|dispersion|RAS|laminar' 'snowNearWall on a laminar flow (no turbulence to walk with)' '' 'nw { type snowNearWall; patches (wall); }'
) || echo "sweep.sh: the OpenFOAM cases failed to run" >&2
else
    echo "sweep.sh: OpenFOAM or $oftop/platforms/lib/libsnowWallInteraction.so not there: OpenFOAM cases skipped" >&2
fi

#@CASES-END@
# ---------------------------------------------------------------- outputs: what was there before a tool writes
# Every output path of every tool and script against what can already be at it: a
# folder with a user's file (refused, nothing changed; with --force written, the
# user's file intact, no marker), the tool's own marked folder with a user's file (the
# file survives), a symbolic link, a regular file, and, at an output file's name, a
# FIFO or a device node made here (a /dev/full-like node, c 1 7; never a system one),
# each left as it was. The harness's before/after listing (name and type) catches any
# change in a refused case; the accepted ones check the user's file themselves.
S=outputs
FOREIGN='mkdir out && echo mine > out/notes.txt'
OWN='mkdir out && printf "SnowWall output folder\ntool: test\n" > out/.snowwall-output && echo mine > out/notes.txt'
KEPT='grep -qx mine out/notes.txt'
NOMARK='! test -e out/.snowwall-output'
# folder outputs: LABEL, the command before --out, a quick run's options, one output file
# name (empty: the refusals only, for tools whose run takes minutes or needs LAMMPS)
while IFS='|' read -r label pre quick fname; do
    [ -n "$label" ] || continue
    SETUP=$FOREIGN; hc $S err 'not empty|force' "$label --out a folder holding a user's file: refused, the file kept" "$pre --out out $quick"
    SETUP='mkdir real && echo mine > real/notes.txt && ln -s real out'
    hc $S err 'link' "$label --out a symbolic link to a folder: refused" "$pre --out out $quick"
    SETUP='echo mine > out'; hc $S err "out" "$label --out a regular file: refused, the file kept" "$pre --out out $quick"
    if [ -n "$fname" ]; then
        SETUP=$FOREIGN; hc $S ok '' "$label --force into a user's folder: written, the user's file intact, no marker" "$pre --out out $quick --force && $KEPT && $NOMARK"
        SETUP=$OWN; hc $S ok '' "$label into its own (marked) folder holding a user's file: the file survives" "$pre --out out $quick && $KEPT"
        # a C tool checks its fixed names before its work; a script finds the clash at its
        # commit and keeps the results in a named work folder (they may have taken hours)
        k=err; case "$pre" in *.sh*|*deposition-report*|*wedge-*) k=keep ;; esac
        SETUP="$OWN && mkfifo out/$fname"; hc $S $k "$fname" "$label: a FIFO at its output name $fname: refused, the FIFO kept" "$pre --out out $quick"
        SETUP="$OWN && mknod out/$fname c 1 7"; hc $S $k "$fname" "$label: a device node at its output name $fname: refused, the node kept" "$pre --out out $quick"
    fi
done <<LIST
snowregime map|\$SR map|--nd 4 --nv 4 --degree 1 --no-plot|map.csv
snowregime sensitivity|\$SR sensitivity|--nd 4 --nv 4 --no-plot|
snowregime convergence|\$SR convergence|--no-plot|
snowlammps|\$top/bin/snowlammps|--grid 2|
validation/rough-wall.sh|\$top/validation/rough-wall.sh|--quick|vcrit.md
validation/contact-laws.sh|\$top/validation/contact-laws.sh||
validation/rough-reference.sh|\$top/validation/rough-reference.sh|--quick|reference.md
validation/deposition.sh|\$top/validation/deposition.sh|--short|
validation/lammps-rough.sh|\$top/validation/lammps-rough.sh|--quick|
validation/codesaturne/channel.sh|\$top/validation/codesaturne/channel.sh||
deposition-report|\$top/validation/deposition/deposition-report \$fx/vplus.csv||vplus.md
wedge-post|\$W/post/wedge-post --case \$W||
wedge-compose|\$W/post/wedge-compose --results .|--mvd 20|
LIST
# single-file outputs: LABEL, the command with FILE where the output goes
while IFS='|' read -r label cmd; do
    [ -n "$label" ] || continue
    SETUP='mknod full c 1 7'; hc $S err 'full' "$label onto a device node (c 1 7, made here): refused, the node kept" "${cmd//FILE/full}"
    SETUP='mkfifo p'; hc $S err "'p'|p:" "$label onto a FIFO: refused, the FIFO kept" "${cmd//FILE/p}"
    SETUP='mkdir d'; hc $S err "'d'|d:" "$label onto a folder: refused" "${cmd//FILE/d}"
    SETUP='echo mine > real && ln -s real link'; hc $S err 'link' "$label onto a symbolic link: refused, the link and its target kept" "${cmd//FILE/link} ; r=\$?; grep -qx mine real; exit \$r"
done <<LIST
snowregime collide --trace-csv|\$SR collide --d 5e-5 --vn 1 --trace-csv FILE
snowregime collide --trace-vtk|\$SR collide --d 5e-5 --vn 1 --trace-vtk FILE
snowdeposit calibrate --out|\$SD calibrate --out FILE --particles 10 --t-warm 0 --t-run 1 --tau-plus 1
snowphoto compare --out|\$SP compare --photo \$fx/photo.png --corners \$C_OK --sim \$fx/sim.csv --res 20 --out FILE
snowgci --md|\$top/bin/snowgci --md FILE \$fx/gci.csv
wedge-panels --out|\$W/post/wedge-panels --out FILE --title T \$fx/sim.csv A
LIST

# ---------------------------------------------------------------- list options: the same rule everywhere
# An empty item or a value twice is refused naming the option; a numeric list out of
# order is taken in ascending order with a note (the same clouds, cells or runs).
S=lists
while IFS='|' read -r label cmd good; do
    [ -n "$label" ] || continue
    hc $S err "${label##* }" "$label: an empty item refused" "${cmd//LIST/${good%%,*},,${good#*,}}"
    hc $S err "${label##* }" "$label: a trailing comma refused" "${cmd//LIST/$good,}"
    hc $S err "${label##* }" "$label: a value twice refused" "${cmd//LIST/${good%%,*},$good}"
done <<LIST
snowregime vcrit --d|\$SR vcrit --d LIST|1e-5,2e-5
snowregime map --vt|\$SR map --out out --nd 4 --nv 4 --no-plot --vt LIST|0,0.5
snowregime convergence --accuracy|\$SR convergence --out out --no-plot --accuracy LIST|20,40
snowdeposit --tau-plus|\$SD channel --particles 10 --t-warm 0 --t-run 1 --tau-plus LIST|1,3
snowlammps --angles|\$top/bin/snowlammps --out out --angles LIST|0,30
validation/deposition.sh --tau-plus|\$top/validation/deposition.sh --out out --tau-plus LIST|1,3
validation/deposition.sh --models|\$top/validation/deposition.sh --out out --models LIST|nearwall,crw
validation/codesaturne/channel.sh --tau-plus|\$top/validation/codesaturne/channel.sh --out out --tau-plus LIST|1,3
validation/lammps-rough.sh --angles|\$top/validation/lammps-rough.sh --out out --angles LIST|0,30
wedge Allrun -sizes|eval "\$AR -sizes LIST"|5,10
wedge Allrun -dispersion|eval "\$AR -dispersion LIST"|nearwall,crw
LIST
hc $S warn 'ascending' 'snowregime vcrit --d 2e-5,1e-5: taken in ascending order, said so' '$SR vcrit --d 2e-5,1e-5'
hc $S warn 'ascending' 'snowdeposit channel --tau-plus 3,1: taken in ascending order, said so' '$SD channel --particles 10 --t-warm 0 --t-run 1 --tau-plus 3,1'
ACCEPT_RE='\(run etc/setup.sh|\(run ./Allwmake\)'
hc $S warn 'ascending' 'wedge Allrun -sizes 10,5: the same clouds, said so' 'eval "$AR -sizes 10,5"'
ACCEPT_RE=

# ---------------------------------------------------------------- resources: estimated and refused before any work
S=resources
hc $S err 'level' 'Allrun -level 9 (outside -3..3)' 'eval "$AR -level 9"'
hc $S err 'level' 'Allrun -level x' 'eval "$AR -level x"'
# these reach the estimate, which comes after the pre-run checks: the real repository
hc $S err 'GB|memory' 'Allrun -level 3: the replay library alone above the memory, refused with the figures' 'SNOWWALL_TOP=$top $W/Allrun -level 3'
SETUP='cp -r "$W" w && sed -i "s/^\( *replayInterval\) .*/\1 1e-6;/" w/constant/sprayProperties'
hc $S err 'replayInterval|maxDeltaT' 'Allrun -test with replayInterval 1e-6 (shorter than the step): refused before the spin-up' 'SNOWWALL_TOP=$top ./w/Allrun -test'
hc $S warn 'estimate' 'Allrun -estimate: one line of cells, memory, disk and time, nothing written' 'SNOWWALL_TOP=$top $W/Allrun -estimate'

# ---------------------------------------------------------------- the table
cat > "$work/notes.md" <<'NOTES'
Each with a regression test in the test file of its surface; the cases below are now clean.

- **A device replaced by a file** (`snowregime collide --trace-csv /dev/full`, as root):
  the output set renames its temporary over the final name, so the device node became a
  regular file, exit 0. An existing folder, device, FIFO or socket as an output is now
  refused, exit 1 named (`regime/tools/swt_io.c`; tests/regime_cli/test_errors.sh).
- **Inputs dropped without a word** (silent changes of meaning): `collide --x/--y` on a flat
  wall, `--stride` without a trace, one file for both traces; `snowregime --version map`;
  rough-wall settings (`lattice`, `asperity_*`, `wall_seed`, `rough_hold`) on a flat wall and
  `gamma` with `adhesion none`; a key given twice in a `--config` file (the later won);
  `convergence --accuracy 20,10,10`; `snowdeposit channel --law` (ran the default channel for
  minutes) and `calibrate --closure`; `Allrun -fine -test`, `Allrun -sizes 5,5`; the C
  loader's `vn`/`dCrit` beside a polynomial (and `coeffs`/`degree` with a table);
  `parcelSplitting` misspelt keys (`maxCopy`, a region's `factr`) and `box` beside `boxes`;
  `snowNearWall { depositionClosure 1; }` (taken as no closure). All refused now, named.
- **Hexadecimal numbers** accepted by strtod: `regime.coeffs` (`vnMax 0x6;`, which
  OpenFOAM's reader of the same file refuses) and `snowphoto --parcel-mass 0x1p-30`,
  `--corners 0x64,...`.
- **No message**: `wedge-capture`/`wedge-compose` exited 2 and `wedge-dispersion` 1 without a
  word on a results folder without results (an empty `ls | sort` under pipefail); now their
  own message, exit 1 as documented.
- `snowdeposit --set CT=nan` did not name the key.

Found by the run of 2026-11-25 17:14 and fixed (main, after the first sweep's fixes were merged):

- **Work without bound**: `snowdeposit channel --particles 1e8 --t-run 1e9` started a run of
  centuries without a word. The particle steps are now estimated from below before any work
  and refused over 1e10 unless `--force` (tools/snowdeposit/swc_main.c).
- **Leftover**: a shear gate whose `field` no function object makes stopped at the first
  impact, after the function objects had written `postProcessing/`; the field is now checked
  at set-up (registered, in the start time's folder, or made by a function object).
- **Silent**: a regime file `#include`d with a key or the `regime` block twice was merged by
  OpenFOAM (the later won) where the C loader refuses it; the wrapper now reads the file again
  with `inputMode error` and names the file, line and key. `snowNearWall` on a laminar flow
  walked with k = eps = 0 (dispersion none); refused at set-up.
- **Unnamed**: `parcelSplitting { regions ( lower 4 ); }` ended in "attempt to read beyond
  EOF"; the list is checked item by item (a name, then its block).

The outputs and resources round (2026-11-27; the `outputs` and `lists` surfaces and the
OpenFOAM estimates are its cases):

- **An output folder replaced by deletion**: `validation/rough-wall.sh --out DIR` (and
  deposition.sh, rough-reference.sh, contact-laws.sh, lammps-rough.sh,
  codesaturne/channel.sh, wedge-compose) removed DIR with whatever a user had in it and
  moved its own folder there; `deposition-report` removed every `.*.dat` in `--out`. Every
  script now goes through `etc/outdir.sh` and every C tool through `common/swo_out.c`: an
  `--out` folder is created, empty, or marked `.snowwall-output`, else refused unless
  `--force`; files are merged one by one after every target is checked; nothing is
  deleted that the run did not write.
- **A device replaced, again**: `snowdeposit calibrate --out /dev/full` (its own writer),
  `snowphoto`, `snowlammps` and the Code_Saturne book each had their own temp-and-rename;
  all now use the one writer, which refuses a folder, device, FIFO, socket or link at an
  output name and checks flush, sync and close (a full disk is exit 1).
- **List options**: `snowdeposit channel --tau-plus 1,,3` ran 1 and 3 without a word; every
  CLI and script now refuses empty items and repeats and takes numbers in ascending order
  with a note.
- **Resources found hours in**: the replay library's memory and an interval shorter than
  the time step; both are now checked before the first step (and by Allrun before any
  work), as are the stick records', parcel splitting's and the size classes' bounds.
- **A film patch**: a snow patch that the cloud's surface film also owns got nothing, in
  silence; it is now reported at set-up (fatal when it is every snow patch).

NOTES
secs=$(( $(date +%s) - start ))
total=$(wc -l < "$rows")
tmpout="$out.tmp.$$"
SW_NOTES="$work/notes.md" SW_ROWS="$rows" SW_CMD="$cmdline" SW_SECS="$secs" SW_NPROC="$(nproc)" \
SW_REV="$(git -C "$top" rev-parse --short HEAD 2>/dev/null || echo '?') on $(git -C "$top" rev-parse --abbrev-ref HEAD 2>/dev/null || echo '?')" \
python3 - "$tmpout" <<'PY' && mv "$tmpout" "$out" || { rm -f "$tmpout"; echo "sweep.sh: cannot write $out" >&2; exit 1; }
import collections, datetime, os, sys
rows = [l.rstrip("\n").split("\t") for l in open(os.environ["SW_ROWS"], encoding="utf-8", errors="replace")]
rows = [r + [""] * (6 - len(r)) for r in rows]
def cell(t, n=300):
    t = "".join(c if c >= " " else " " for c in t)[:n]
    return t.replace("\\", "\\\\").replace("|", "\\|").replace("`", "'").replace("<", "&lt;")
order = ["clean", "crash", "hang", "silent", "leftover", "unnamed", "setup-failed"]
cnt = collections.Counter(r[4] for r in rows)
surf = collections.Counter(r[1] for r in rows)
o = []
o.append("# Hostile-input sweep\n")
o.append("Generated by `%s` on %s in %s s (%s processors; commit %s)." % (
    os.environ["SW_CMD"], datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
    os.environ["SW_SECS"], os.environ["SW_NPROC"], os.environ["SW_REV"]))
o.append("Each case runs in a fresh folder under `timeout 60`. Outcomes: **clean** (the expected")
o.append("named refusal: exit 2, an OpenFOAM fatal error with exit 1, or exit 1 for an output")
o.append("failure or a missing result where that is the documented status; nothing left in the")
o.append("case folder; for a control case or a documented acceptance: accepted), **crash**")
o.append("(signal), **hang** (60 s), **silent** (accepted where a refusal or a warning was")
o.append("expected: a silent change of meaning), **leftover** (refused, files left), **unnamed**")
o.append("(refused with another exit status, or a message that does not name the input).")
o.append("The expected column says what the case should give and, where a case is accepted")
o.append("on purpose, why that is no change of meaning.\n")
o.append("| outcome | cases |\n|---|---:|")
for k in order:
    if cnt[k] or k != "setup-failed":
        o.append("| %s | %d |" % (k, cnt[k]))
o.append("| **total** | **%d** |\n" % len(rows))
o.append("Cases per surface: " + ", ".join("%s %d" % (k, v) for k, v in surf.items()) + ".\n")
o.append("## Found by earlier sweeps and fixed\n")
o.append(open(os.environ["SW_NOTES"]).read())
o.append("## Findings of this run (cases that are not clean)\n")
bad = [r for r in rows if r[4] != "clean"]
for r in bad:
    o.append("- case %s (%s, **%s**): `%s`: expected %s; got: %s" % (r[0], r[1], r[4], cell(r[2], 160), cell(r[3]), cell(r[5], 200)))
if not bad:
    o.append("None: every case is clean.")
o.append("\n## Cases\n")
o.append("| case | surface | input | expected | outcome | message (first line) |")
o.append("|---:|---|---|---|---|---|")
for r in rows:
    o.append("| %s | %s | `%s` | %s | %s | %s |" % (r[0], r[1], cell(r[2]), cell(r[3]), r[4], cell(r[5])))
open(sys.argv[1], "w").write("\n".join(o) + "\n")
PY
count() { awk -F'\t' -v o="$1" '$5 == o' "$rows" | wc -l; }
bad=$((total - $(count clean)))
echo "sweep.sh: $total cases, $(count clean) clean, $bad not (crash $(count crash), hang $(count hang), silent $(count silent), leftover $(count leftover), unnamed $(count unnamed)) in ${secs} s; table: $out"
[ "$bad" = 0 ]
