#!/usr/bin/env bash
# The figures of the library's structure (docs/architecture.md): each module's shared
# library with its size and the shared libraries it needs (readelf -d), the umbrella
# library, the public headers' lengths and the longest function.
#   scripts/library-figures.sh [BUILD_DIR]      default: build
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
printf '%-34s %9s  %s\n' library bytes needs
for so in "$build"/libshitsukan*.so; do
    real=$(readlink -f "$so")
    needs=$(readelf -d "$real" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' |
        sed 's/\.so.*//; s/^lib//' | tr '\n' ' ')
    printf '%-34s %9d  %s\n' "$(basename "$so")" "$(stat -c %s "$real")" "$needs"
done
echo
echo "public headers (lines):"
wc -l "$root"/include/shitsukan/*.h | sort -rn | sed "s#$root/##" | head -8
echo
bash "$root/tests/lint/function_length.sh" "$root" 2>&1 | tail -1 || true
