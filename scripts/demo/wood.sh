#!/usr/bin/env bash
# Wood demonstrations of Kawai 2000: the paper's Figs. 5, 6, 7 and 9 regenerated from
# their presets, each laid out as a contact sheet like the paper's; the rings'
# fluctuation R(t, theta) (sec. 4.4); the brightness shift added (the paper) and
# multiplied; knots and oak's broad rays (beyond the paper); species cuts (end grain,
# flat-sawn, quarter-sawn) with the maps a renderer takes; a light sweep over the
# figured board of Fig. 9. Writes into $OUT/wood/.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
out="$OUT/wood"
mkdir -p "$out/figures" "$out/species" "$out/maps" "$out/beyond"
size=512

cut() { "$SK" wood cut -q --size "$size" "$@"; }

# Fig. 5 and Fig. 6: vessels under straight, spiral (g1 = 0.12) and wavy (lambda = 40 mm,
# A = 0.20) grain, diffuse- and ring-porous, black where a point lies in a vessel.
for fig in 5 6; do
  for panel in a b c; do
    cut --preset "fig$fig$panel" -o "$out/figures/fig$fig$panel.png"
  done
done
"$SK" sheet "$out/figures/fig5a.png" "$out/figures/fig5b.png" "$out/figures/fig5c.png" \
  --label "a. straight grain" --label "b. spiral grain" --label "c. wavy grain" --columns 3 \
  --border 1 --title "Fig. 5  Diffuse-porous wood depending on grain" -o "$out/fig5.png"
"$SK" sheet "$out/figures/fig6a.png" "$out/figures/fig6b.png" "$out/figures/fig6c.png" \
  --label "a. straight grain" --label "b. spiral grain" --label "c. wavy grain" --columns 3 \
  --border 1 --title "Fig. 6  Ring-porous wood depending on grain" -o "$out/fig6.png"

# Fig. 7: the end-grain array C'(t, theta) (rings + 40 % brightness shift) and the texture
# it gives through wavy grain (lambda = 15 mm, A = 0.15).
cut --preset fig7 --plane end --distance 0 --width-mm 80 -o "$out/figures/fig7a.png"
cut --preset fig7 -o "$out/figures/fig7b.png"
"$SK" sheet "$out/figures/fig7a.png" "$out/figures/fig7b.png" \
  --label "cross section (end grain)" --label "generated texture" --columns 2 \
  --title "Fig. 7  Cross section and generated texture" -o "$out/fig7.png"

# The brightness shift of Fig. 7 added to the cells' brightness (the paper, sec. 6.3) and
# the darkening product (shift_mode multiply), on the same board.
cut --preset fig7 --set fibre.shift_mode=multiply -o "$out/figures/fig7b-multiply.png"
"$SK" sheet "$out/figures/fig7b.png" "$out/figures/fig7b-multiply.png" \
  --label "added: brightness + [-20 %, +20 %]" --label "multiplied: x [0.6, 1]" --columns 2 \
  --title "The brightness shift (40 %) added, as in the paper, and multiplied" -o "$out/shift.png"

# The rings' fluctuation R(t, theta) (sec. 4.4): lobed rings on the end grain, the ring-
# porous pores placed through R, irregular arches on a flat-sawn face.
cut --preset ring-fluctuation -o "$out/figures/rings-end.png"
cut --preset ring-fluctuation --width-mm 20 --distance 30 -o "$out/figures/rings-pores.png"
cut --preset ring-fluctuation --plane flat --distance 35 --tilt 3 --width-mm 100 \
  -o "$out/figures/rings-flat.png"
"$SK" sheet "$out/figures/rings-end.png" "$out/figures/rings-pores.png" "$out/figures/rings-flat.png" \
  --label "end grain, 120 mm" --label "pores through R, 20 mm" --label "flat-sawn, 100 mm" \
  --columns 3 --title "Ring fluctuation R(t, theta): preset ring-fluctuation" -o "$out/rings.png"

# Fig. 9: eq. (4) on a quarter-sawn face of wavy grain (lambda = 20 mm, A = 0.15), view
# along the normal, 30 % specular, the light at +7.2, 0 and -7.2 degrees.
cut --preset fig9 --light-deg 7.2 -o "$out/figures/fig9a.png"
cut --preset fig9 --light-deg 0 -o "$out/figures/fig9b.png"
cut --preset fig9 --light-deg -7.2 -o "$out/figures/fig9c.png"
"$SK" sheet "$out/figures/fig9a.png" "$out/figures/fig9b.png" "$out/figures/fig9c.png" \
  --label "a. delta = 7.2 deg" --label "b. delta = 0.0 deg" --label "c. delta = -7.2 deg" \
  --columns 3 --title "Fig. 9  Generated moving reflection" -o "$out/fig9.png"

