# shellcheck shell=bash
# etc/outdir.sh - sourced by the project's shell scripts (bash): output folders
# that never destroy what the script did not write, and strict list options.
#
# The output-folder rules (the same for the C tools):
#   A folder is a SnowWall output folder when it holds a regular file
#   .snowwall-output (first line "SnowWall output folder", then "tool: NAME"
#   and "written: <UTC time>").
#   --out DIR missing: created (its parent must exist, or the parents are
#     created when the script asks for it), the marker written.
#   DIR an existing folder, empty or holding the marker: the script's files are
#     written into it; files of other names already there are left alone.
#   DIR holding anything else and no marker: refused before any work (exit 2,
#     the folder and one foreign entry named); with --force the script writes
#     its own files into it, replaces only regular files of its own output
#     names, deletes nothing and adds no marker.
#   DIR a symbolic link, or not a folder, or not writable: refused (exit 2).
#   A final name that exists and is not a regular file (a folder where a file
#   goes, a device, FIFO, socket or symbolic link), or that is not a folder
#   where a folder goes, refuses the whole commit before its first move
#   (exit 2; the run's results are kept in their temporary folder, named).
#   Nothing is deleted but the script's own temporary folder.
#
# Functions (TOOL: the script's name in messages, e.g. rough-wall.sh):
#   outdir_begin TOOL OUT FORCE [parents]
#       check OUT before any work (FORCE: 1 when --force was given; parents:
#       create OUT's missing parents, removed again when they stay empty after
#       a failed run), and make the work folder $tmp (absolute path): inside OUT
#       when OUT exists (the moves stay on OUT's file system), else beside it.
#       $tmp is removed when the script exits without outdir_commit (kept for a
#       look when KEEP_TMP is set). A script with its own EXIT trap calls
#       outdir_cleanup from it.
#   outdir_commit
#       merge $tmp's files into OUT file by file (subfolders merged), after
#       checking every target; OUT's marker written unless --force was used on
#       a folder without it; then $tmp removed. A missing OUT is made by
#       renaming $tmp itself (it appears whole).
#   outdir_file_check TOOL OPT PATH
#       for an option naming one output file: PATH must be absent or a regular
#       file (not a symbolic link) and its folder must exist; else exit 2.
#   outdir_publish_file TOOL TMPFILE PATH
#       rename TMPFILE (written in PATH's folder) to PATH after the same check
#       (TMPFILE removed and exit 2 when refused).
#   outdir_list VAR TOOL OPT TEXT num|name
#       a comma-separated list option: an empty item (1,,3 ,1 1,) or a
#       duplicate is refused naming OPT and TEXT (exit 2); a num list must hold
#       numbers and is put in ascending order (a one-line note on stderr when
#       it was not); a name list keeps its order. The list, comma-separated,
#       goes into the variable VAR.
# Exit statuses: 2 for every refusal above; 1 when a move fails midway.

OUTDIR_MARKER=.snowwall-output

outdir__die() { echo "$OUTDIR_TOOL: $*" >&2; exit 2; }

# outdir__abs PATH: PATH made absolute (its parent resolved; PATH need not exist)
outdir__abs() {
    local d b
    d=$(dirname -- "$1"); b=$(basename -- "$1")
    d=$(cd -- "$d" 2>/dev/null && pwd -P) || return 1
    case "$b" in
        /) echo / ;;
        .|..) (cd -- "$d/$b" && pwd -P) ;;
        *) [ "$d" = / ] && echo "/$b" || echo "$d/$b" ;;
    esac
}

