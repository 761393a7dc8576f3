#!/usr/bin/env bash
# Blender's Mesh Cache modifier plays the point cache of a tissue run on its rest mesh
# (tests/tissue/blender_pc2.py). Skips (77) when Blender is not installed.
set -euo pipefail
sk=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v blender >/dev/null 2>&1; then
  echo "blender not found: skipping the Mesh Cache check"
  exit 77
fi
rm -rf "$out"
"$sk" tissue run --character arm --motion curl --fps 10 --frames 0:5 --obj-frames --no-glb -q \
  --set skin.spacing_mm=12 --set skin.dilation_radius_mm=18 -o "$out"
blender -b --factory-startup --python "$here/blender_pc2.py" -- "$out" 6 2>&1 | grep -E "^blender:|Error|differ" || true
blender -b --factory-startup --python "$here/blender_pc2.py" -- "$out" 6 >/dev/null 2>&1
