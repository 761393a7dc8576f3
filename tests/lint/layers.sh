#!/usr/bin/env bash
# Every #include of a library source names a header of its own module or of a module that
# cmake/modules.cmake lets it call: no include runs back up a layer or sideways to a module
# it does not name. (Calls are checked too: each module's shared library is linked with
# --no-undefined against only the modules it names.) Usage: layers.sh ROOT
set -euo pipefail
root=${1:?usage: layers.sh ROOT}
cd "$root"
# module -> folder, and module -> the modules it may call, from the table
table=$(awk '
    /^sk_module\(/ { collecting = 1; line = "" }
    collecting { line = line " " $0; if ($0 ~ /\)/) { collecting = 0; print line } }' cmake/modules.cmake |
    sed -E 's/sk_module\(//; s/\)//; s/ +/ /g')
declare -A dir_of allowed
while read -r name _ dir rest; do
    dir_of[$name]=$dir
    mods=$(sed -E 's/.*MODULES ([^A-Z]*).*/\1/; t; s/.*//' <<<"$rest")
    allowed[$dir]=" $dir "
    for m in $mods; do allowed[$dir]+="${m} "; done
done <<<"$table"
# the modules' names -> folders in each allowed list
for d in "${!allowed[@]}"; do
    list=" $d "
    for m in ${allowed[$d]}; do [ -n "${dir_of[$m]:-}" ] && list+="${dir_of[$m]} "; done
    allowed[$d]=$list
done
bad=0 checked=0
while IFS= read -r f; do
    dir=$(dirname "${f#src/}")
    [ -n "${allowed[$dir]:-}" ] || { echo "layers: $f is in no module of cmake/modules.cmake" >&2; bad=1; continue; }
    while IFS= read -r inc; do
        checked=$((checked + 1))
        target=$(dirname "$inc")
        case "${allowed[$dir]}" in *" $target "*) ;; *)
            echo "layers: $f includes \"$inc\": module folder $target is not one $dir may call" >&2
            bad=1 ;;
        esac
    done < <(sed -n 's/^#include "\([^"]*\/[^"]*\)".*/\1/p' "$f" | grep -v '^shitsukan/')
done < <(find src -name '*.c' -o -name '*.h' -o -name '*.cpp' | sort)
[ $bad -eq 0 ] && echo "layers: $checked includes of internal headers, each within its module's allowed layers"
exit $bad
