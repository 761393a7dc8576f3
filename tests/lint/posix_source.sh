#!/usr/bin/env bash
# Every source that uses a POSIX name (PATH_MAX, strdup, fileno, ...) must ask for POSIX
# with _POSIX_C_SOURCE (or _XOPEN_SOURCE, _GNU_SOURCE) before its first include: gcc gets them through
# -fopenmp anyway, so only the clang builds (make fuzz) would fail. Usage: posix_source.sh ROOT
set -euo pipefail
root=${1:?usage: posix_source.sh ROOT}
names='PATH_MAX|NAME_MAX|\bstrdup\(|\bstrndup\(|\bfileno\(|\breadlink\(|\blstat\(|\bmkstemp\(|\bnewlocale\('
bad=0
while IFS= read -r f; do
    first_include=$(grep -n '^#include' "$f" | head -1 | cut -d: -f1)
    [ -n "$first_include" ] || continue
    if ! head -n "$first_include" "$f" | grep -q '_POSIX_C_SOURCE\|_XOPEN_SOURCE\|_GNU_SOURCE'; then
        # a file whose first include is a private header that defines it counts too
        echo "$f: uses POSIX names without _POSIX_C_SOURCE before its first include" >&2
        bad=1
    fi
done < <(grep -rlE "$names" "$root/src" "$root/tools" --include='*.c' | grep -v '_test\.c$')
[ $bad -eq 0 ] && echo "posix_source: every source asks for POSIX where it uses it"
exit $bad
