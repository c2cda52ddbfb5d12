#!/usr/bin/env bash
# test_outdir.sh - etc/outdir.sh, the output folders and list options of the shell
# scripts: a missing folder (created, marked), an empty one, an own one with an
# earlier run's file and a user's file (the user's file stays), a foreign one
# (refused, exit 2, unchanged; with --force written, no marker), a device node, a
# FIFO, a folder and a symbolic link where an output file goes (the whole commit
# refused, the node untouched), a link given as --out, a file given as --out, a
# read-only folder (as an unprivileged user), a failed run (nothing left), one-file
# outputs, the list rules; then validation/rough-wall.sh end to end on a folder
# holding a user's file.
set -u
top=${SW_TOP:?SW_TOP not set (run through ctest)}
lib=$top/etc/outdir.sh
w=$(mktemp -d "${TMPDIR:-/tmp}/outdir.XXXXXX")
trap 'rm -rf -- "$w"' EXIT
fails=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fails=$((fails + 1)); fi; }

# a script of the kind the project has: --out DIR [--force], two files and a
# subfolder, FAIL=1 makes it fail after the work began
cat >"$w/drv.sh" <<EOF
set -euo pipefail
. "$lib"
out=\$1 force=\${2:-0}
outdir_begin drv.sh "\$out" "\$force" \${3:-}
echo "run \${RUN:-1}" >"\$tmp/result.txt"
mkdir "\$tmp/sub"; echo inner >"\$tmp/sub/inner.txt"
[ "\${FAIL:-0}" = 0 ] || { echo "drv.sh: failed" >&2; exit 1; }
outdir_commit
EOF
drv() { bash "$w/drv.sh" "$@" >"$w/out.log" 2>"$w/err.log"; }
state() { (cd "$1" && find . -printf '%p %y %s %m\n' | LC_ALL=C sort && find . -type f -exec cksum {} + | LC_ALL=C sort); }
leftover() { ls -A "$1" | grep -q '^\.drv\.'; }

# 1. a missing folder: created with the files and the marker, no work folder left
drv "$w/new"; rc=$?
check "missing folder: exit 0" "[ $rc = 0 ]"
check "missing folder: files written" "[ \"\$(cat '$w/new/result.txt')\" = 'run 1' ] && [ -f '$w/new/sub/inner.txt' ]"
check "missing folder: marker lines" "[ \"\$(head -n 1 '$w/new/.snowwall-output')\" = 'SnowWall output folder' ] && grep -q '^tool: drv.sh\$' '$w/new/.snowwall-output' && grep -Eq '^written: [0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z\$' '$w/new/.snowwall-output'"
check "missing folder: no work folder left" "! leftover '$w'"

# 2. an empty folder
mkdir "$w/empty"
drv "$w/empty"; rc=$?
check "empty folder: exit 0, files and marker" "[ $rc = 0 ] && [ -f '$w/empty/result.txt' ] && [ -f '$w/empty/.snowwall-output' ]"
check "empty folder: no work folder left" "! leftover '$w/empty'"

# 3. an own folder: the earlier run's file replaced, the user's file kept
echo "mine" >"$w/new/notes.txt"
RUN=2 drv "$w/new"; rc=$?
check "own folder: exit 0" "[ $rc = 0 ]"
check "own folder: the earlier run's file replaced" "[ \"\$(cat '$w/new/result.txt')\" = 'run 2' ]"
check "own folder: the user's file stays" "[ \"\$(cat '$w/new/notes.txt')\" = mine ]"
check "own folder: no work folder left" "! leftover '$w/new'"

# 4. a foreign folder: refused before any work, nothing changed; --force writes
# beside the foreign file and adds no marker
mkdir "$w/foreign"; echo "keep" >"$w/foreign/notes.txt"
before=$(state "$w/foreign")
drv "$w/foreign"; rc=$?
check "foreign folder: exit 2" "[ $rc = 2 ]"
check "foreign folder: one line naming the folder, the entry and --force" \
    "[ \$(wc -l <'$w/err.log') = 1 ] && grep -q \"drv.sh: --out: '$w/foreign' is not empty and not a SnowWall output folder (holds 'notes.txt'); give --force\" '$w/err.log'"
