# outdir.sh - sourced by the validation scripts: an output folder that appears
# whole or not at all.
#   outdir_begin NAME OUT   check that OUT's parent exists (else exit 2 with a
#                           message of NAME.sh), make the temporary folder $tmp
#                           beside OUT, removed on exit unless committed (or
#                           kept for a look when KEEP_TMP is set)
#   outdir_commit OUT       replace OUT by $tmp (mode 755)
outdir_begin() {
    local parent
    parent=$(dirname -- "$2")
    [ -d "$parent" ] || { echo "$1.sh: --out: parent folder '$parent' does not exist" >&2; exit 2; }
    tmp=$(mktemp -d "$parent/.$1.XXXXXX")
    trap '[ -n "${KEEP_TMP:-}" ] || rm -rf -- "$tmp"' EXIT
}
outdir_commit() {
    chmod 755 "$tmp"
    rm -rf -- "$1"
    mv -- "$tmp" "$1"
    trap - EXIT
}
