#!/usr/bin/env bash
# function-lengths.sh - the length of every function in the project's C and C++
# sources, longest first, as Universal Ctags sees them (first line of the
# definition to its closing brace, comments and blank lines included).
#
# Usage: etc/function-lengths.sh [--help] [--over N] [FOLDER...]
#
#   --over N   list only the functions longer than N lines (default 100; a whole
#              number from 0)
#   FOLDER     folders of the repository to read (default: regime wallmodel tools
#              applications common validation); the files git tracks below them
#              with the endings .c .h .C .H
#
# Prints one line per function: LINES FILE:LINE NAME. The house rule is that no
# function in regime/, wallmodel/, tools/ or applications/ is over 150 lines;
# tests/style/test_function_length.sh holds the code to it.
# Exit status: 0 listed (also when nothing is over N), 1 Universal Ctags
# (Debian's universal-ctags) or git missing, 2 bad usage.
set -euo pipefail
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
die() { echo "function-lengths.sh: $1" >&2; exit "${2:-2}"; }
over=100
folders=()
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) usage; exit 0 ;;
        --over) [[ ${2:-} =~ ^[0-9]{1,6}$ ]] || die "--over needs a whole number of lines, got '${2:-}'"; over=$2; shift ;;
        -*) die "unknown option '$1' (see --help)" ;;
        *) folders+=("$1") ;;
    esac
    shift
done
[ ${#folders[@]} -gt 0 ] || folders=(regime wallmodel tools applications common validation)
top=$(cd "$(dirname "$0")/.." && pwd)
command -v git > /dev/null || die "git not found" 1
ctags=
for c in ctags-universal universal-ctags ctags; do
    if command -v "$c" > /dev/null && "$c" --version 2>/dev/null | grep -q '^Universal Ctags'; then ctags=$c; break; fi
done
[ -n "$ctags" ] || die "Universal Ctags not found (Debian: apt-get install universal-ctags)" 1
cd "$top"
for f in "${folders[@]}"; do
    [ -d "$f" ] || die "'$f' is not a folder of the repository ($top)"
done
pats=()
for f in "${folders[@]}"; do pats+=("${f%/}/*.c" "${f%/}/*.h" "${f%/}/*.C" "${f%/}/*.H"); done
git ls-files -z -- "${pats[@]}" |
    xargs -0 -r "$ctags" -f - --fields=+ne --kinds-C=f --kinds-C++=f --langmap=C++:+.C.H --langmap=C:.c.h |
    awk -F'\t' -v over="$over" '{
        l = ""; e = ""
        for (i = 4; i <= NF; i++) {
            if ($i ~ /^line:/) l = substr($i, 6)
            if ($i ~ /^end:/) e = substr($i, 5)
        }
        if (l != "" && e != "" && e - l + 1 > over + 0) printf "%d %s:%d %s\n", e - l + 1, $2, l, $1
    }' | sort -k1,1nr -k2,2