outdir_begin() {
    OUTDIR_TOOL=$1 OUTDIR_ARG=$2 OUTDIR_FORCE=${3:-0}
    local parents=${4:-} parent first
    OUTDIR_MARK=1 OUTDIR_MADE='' OUTDIR_NEW=0
    [ -n "$OUTDIR_ARG" ] || outdir__die "--out: an empty folder name"
    # without its trailing slashes (a link given as LINK/ is still the link)
    while [ "${OUTDIR_ARG%/}" != "$OUTDIR_ARG" ] && [ "$OUTDIR_ARG" != / ]; do OUTDIR_ARG=${OUTDIR_ARG%/}; done
    if [ -L "$OUTDIR_ARG" ]; then
        outdir__die "--out: '$OUTDIR_ARG' is a symbolic link: give the folder itself"
    elif [ -e "$OUTDIR_ARG" ] && [ ! -d "$OUTDIR_ARG" ]; then
        outdir__die "--out: '$OUTDIR_ARG' exists and is not a folder"
    elif [ -d "$OUTDIR_ARG" ]; then
        [ -w "$OUTDIR_ARG" ] && [ -x "$OUTDIR_ARG" ] || outdir__die "--out: folder '$OUTDIR_ARG' is not writable"
        if [ -f "$OUTDIR_ARG/$OUTDIR_MARKER" ] && [ ! -L "$OUTDIR_ARG/$OUTDIR_MARKER" ]; then
            :   # a SnowWall output folder
        else
            first=$(LC_ALL=C ls -A -- "$OUTDIR_ARG" 2>/dev/null) \
                || outdir__die "--out: cannot list folder '$OUTDIR_ARG'"
            first=${first%%$'\n'*}
            if [ -n "$first" ]; then
                [ "$OUTDIR_FORCE" = 1 ] || outdir__die "--out: '$OUTDIR_ARG' is not empty and not a SnowWall output folder (holds '$first'); give --force to write into it"
                OUTDIR_MARK=0
            fi
        fi
        OUTDIR_OUT=$(cd -- "$OUTDIR_ARG" && pwd -P) || outdir__die "--out: cannot enter folder '$OUTDIR_ARG'"
        tmp=$(mktemp -d "$OUTDIR_OUT/.${OUTDIR_TOOL%.sh}.XXXXXX" 2>/dev/null) \
            || outdir__die "--out: cannot make a work folder in '$OUTDIR_ARG'"
    else
        OUTDIR_NEW=1
        parent=$(dirname -- "$OUTDIR_ARG")
        if [ ! -d "$parent" ] && [ "$parents" = parents ]; then
            local p=$parent
            while [ ! -e "$p" ] && [ ! -L "$p" ]; do OUTDIR_MADE=$p; p=$(dirname -- "$p"); done
            mkdir -p -- "$parent" 2>/dev/null || outdir__die "--out: cannot make folder '$parent'"
            OUTDIR_MADE=$(outdir__abs "$OUTDIR_MADE")
        fi
        [ -d "$parent" ] || outdir__die "--out: parent folder '$parent' does not exist"
        [ -w "$parent" ] && [ -x "$parent" ] || outdir__die "--out: parent folder '$parent' is not writable"
        OUTDIR_OUT=$(outdir__abs "$OUTDIR_ARG") || outdir__die "--out: cannot resolve '$OUTDIR_ARG'"
        tmp=$(mktemp -d "$(dirname -- "$OUTDIR_OUT")/.${OUTDIR_TOOL%.sh}.XXXXXX" 2>/dev/null) \
            || outdir__die "--out: cannot make a work folder beside '$OUTDIR_ARG'"
    fi
    OUTDIR_TMP=$tmp
    OUTDIR_DONE=0
    trap outdir_cleanup EXIT
}

# outdir_cleanup: the EXIT trap: the work folder and the parents made, when not committed
outdir_cleanup() {
    [ "${OUTDIR_DONE:-1}" = 0 ] || return 0
    [ -n "${KEEP_TMP:-}" ] && { echo "$OUTDIR_TOOL: the work folder is kept: $OUTDIR_TMP" >&2; return 0; }
    [ -z "${OUTDIR_TMP:-}" ] || rm -rf -- "$OUTDIR_TMP"
    if [ -n "${OUTDIR_MADE:-}" ]; then   # the parents made, only while empty
        local p
        p=$(dirname -- "$OUTDIR_OUT")
        while rmdir -- "$p" 2>/dev/null; do
            [ "$p" = "$OUTDIR_MADE" ] && break
            p=$(dirname -- "$p")
        done
    fi
    return 0
}

# outdir__keep MESSAGE: refuse the commit, keep the results in the work folder
outdir__keep() {
    OUTDIR_DONE=1
    echo "$OUTDIR_TOOL: --out: $1; nothing was moved, the results are kept in '$OUTDIR_TMP'" >&2
    exit 2
}