check "foreign folder: nothing changed" "[ \"\$(state '$w/foreign')\" = \"\$before\" ]"
drv "$w/foreign" 1; rc=$?
check "foreign folder --force: exit 0, files written" "[ $rc = 0 ] && [ -f '$w/foreign/result.txt' ] && [ -f '$w/foreign/sub/inner.txt' ]"
check "foreign folder --force: the foreign file intact" "[ \"\$(cat '$w/foreign/notes.txt')\" = keep ]"
check "foreign folder --force: no marker" "[ ! -e '$w/foreign/.snowwall-output' ]"
check "foreign folder --force: no work folder left" "! leftover '$w/foreign'"
# a marker that is not a regular file does not make a folder own
mkdir "$w/fakemark"; mkdir "$w/fakemark/.snowwall-output"
drv "$w/fakemark"; rc=$?
check "a folder named .snowwall-output is no marker: exit 2" "[ $rc = 2 ] && [ ! -e '$w/fakemark/result.txt' ]"

# 5. what sits at an output name and is not a regular file: the whole commit is
# refused before its first move (sub/inner.txt not moved either), the thing stays
node() {  # node LABEL FLAG SETUP: an own folder with SETUP done in it, then a run
    local d="$w/node_$1"
    mkdir "$d"; : >"$d/.snowwall-output"
    (cd "$d" && eval "$3")
    drv "$d"; local rc=$?
    check "$1 at result.txt: exit 2, named" "[ $rc = 2 ] && grep -q \"'$d/result.txt'\" '$w/err.log'"
    check "$1 at result.txt: untouched" "[ $2 '$d/result.txt' ]"
    check "$1 at result.txt: nothing moved" "[ ! -e '$d/sub' ]"
    check "$1 at result.txt: the results kept and named" "grep -q 'results are kept in' '$w/err.log'"
    rm -rf -- "$d"/.drv.*
}
if [ "$(id -u)" = 0 ]; then
    node device -c "mknod result.txt c 1 3"   # a character device in this test's own folder
else
    echo "skip device node: mknod needs root"
fi
node fifo -p "mkfifo result.txt"
node folder -d "mkdir result.txt; echo x > result.txt/x"
node symlink -L "ln -s ../notes.txt result.txt"
# a subfolder name taken by a file, or by a link to a folder
mkdir "$w/subfile"; : >"$w/subfile/.snowwall-output"; echo x >"$w/subfile/sub"
drv "$w/subfile"; rc=$?
check "a file where the subfolder goes: exit 2, kept" "[ $rc = 2 ] && [ \"\$(cat '$w/subfile/sub')\" = x ] && [ ! -e '$w/subfile/result.txt' ]"
rm -rf -- "$w/subfile"/.drv.*
mkdir "$w/sublink" "$w/elsewhere"; : >"$w/sublink/.snowwall-output"; ln -s ../elsewhere "$w/sublink/sub"
drv "$w/sublink"; rc=$?
check "a link where the subfolder goes: exit 2, nothing written through it" "[ $rc = 2 ] && [ -z \"\$(ls -A '$w/elsewhere')\" ]"
rm -rf -- "$w/sublink"/.drv.*

# 6. --out a symbolic link to a folder, or a file
mkdir "$w/target"; echo t >"$w/target/t.txt"; ln -s target "$w/link"
for arg in "$w/link" "$w/link/"; do
    drv "$arg"; rc=$?
    check "--out '$arg' (a link): exit 2, named" "[ $rc = 2 ] && grep -q 'symbolic link' '$w/err.log'"
