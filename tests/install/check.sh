#!/usr/bin/env bash
# Installs a build into a temporary prefix, then builds and runs a consumer program with
# find_package(shitsukan) (shared and static) and with pkg-config.
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$source/tests/install" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib" "$work/consumer/consumer_shared" | grep -q "^0\."
"$work/consumer/consumer_static" | grep -q "^0\."
LD_LIBRARY_PATH="$work/prefix/lib" "$work/consumer/consumer_skin" | grep -q "^skin heights"
pcdir=$(dirname "$(find "$work/prefix" -name shitsukan.pc | head -n 1)")
flags=$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs shitsukan)
# shellcheck disable=SC2086
cc "$source/tests/install/consumer.c" $flags -o "$work/consumer_pc"
LD_LIBRARY_PATH="$work/prefix/lib" "$work/consumer_pc" | grep -q "^0\."
"$work/prefix/bin/shitsukan" presets noise | grep -q clouds

# A skin-only program against the installed shitsukan-skin module: it runs, and neither it
# nor any shared library it loads (readelf -d, followed through the closure) needs Embree,
# TBB, GLib, libsmf or LAPACK.
libdir=$(dirname "$(find "$work/prefix" -name 'libshitsukan-skin.so' | head -n 1)")
skin_flags=$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs shitsukan-skin)
# shellcheck disable=SC2086
cc "$source/tests/install/skin_only.c" $skin_flags -o "$work/skin_only"
LD_LIBRARY_PATH="$libdir" "$work/skin_only" | grep -q "^skin heights"
needed_closure() { # the NEEDED entries of a file and, recursively, of the libraries it names
    local seen=" " queue=("$1") f lib path
    while [ ${#queue[@]} -gt 0 ]; do
        f=${queue[0]}; queue=("${queue[@]:1}")
        for lib in $(readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
            case "$seen" in *" $lib "*) continue ;; esac
            seen="$seen$lib "
            echo "$lib"
            path="$libdir/$lib"
            [ -f "$path" ] || path=$(ldconfig -p | awk -v l="$lib" '$1 == l { print $NF; exit }')
            [ -n "$path" ] && [ -f "$path" ] && queue+=("$path")
        done
    done
}
closure=$(needed_closure "$work/skin_only")
if grep -Ei 'embree|tbb|glib|smf|lapack|blas' <<<"$closure"; then
    echo "install check: the skin-only program needs the libraries above" >&2
    exit 1
fi
direct=$(readelf -d "$work/skin_only" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
echo "skin-only program: needs $direct(closure: $(echo $closure | tr '\n' ' '))"
echo "install check passed"
