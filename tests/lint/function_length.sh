#!/usr/bin/env bash
# No function is over 150 lines, counted from its opening brace to its closing brace.
# The formatter puts a function's braces alone at column 0 (.clang-format), which is
# what this counts; tests/lint/format.sh checks that layout. Usage: function_length.sh ROOT
set -euo pipefail
root=${1:?usage: function_length.sh ROOT}
limit=150
cd "$root"
mapfile -t files < <(find src tools tests bench fuzz web/wasm python \
    \( -name '*.c' -o -name '*.cpp' \) -type f 2>/dev/null | sort)
report=$(awk -v limit=$limit '
    FNR == 1 { start = 0 }
    /^\{$/ { start = FNR; next }
    /^\}/ && start { n = FNR - start + 1; if (n > longest) { longest = n; where = FILENAME ":" start }
                     if (n > limit) print "long: " FILENAME ":" start ": " n " lines"; start = 0 }
    END { print "longest: " longest " lines at " where }' "${files[@]}")
if grep -q '^long:' <<<"$report"; then
    grep '^long:' <<<"$report" >&2
    echo "function_length: the functions above are over $limit lines: split them" >&2
    exit 1
fi
echo "function_length: every function is at most $limit lines; $(grep '^longest:' <<<"$report")"