done
check "--out a link: its folder unchanged" "[ \"\$(ls -A '$w/target')\" = t.txt ]"
echo f >"$w/afile"
drv "$w/afile"; rc=$?
check "--out a file: exit 2, the file unchanged" "[ $rc = 2 ] && grep -q 'not a folder' '$w/err.log' && [ \"\$(cat '$w/afile')\" = f ]"
drv "$w/no/such/out"; rc=$?
check "--out with a missing parent: exit 2, named" "[ $rc = 2 ] && grep -q \"parent folder '$w/no/such' does not exist\" '$w/err.log'"

# 7. a run that fails: nothing written, nothing left; made parents removed again
FAIL=1 drv "$w/failed"; rc=$?
check "failed run: exit 1, no folder, no work folder" "[ $rc = 1 ] && [ ! -e '$w/failed' ] && ! leftover '$w'"
state0=$(state "$w/new")
FAIL=1 RUN=3 drv "$w/new"; rc=$?
check "failed run into an own folder: unchanged" "[ $rc = 1 ] && [ \"\$(state '$w/new')\" = \"\$state0\" ]"
FAIL=1 drv "$w/p1/p2/out" 0 parents; rc=$?
check "failed run with parents: the parents made are removed" "[ $rc = 1 ] && [ ! -e '$w/p1' ]"
drv "$w/p1/p2/out" 0 parents; rc=$?
check "parents: made, the folder written" "[ $rc = 0 ] && [ -f '$w/p1/p2/out/result.txt' ]"

# 8. a read-only folder, as an unprivileged user (root's writes ignore permissions)
mkdir -m 755 "$w/ro_area"; cp "$lib" "$w/ro_area/outdir.sh"
sed "s|^\. \".*\"$|. \"$w/ro_area/outdir.sh\"|" "$w/drv.sh" >"$w/ro_area/drv.sh"
mkdir -m 555 "$w/ro_area/ro"
chmod 755 "$w"; chmod 644 "$w/ro_area/outdir.sh" "$w/ro_area/drv.sh"
as_user=()
if [ "$(id -u)" = 0 ]; then
    if setpriv --reuid=nobody --regid=nogroup --clear-groups test -r "$w/ro_area/drv.sh" 2>/dev/null; then
        as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
    else
        as_user=(skip)
    fi
fi
if [ "${as_user[0]:-}" = skip ]; then
    echo "skip read-only folder: cannot run as an unprivileged user"
else
    "${as_user[@]}" bash "$w/ro_area/drv.sh" "$w/ro_area/ro" >/dev/null 2>"$w/err.log"; rc=$?
    check "read-only folder: exit 2, named" "[ $rc = 2 ] && grep -q \"'$w/ro_area/ro' is not writable\" '$w/err.log'"
    check "read-only folder: nothing written" "[ -z \"\$(ls -A '$w/ro_area/ro')\" ] && [ \"\$(ls -A '$w/ro_area')\" = \"\$(printf 'drv.sh\noutdir.sh\nro')\" ]"
fi
chmod 700 "$w"

# 9. one-file outputs (--out PNG): only a regular file is replaced
fileout() { bash -c '. "$1"; echo new > "$2.tmp"; outdir_file_check t --out "$2" && outdir_publish_file t "$2.tmp" "$2"' _ "$lib" "$1" 2>"$w/err.log"; }
echo old >"$w/f.png"; fileout "$w/f.png"; rc=$?
check "one file: a regular file replaced" "[ $rc = 0 ] && [ \"\$(cat '$w/f.png')\" = new ]"
mkfifo "$w/p.png"; fileout "$w/p.png"; rc=$?
check "one file: a FIFO refused, exit 2, still a FIFO, no temporary left" "[ $rc = 2 ] && [ -p '$w/p.png' ] && grep -q 'not a regular file' '$w/err.log'"
ln -s f.png "$w/l.png"; fileout "$w/l.png"; rc=$?
check "one file: a link refused" "[ $rc = 2 ] && [ -L '$w/l.png' ] && [ \"\$(cat '$w/f.png')\" = new ]"

