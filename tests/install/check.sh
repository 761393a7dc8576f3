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
pcdir=$(dirname "$(find "$work/prefix" -name shitsukan.pc | head -n 1)")
flags=$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs shitsukan)
# shellcheck disable=SC2086
cc "$source/tests/install/consumer.c" $flags -o "$work/consumer_pc"
LD_LIBRARY_PATH="$work/prefix/lib" "$work/consumer_pc" | grep -q "^0\."
"$work/prefix/bin/shitsukan" presets noise | grep -q clouds
echo "install check passed"
