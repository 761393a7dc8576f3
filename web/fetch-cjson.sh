#!/usr/bin/env bash
# Fetches Debian's cJSON source package (bookworm, with Debian's patches applied) into
# DIR for the WebAssembly build, which has no cJSON library to link. Uses a private
# package list in DIR: the system's apt sources are not touched. Nothing fetched here
# belongs in the repository.
#
#   web/fetch-cjson.sh DIR      -> DIR/include/cjson/cJSON.h, DIR/cJSON.c
set -eu
dir=$1
if [ -f "$dir/cJSON.c" ] && [ -f "$dir/include/cjson/cJSON.h" ]; then exit 0; fi
mkdir -p "$dir/apt/sources" "$dir/apt/lists/partial" "$dir/src"
dir=$(cd "$dir" && pwd)
echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main" \
  > "$dir/apt/sources/bookworm-src.list"
apt_opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$dir/apt/sources"
          -o "Dir::State::Lists=$dir/apt/lists" -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=)
echo "fetch-cjson: Debian source package cjson (bookworm)"
apt-get -q "${apt_opts[@]}" update >/dev/null
(cd "$dir/src" && apt-get -q "${apt_opts[@]}" source cjson >/dev/null 2>&1)
tree=$(ls -d "$dir"/src/cjson-*/ | head -n 1)
mkdir -p "$dir/include/cjson"
cp "$tree/cJSON.c" "$dir/cJSON.c"
cp "$tree/cJSON.h" "$dir/include/cjson/cJSON.h"
cp "$tree/LICENSE" "$dir/LICENSE"
echo "fetch-cjson: $(basename "$tree") in $dir"