# 10. list options
lst() { bash -c '. "$1"; outdir_list v my.sh "$2" "$3" "$4" && echo "$v"' _ "$lib" "$@" >"$w/l.out" 2>"$w/l.err"; }
for t in '1,,3' ',1' '1,' ''; do
    lst --tau-plus "$t" num; rc=$?
    check "list '$t': exit 2, the option and the text named" "[ $rc = 2 ] && grep -q \"^my.sh: --tau-plus: \" '$w/l.err' && { [ -z '$t' ] || grep -qF \"'$t'\" '$w/l.err'; } && [ ! -s '$w/l.out' ]"
done
lst --tau-plus 1,3,1e0 num; rc=$?
check "list: a value twice (1 and 1e0) refused" "[ $rc = 2 ] && grep -q \"'1e0' is given twice in '1,3,1e0'\" '$w/l.err'"
lst --tau-plus 1,x num; rc=$?
check "list: a non-number refused" "[ $rc = 2 ] && grep -q \"'x' in '1,x' is not a number\" '$w/l.err'"
lst --tau-plus 10,0.3,3 num; rc=$?
check "list: unsorted taken in ascending order" "[ $rc = 0 ] && [ \"\$(cat '$w/l.out')\" = 0.3,3,10 ]"
check "list: the note, one line" "[ \"\$(cat '$w/l.err')\" = \"my.sh: note: --tau-plus: '10,0.3,3' taken in ascending order\" ]"
lst --tau-plus 0.3,3,10 num; rc=$?
check "list: sorted, no note" "[ $rc = 0 ] && [ \"\$(cat '$w/l.out')\" = 0.3,3,10 ] && [ ! -s '$w/l.err' ]"
lst --models none,gradient name; rc=$?
check "name list: order kept, no note" "[ $rc = 0 ] && [ \"\$(cat '$w/l.out')\" = none,gradient ] && [ ! -s '$w/l.err' ]"
lst --models none,gradient,none name; rc=$?
check "name list: a name twice refused" "[ $rc = 2 ] && grep -q \"'none' is given twice\" '$w/l.err'"
lst --models none,,crw name; rc=$?
check "name list: an empty item refused" "[ $rc = 2 ] && grep -q \"empty item in 'none,,crw'\" '$w/l.err'"

# 11. a real script: validation/rough-wall.sh --quick on a folder holding a user's file
SR=${SW_BUILD:-}/regime/cli/snowregime
[ -x "$SR" ] || SR=$top/bin/snowregime
if [ -x "$SR" ]; then
    RW=$top/validation/rough-wall.sh
    mkdir "$w/rw"; echo "my notes" >"$w/rw/notes.txt"
    before=$(state "$w/rw")
    SNOWREGIME=$SR "$RW" --out "$w/rw" --quick >"$w/rw.log" 2>&1; rc=$?
    check "rough-wall.sh on a foreign folder: exit 2, named, unchanged" \
        "[ $rc = 2 ] && grep -q \"'$w/rw' is not empty and not a SnowWall output folder (holds 'notes.txt')\" '$w/rw.log' && [ \"\$(state '$w/rw')\" = \"\$before\" ]"
    t0=$(date +%s)
    SNOWREGIME=$SR "$RW" --out "$w/rw" --quick --force >"$w/rw.log" 2>&1; rc=$?
    echo "     (rough-wall.sh --quick: $(( $(date +%s) - t0 )) s)"
    check "rough-wall.sh --force: exit 0, outputs written" "[ $rc = 0 ] && [ -s '$w/rw/vcrit.md' ] && [ -s '$w/rw/map/regime.coeffs' ]" || cat "$w/rw.log"
    check "rough-wall.sh --force: the user's file intact, no marker, no work folder" \
        "[ \"\$(cat '$w/rw/notes.txt')\" = 'my notes' ] && [ ! -e '$w/rw/.snowwall-output' ] && ! ls -A '$w/rw' | grep -q '^\.rough-wall'"
else
    echo "skip rough-wall.sh end to end: no snowregime built"
fi

[ "$fails" = 0 ] && { echo PASS; exit 0; }
echo "$fails failure(s)"; exit 1
