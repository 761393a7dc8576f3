#!/usr/bin/env bash
# Demo part of the skin module: every row of Table 1 of Ishii et al. 1991 (Figs. 13-19)
# at the paper's 400 x 400, one contact sheet per figure laid out like the paper's (with
# zoomed views for Figs. 14 and 18 and the whole tiles of Figs. 19(d)-(f)), the two normal
# models side by side, the real-region presets, and a seamless 2048 map set with 2 x 2
# repeats.
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
# Each figure at the paper's 400 x 400 with 3 x 3 samples a pixel, so the finest level's
# furrows (about 5 pixels apart) are resolved rather than aliased. Figs. 19(d)-(f) hold
# whole stretched cells on tiles 80, 60 and 20 mm long: their panels are the paper's
# 10 mm view (the first 400 pixels at the other figures' 0.025 mm a pixel), and
# fig19-tiles.png shows the whole tiles.
declare -A long=([19d]=3200x400 [19e]=2400x400 [19f]=800x400)
samples=3

for fig in 13 14 15 16 17 18 19; do
  sheet_args=()
  letters=${rows[$fig]}
  for ((i = 0; i < ${#letters}; i++)); do
    l=${letters:$i:1}
    size=400 region=()
    if [ -n "${long[$fig$l]:-}" ]; then size=${long[$fig$l]} region=(--region 0,0,400,400); fi
    "$SK" skin --preset "fig$fig$l" --size "$size" "${region[@]}" --samples $samples --quiet \
      -o "$out/fig$fig$l.png"
    sheet_args+=(--label "($l)" "$out/fig$fig$l.png")
  done
  # Figs. 14 (roundness: the contours of one cell) and 18 (levels: the finest ridges) make
  # their point in detail: a second row zooms 4 x into the middle of each panel.
  if [ "$fig" = 14 ] || [ "$fig" = 18 ]; then
    for ((i = 0; i < ${#letters}; i++)); do
      l=${letters:$i:1}
      "$SK" skin --preset "fig$fig$l" --size 1600 --region 600,600,400,400 --samples 2 --quiet \
        -o "$out/fig$fig$l-zoom.png"
      sheet_args+=(--label "($l) 4 x" "$out/fig$fig$l-zoom.png")
    done
  fi
  "$SK" sheet --title "${titles[$fig]}" --columns 3 "${sheet_args[@]}" -o "$out/fig$fig-sheet.png"
done
tiles=()
for l in d e f; do
  "$SK" skin --preset "fig19$l" --size "${long[19$l]}" --samples 2 --quiet -o "$out/fig19$l-tile.png"
  tiles+=(--label "($l) the whole ${long[19$l]%x*}-pixel tile" "$out/fig19$l-tile.png")
done
"$SK" sheet --title "Fig. 19(d)-(f): whole tiles, every level-1 cell whole" --columns 1 \
  --tile-size 1200 "${tiles[@]}" -o "$out/fig19-tiles.png"

# The two normal models on Fig. 13(c): the paper's (profile) and the height's gradient.
"$SK" skin --preset fig13c --samples $samples --quiet -o "$out/normals-profile.png"
"$SK" skin --preset fig13c --set normal_model=gradient --samples $samples --quiet \
  -o "$out/normals-gradient.png"
"$SK" sheet --title "Normals: the paper's profile model and the height's gradient" --columns 2 \
  --label "profile (Fig. 7; figure presets)" "$out/normals-profile.png" \
  --label "gradient (maps; region presets)" "$out/normals-gradient.png" -o "$out/normals-sheet.png"

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
