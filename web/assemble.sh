#!/usr/bin/env bash
# Assembles the studio's served folder BUILD/www from the page (web/www), the wasm build
# (BUILD/studio.mjs, studio.wasm), three.js from node_modules and the shipped presets,
# with an index of the presets per module.
#
#   web/assemble.sh SOURCE_ROOT BUILD_DIR
set -eu
root=$1
build=$2
www="$build/www"
mkdir -p "$www/wasm" "$www/three/addons/controls" "$www/presets"
cp -R "$root/web/www/." "$www/"
rm -f "$www/wasm/studio.js"
cp "$build/studio.mjs" "$build/studio.wasm" "$www/wasm/"
three="$root/node_modules/three"
if [ ! -f "$three/build/three.module.js" ]; then
  echo "assemble: error: $three is missing (scripts/deps.sh node installs it)" >&2
  exit 1
fi
cp "$three/build/three.module.js" "$three/build/three.core.js" "$www/three/" 2>/dev/null ||
  cp "$three/build/three.module.js" "$www/three/"
cp "$three/examples/jsm/controls/OrbitControls.js" "$www/three/addons/controls/"
cp "$three/LICENSE" "$www/three/LICENSE"
for module in skin wood hand; do
  rm -rf "$www/presets/$module"
  mkdir -p "$www/presets/$module"
  cp "$root/presets/$module"/*.json "$www/presets/$module/"
done
if [ -d "$root/presets/tissue" ]; then
  rm -rf "$www/presets/tissue"
  cp -R "$root/presets/tissue" "$www/presets/tissue"
fi
# presets/index.json: {"skin": ["back-of-hand", ...], ...}
{
  printf '{'
  first=1
  for module in skin wood hand tissue; do
    [ -d "$www/presets/$module" ] || continue
    [ $first = 1 ] || printf ','
    first=0
    printf '"%s":[' "$module"
    sep=
    for f in "$www/presets/$module"/*.json; do
      printf '%s"%s"' "$sep" "$(basename "$f" .json)"
      sep=,
    done
    printf ']'
  done
  printf '}\n'
} > "$www/presets/index.json"
echo "studio: $www"
