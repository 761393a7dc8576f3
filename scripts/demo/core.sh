#!/usr/bin/env bash
# Demo part of the core: tileable noise maps and a 2x2 repeat that shows they have no seam.
set -euo pipefail
out="$OUT/core"
mkdir -p "$out"
for preset in clouds grain; do
  "$SK" noise --preset "$preset" --size 512 --quiet -o "$out/noise-$preset.png"
  "$SK" noise --preset "$preset" --size 512 --quiet -o "$out/noise-$preset.exr"
  "$SK" sheet --repeat 2x2 "$out/noise-$preset.png" -o "$out/noise-$preset-tiled-2x2.png"
done
"$SK" sheet --title "Noise presets" --label "(a) clouds" "$out/noise-clouds.png" \
  --label "(b) grain" "$out/noise-grain.png" -o "$out/noise-sheet.png"
