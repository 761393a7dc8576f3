#!/usr/bin/env bash
# Demo part of the skin module: every row of Table 1 of Ishii et al. 1991 (Figs. 13-19)
# at the paper's 400 x 400, one contact sheet per figure laid out like the paper's, the
# real-region presets, and a seamless 2048 map set with 2 x 2 repeats.
set -euo pipefail
out="$OUT/skin"
mkdir -p "$out"

declare -A titles=(
  [13]="Fig. 13  Changes in slope"
  [14]="Fig. 14  Changes in roundness"
  [15]="Fig. 15  Changes in centre-point distribution"
  [16]="Fig. 16  Changes in perturbation"
  [17]="Fig. 17  Changes in direction"
  [18]="Fig. 18  Changes in the number of hierarchical levels"
  [19]="Fig. 19  Examples of skin rendering")
declare -A rows=([13]=abc [14]=abc [15]=abc [16]=ab [17]=abc [18]=abc [19]=abcdef)

for fig in 13 14 15 16 17 18 19; do
  sheet_args=()
  letters=${rows[$fig]}
  for ((i = 0; i < ${#letters}; i++)); do
    l=${letters:$i:1}
    "$SK" skin --preset "fig$fig$l" --size 400 --quiet -o "$out/fig$fig$l.png"
    sheet_args+=(--label "($l)" "$out/fig$fig$l.png")
  done
  "$SK" sheet --title "${titles[$fig]}" --columns 3 "${sheet_args[@]}" -o "$out/fig$fig-sheet.png"
done

# Real regions, anti-aliased previews.
for region in back-of-hand wrist forearm; do
  "$SK" skin --preset "$region" --size 600 --samples 2 --quiet -o "$out/$region.png"
done
"$SK" sheet --title "Skin regions (published measurements)" --columns 3 \
  --label "back of the hand" "$out/back-of-hand.png" --label "wrist" "$out/wrist.png" \
  --label "forearm" "$out/forearm.png" -o "$out/regions-sheet.png"

# Showcase: a seamless map set a renderer takes, and 2 x 2 repeats that show no seam.
"$SK" skin maps --preset back-of-hand --size 2048 --edges --quiet -o "$out/back-of-hand-maps"
"$SK" sheet --repeat 2x2 "$out/back-of-hand-maps/preview.png" -o "$out/back-of-hand-preview-2x2.png"
"$SK" sheet --repeat 2x2 "$out/back-of-hand-maps/normal.png" -o "$out/back-of-hand-normal-2x2.png"