# Knots (branches as cones from the pith, the grain flowing round them): boards of pine
# and Douglas-fir as their presets cut them, a close-up of a pine knot with its fibre
# map, a section along a branch from the pith (the sound knot's cone, the dead knot, the
# overgrown stub) and the end grain at a whorl.
cut --preset pine -o "$out/beyond/knots-pine.png"
cut --preset douglas-fir -o "$out/beyond/knots-douglas-fir.png"
"$SK" wood cut -q --size "$size" --preset pine --point 33,170,30 --normal 0,0,1 --axis 1,0,0 \
  --width-mm 40 --maps "$out/beyond/knot-maps" -o "$out/beyond/knot-close.png"
"$SK" wood cut -q --preset pine --size 768x384 --point 60,160,54 --normal -0.67,0,0.74 --axis 0.74,0,0.67 \
  --width-mm 160 -o "$out/beyond/knot-branch.png"
cut --preset pine --plane end --height 160 --distance 0 --width-mm 160 -o "$out/beyond/knot-whorl.png"
"$SK" sheet "$out/beyond/knots-pine.png" "$out/beyond/knots-douglas-fir.png" \
  "$out/beyond/knot-close.png" "$out/beyond/knot-maps/fibre.png" \
  --label "pine, flat-sawn" --label "Douglas-fir, flat-sawn" --label "a pine knot, 40 mm" \
  --label "its fibre map" --columns 4 --title "Knots: the grain flows round them" -o "$out/knots.png"
"$SK" sheet "$out/beyond/knot-branch.png" "$out/beyond/knot-whorl.png" --tile-size 384 \
  --label "along a branch from the pith: sound knot, dead knot, stub" --label "end grain at a whorl" \
  --columns 2 -o "$out/knots-section.png"

# Oak's broad rays: a board sawn 1.2 mm off the radial plane (the silver figure), a
# flat-sawn face and the end grain.
"$SK" wood cut -q --size "$size" --preset oak --point 80,0,1.2 --normal 0,0,1 --axis 1,0,0 \
  --width-mm 100 --light-deg 5 -o "$out/beyond/rays-quarter.png"
cut --preset oak -o "$out/beyond/rays-flat.png"
cut --preset oak --plane end --distance 60 --width-mm 25 -o "$out/beyond/rays-end.png"
"$SK" sheet "$out/beyond/rays-quarter.png" "$out/beyond/rays-flat.png" "$out/beyond/rays-end.png" \
  --label "quarter-sawn (1.2 mm off radial)" --label "flat-sawn" --label "end grain, 25 mm" \
  --columns 3 --title "Oak's broad rays" -o "$out/rays.png"

# Species: end grain, flat-sawn and quarter-sawn cuts in physical units, one sheet each,
# and one sheet of all species as preset.
species="oak ash maple birch cherry douglas-fir pine"
all=()
for s in $species; do
  cut --preset "$s" --plane end --distance 60 --width-mm 25 -o "$out/species/$s-end.png"
  cut --preset "$s" --plane flat -o "$out/species/$s-flat.png"
  cut --preset "$s" --plane quarter --light-deg 25 -o "$out/species/$s-quarter.png"
  cut --preset "$s" -o "$out/species/$s.png"
  "$SK" sheet "$out/species/$s-end.png" "$out/species/$s-flat.png" "$out/species/$s-quarter.png" \
    --label "end grain, 25 mm" --label "flat-sawn, 100 mm" --label "quarter-sawn, 100 mm" \
    --columns 3 --title "$s" -o "$out/species-$s.png"
  all+=("$out/species/$s.png" --label "$s")
done
"$SK" sheet "${all[@]}" --columns 4 --tile-size 384 --title "Species presets" -o "$out/species.png"

# Maps a renderer takes (albedo, fibre direction, pores) for an oak board and figured maple.
for s in oak maple; do
  "$SK" wood cut -q --preset "$s" --size 1024 --maps "$out/maps/$s" -o "$out/maps/$s/shaded.png"
done

# A short light sweep over the figured board of Fig. 9: 12 frames from -20 to +20 degrees.
"$SK" wood sweep -q --preset fig9 --size 256 --frames 12 -o "$out/sweep-fig9"
frames=()
for f in "$out"/sweep-fig9/frame_*.png; do frames+=("$f"); done
labels=()
for i in $(seq 0 11); do
  labels+=(--label "$(awk -v i="$i" 'BEGIN { printf "%.1f deg", -20 + 40 * i / 11 }')")
done
"$SK" sheet "${frames[@]}" "${labels[@]}" --columns 6 --title "Fig. 9 board, light swept" \
  -o "$out/sweep-fig9.png"
