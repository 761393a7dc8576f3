#!/usr/bin/env bash
# The main job as `make demo` runs it (scripts/demo.sh: every module's figures and the
# showcase), into a fresh folder: it must finish, and each module's outputs must be there
# and not empty, so a command the demo calls cannot break unnoticed.
#
#   tests/demo/run.sh SHITSUKAN_BINARY SOURCE_DIR OUT_DIR
set -euo pipefail
bin=$1
root=$2
out=$3
rm -rf "$out"
bash "$root/scripts/demo.sh" "$bin" "$out"
# one picture or file per module that its part of the demo writes last or that a reader
# of the docs looks at first
expect=(
  core/noise-sheet.png
  hand/hand.glb
  hand/fig4.17-poses.png
  render/piano.png
  showcase/still.png
  skin/fig19-sheet.png
  skin/back-of-hand-maps/furrow.png
  tissue/curl/skin.glb
  wood/fig9.png
  wood/maps/oak/shaded.png
  wood/maps/maple/albedo.png
)
missing=0
for f in "${expect[@]}"; do
  if [ ! -s "$out/$f" ]; then
    echo "demo: $f is missing or empty"
    missing=1
  fi
done
# no staged or temporary output left behind
left=$(find "$out" \( -name '*.part*' -o -name '*.tmp' \) | head -n 5)
if [ -n "$left" ]; then
  echo "demo: staged files left behind: $left"
  missing=1
fi
[ "$missing" = 0 ] && echo "demo: every expected output is there ($(find "$out" -type f | wc -l) files)"
exit "$missing"
