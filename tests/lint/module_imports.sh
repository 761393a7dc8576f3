#!/usr/bin/env bash
# What the shared libraries of one layer import from outside the project, read from their
# dynamic symbol tables (nm -D --undefined-only): none may import a name that matches
# FORBIDDEN (an extended regular expression). The layer's modules are those whose folder
# in cmake/modules.cmake starts with LAYER/. Usage:
#   module_imports.sh ROOT BUILD LAYER WHAT FORBIDDEN
# models_do_no_io.sh and products_start_no_program.sh call it with their rules.
set -euo pipefail
root=${1:?} build=${2:?} layer=${3:?} what=${4:?} forbidden=${5:?}
mods=$(sed -n "s/^sk_module(\([a-z-]*\) DIR $layer\/.*/\1/p" "$root/cmake/modules.cmake")
[ -n "$mods" ] || { echo "$layer: no modules in cmake/modules.cmake" >&2; exit 1; }
bad=0 n=0
for m in $mods; do
    lib="$build/libshitsukan-$m.so"
    [ -f "$lib" ] || { echo "$layer: $lib is not built" >&2; bad=1; continue; }
    n=$((n + 1))
    hits=$(nm -D --undefined-only "$lib" | awk '{print $NF}' | sed 's/@.*//' | grep -E "^($forbidden)\$" || true)
    if [ -n "$hits" ]; then
        echo "$layer: libshitsukan-$m imports $(echo $hits | tr '\n' ' ')(it must not: they $what)" >&2
        bad=1
    fi
done
[ $bad -eq 0 ] && echo "$layer: the $n libraries ($(echo $mods)) import none of the calls they must not make: they $what"
exit $bad
