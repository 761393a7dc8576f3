#!/usr/bin/env bash
# Writes the docs' key tables from the schemas: every block of docs/*.md between
#   <!-- keys: COMMAND -->  and  <!-- end keys -->
# becomes the output of `shitsukan COMMAND --help-keys=markdown` (tests/test_schema.c checks
# that the docs hold exactly that, so a key's range and default are stated once: in its
# schema). Usage: scripts/docs-keys.sh SHITSUKAN_BINARY
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: scripts/docs-keys.sh SHITSUKAN_BINARY" >&2; exit 2; }
sk=$(realpath "$1")
cd "$(dirname "$0")/.."
for doc in docs/*.md; do
  grep -q '^<!-- keys: ' "$doc" || continue
  tmp=$(mktemp)
  skip=0
  while IFS= read -r line; do
    if [[ $line =~ ^\<\!--\ keys:\ (.*)\ --\>$ ]]; then
      printf '%s\n' "$line" >> "$tmp"
      read -r -a words <<< "${BASH_REMATCH[1]}"
      "$sk" "${words[@]}" --help-keys=markdown >> "$tmp"
      skip=1
    elif [ "$line" = "<!-- end keys -->" ]; then
      printf '%s\n' "$line" >> "$tmp"
      skip=0
    elif [ $skip -eq 0 ]; then
      printf '%s\n' "$line" >> "$tmp"
    fi
  done < "$doc"
  mv "$tmp" "$doc"
done
