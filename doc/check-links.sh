#!/bin/sh
# doc/check-links.sh [ROOT]: every relative markdown link [t](path[#anchor]) of ROOT/README.md and
# ROOT/doc/**/*.md (outside code fences) must name an existing file, and an anchor must be
# a heading's GitHub slug in that file. Prints each broken link; exit 1 if any.
root=${1:-.}; cd "$root" || exit 2
slugs() { # file -> its heading slugs, one a line (GitHub: lower case, punctuation dropped, spaces -> -)
  awk '/^```/{f=!f;next} !f && /^#+ /{sub(/^#+ +/,""); s=tolower($0); gsub(/[][!"#$%&'"'"'()*+,.\/:;<=>?@\\^`{|}~]/,"",s); gsub(/ /,"-",s); n[s]++; if(n[s]>1) print s "-" n[s]-1; else print s}' "$1"
}
bad=0; n=0
for f in README.md $(find doc -name '*.md' | sort); do
  dir=$(dirname "$f")
  awk '/^```/{f=!f;next} !f{ line=$0; while (match(line,/\]\([^) ]+\)/)) { print NR "\t" substr(line,RSTART+2,RLENGTH-3); line=substr(line,RSTART+RLENGTH) } }' "$f" |
  while IFS="$(printf '\t')" read -r ln target; do
    case $target in http://*|https://*|mailto:*) continue;; esac
    path=${target%%#*}; anchor=; case $target in *#*) anchor=${target#*#};; esac
    if [ -z "$path" ]; then tf=$f; else tf=$dir/$path; fi
    if [ ! -e "$tf" ]; then echo "$f:$ln: missing file: $target"; continue; fi
    if [ -n "$anchor" ]; then
      case $tf in *.md) slugs "$tf" | grep -qxF -- "$anchor" || echo "$f:$ln: missing anchor: $target";; esac
    fi
  done
done > "${TMPDIR:-/tmp}/check-links.$$"
total=$(for f in README.md $(find doc -name '*.md'); do awk '/^```/{f=!f;next} !f{ line=$0; while (match(line,/\]\([^) ]+\)/)) { c++; line=substr(line,RSTART+RLENGTH) } } END{print c+0}' "$f"; done | awk '{s+=$1} END{print s}')
cat "${TMPDIR:-/tmp}/check-links.$$"
echo "links checked: $total, broken: $(wc -l < "${TMPDIR:-/tmp}/check-links.$$")"
if [ -s "${TMPDIR:-/tmp}/check-links.$$" ]; then rm -f "${TMPDIR:-/tmp}/check-links.$$"; exit 1; fi; rm -f "${TMPDIR:-/tmp}/check-links.$$"
