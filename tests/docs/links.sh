#!/usr/bin/env bash
# Every picture and page the README and docs/ link to exists in the repository (a link to
# a file that `make demo` writes into out/ is not a repository link and is not checked).
# Usage: links.sh SOURCE_DIR
set -euo pipefail
root=${1:?usage: links.sh SOURCE_DIR}
missing=0
for doc in "$root"/README.md "$root"/docs/*.md; do
  dir=$(dirname "$doc")
  # targets of Markdown links and images: ](target) with no scheme and no anchor-only link
  while IFS= read -r target; do
    target=${target%%#*}
    [ -n "$target" ] || continue
    case $target in
      http://* | https://* | mailto:* | out/* | ../out/*) continue ;;
    esac
    if [ ! -e "$dir/$target" ]; then
      echo "${doc#"$root"/}: links to $target, which does not exist"
      missing=$((missing + 1))
    fi
  done < <(grep -o '](\([^)]*\))' "$doc" | sed 's/^](\(.*\))$/\1/')
done
if [ "$missing" -gt 0 ]; then
  echo "$missing broken link(s)"
  exit 1
fi
echo "all links of README.md and docs/*.md resolve"
