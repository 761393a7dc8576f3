#!/usr/bin/env bash
# Every C source and header is as `.clang-format` lays it out (one line width: 100
# columns). Usage: format.sh ROOT. Fix a failure with:
#   clang-format -i $(git ls-files '*.c' '*.h' '*.cpp')
# Skipped (exit 77) when clang-format is absent; scripts/deps.sh test installs it.
set -euo pipefail
root=${1:?usage: format.sh ROOT}
if ! command -v clang-format >/dev/null 2>&1; then
    echo "format: clang-format is not installed (scripts/deps.sh test installs it): skipped"
    exit 77
fi
cd "$root"
mapfile -t files < <(find src include tools tests bench fuzz web/wasm python \
    \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -type f 2>/dev/null | sort)
if ! clang-format --dry-run -Werror "${files[@]}" 2>/tmp/sk-format.$$; then
    grep -oE '^[^:]+:[0-9]+' /tmp/sk-format.$$ | sort -u | head -20 >&2
    echo "format: the files above differ from .clang-format's layout" >&2
    rm -f /tmp/sk-format.$$
    exit 1
fi
rm -f /tmp/sk-format.$$
# characters, not bytes: comments quote the papers in Japanese
long=$(perl -CSD -ne 'print "$ARGV:$.\n" if length($_) > 101; close ARGV if eof' "${files[@]}")
if [ -n "$long" ]; then
    echo "$long" | head -20 >&2
    echo "format: the lines above are over 100 columns (comments are not reflowed)" >&2
    exit 1
fi
echo "format: ${#files[@]} files as .clang-format lays them out, none over 100 columns"