outdir_commit() {
    local rel t n=0
    if [ "$OUTDIR_MARK" = 1 ]; then
        printf 'SnowWall output folder\ntool: %s\nwritten: %s\n' "$OUTDIR_TOOL" \
            "$(date -u +%Y-%m-%dT%H:%M:%SZ)" > "$OUTDIR_TMP/$OUTDIR_MARKER"
    fi
    if [ "$OUTDIR_NEW" = 1 ]; then
        # OUT was missing: the work folder becomes it (mode as the umask gives)
        chmod "$(printf '%o' $(( 0777 & ~$(umask) )))" "$OUTDIR_TMP"
        if [ ! -e "$OUTDIR_OUT" ] && [ ! -L "$OUTDIR_OUT" ] && mv -T -- "$OUTDIR_TMP" "$OUTDIR_OUT" 2>/dev/null; then
            OUTDIR_DONE=1
            trap - EXIT
            return 0
        fi
        # it appeared meanwhile: the same checks as for an existing folder
        [ -d "$OUTDIR_OUT" ] && [ ! -L "$OUTDIR_OUT" ] || outdir__keep "'$OUTDIR_ARG' appeared during the run and is not a folder"
    fi
    # every target checked before the first move
    while IFS= read -r -d '' rel; do
        rel=${rel#./}
        t=$OUTDIR_OUT/$rel
        if [ -d "$OUTDIR_TMP/$rel" ] && [ ! -L "$OUTDIR_TMP/$rel" ]; then
            if [ -L "$t" ] || { [ -e "$t" ] && [ ! -d "$t" ]; }; then
                outdir__keep "'$OUTDIR_ARG/$rel' exists and is not a folder"
            fi
        elif [ -L "$t" ]; then
            outdir__keep "'$OUTDIR_ARG/$rel' is a symbolic link"
        elif [ -e "$t" ] && [ ! -f "$t" ]; then
            outdir__keep "'$OUTDIR_ARG/$rel' exists and is not a regular file"
        fi
        n=$((n + 1))
    done < <(cd -- "$OUTDIR_TMP" && find . -mindepth 1 -print0)
    # folders first (made when missing), then the files and links, renamed
    while IFS= read -r -d '' rel; do
        rel=${rel#./}
        [ -d "$OUTDIR_OUT/$rel" ] || mkdir -- "$OUTDIR_OUT/$rel" \
            || { echo "$OUTDIR_TOOL: cannot make '$OUTDIR_ARG/$rel' (results kept in '$OUTDIR_TMP')" >&2; OUTDIR_DONE=1; exit 1; }
    done < <(cd -- "$OUTDIR_TMP" && find . -mindepth 1 -type d -print0)
    while IFS= read -r -d '' rel; do
        rel=${rel#./}
        mv -f -T -- "$OUTDIR_TMP/$rel" "$OUTDIR_OUT/$rel" \
            || { echo "$OUTDIR_TOOL: cannot move '$rel' into '$OUTDIR_ARG' (the rest kept in '$OUTDIR_TMP')" >&2; OUTDIR_DONE=1; exit 1; }
    done < <(cd -- "$OUTDIR_TMP" && find . -mindepth 1 ! -type d -print0)
    # only the emptied folders of the work folder are left: removed
    find "$OUTDIR_TMP" -depth -type d -empty -delete 2>/dev/null || true
    [ ! -e "$OUTDIR_TMP" ] || rm -rf -- "$OUTDIR_TMP"
    OUTDIR_DONE=1
    trap - EXIT
    return 0
}

outdir_file_check() {   # outdir_file_check TOOL OPT PATH
    local dir
    dir=$(dirname -- "$3")
    [ -n "$3" ] || { echo "$1: $2: an empty file name" >&2; exit 2; }
    [ -d "$dir" ] || { echo "$1: $2: folder '$dir' does not exist" >&2; exit 2; }
    if [ -L "$3" ]; then
        echo "$1: $2: '$3' is a symbolic link: give the file itself" >&2; exit 2
    elif [ -e "$3" ] && [ ! -f "$3" ]; then
        echo "$1: $2: '$3' exists and is not a regular file" >&2; exit 2
    fi
    return 0
}

outdir_publish_file() {   # outdir_publish_file TOOL TMPFILE PATH
    if [ -L "$3" ] || { [ -e "$3" ] && [ ! -f "$3" ]; }; then
        rm -f -- "$2"
        echo "$1: '$3' exists and is not a regular file: not replaced" >&2
        exit 2
    fi
    mv -f -T -- "$2" "$3"
}

outdir_list() {   # outdir_list VAR TOOL OPT TEXT num|name
    local res rc
    res=$(awk -v text="$4" -v kind="$5" -v tool="$2" -v opt="$3" 'BEGIN {
        num = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$"
        if (text == "") { printf "%s: %s: an empty list\n", tool, opt > "/dev/stderr"; exit 2 }
        n = split(text, a, ",")
        for (i = 1; i <= n; i++) {
            if (a[i] == "") { printf "%s: %s: an empty item in '\''%s'\''\n", tool, opt, text > "/dev/stderr"; exit 2 }
            if (kind == "num" && a[i] !~ num) { printf "%s: %s: '\''%s'\'' in '\''%s'\'' is not a number\n", tool, opt, a[i], text > "/dev/stderr"; exit 2 }
            k = (kind == "num") ? sprintf("%.17g", a[i] + 0) : a[i]
            if (k in seen) { printf "%s: %s: '\''%s'\'' is given twice in '\''%s'\''\n", tool, opt, a[i], text > "/dev/stderr"; exit 2 }
            seen[k] = 1
        }
        if (kind == "num") {
            sorted = 1
            for (i = 2; i <= n; i++) if (a[i] + 0 < a[i - 1] + 0) sorted = 0
            if (!sorted) {
                for (i = 2; i <= n; i++) { x = a[i]; for (j = i - 1; j >= 1 && a[j] + 0 > x + 0; j--) a[j + 1] = a[j]; a[j + 1] = x }
                printf "%s: note: %s: '\''%s'\'' taken in ascending order\n", tool, opt, text > "/dev/stderr"
            }
        }
        for (i = 1; i <= n; i++) printf "%s%s", (i > 1 ? "," : ""), a[i]
        print "" }') || { rc=$?; [ "$rc" = 2 ] && exit 2; echo "$2: $3: cannot read '$4'" >&2; exit 2; }
    printf -v "$1" '%s' "$res"
}
