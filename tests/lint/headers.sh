#!/usr/bin/env bash
# Every public header compiles on its own (C11 and C++) and is at most 800 lines.
# Usage: headers.sh ROOT
set -euo pipefail
root=${1:?usage: headers.sh ROOT}
cd "$root"
bad=0 longest=0 name=""
for h in include/shitsukan/*.h; do
    base=$(basename "$h")
    if ! echo "#include \"shitsukan/$base\"" | cc -std=c11 -fsyntax-only -Wall -Werror -Iinclude -x c - 2>&1; then
        echo "headers: $base does not compile on its own" >&2; bad=1
    fi
    if command -v c++ >/dev/null 2>&1 &&
       ! echo "#include \"shitsukan/$base\"" | c++ -fsyntax-only -Iinclude -x c++ - 2>&1; then
        echo "headers: $base does not compile as C++" >&2; bad=1
    fi
    n=$(wc -l < "$h")
    [ "$n" -gt "$longest" ] && longest=$n name=$base
    if [ "$n" -gt 800 ]; then echo "headers: $base is $n lines (at most 800: split it by concept)" >&2; bad=1; fi
done
[ $bad -eq 0 ] && echo "headers: each compiles on its own; the longest is $name, $longest lines"
exit $bad
