#!/usr/bin/env bash
# The scan-to-surface pipeline of Yasumuro's thesis (sec. 4.1) on the hand surface: the
# palm and back range scans of the cast, the registered clouds, the slices, the polygons
# (slice by slice as the thesis, and with the neighbouring slices), the 96 Bezier
# patches, the patches moving with their links, and Table 4.1 beside the thesis's
# figures. Writes $OUT/hand/scan/ (every file of `shitsukan hand scan`) and
# $OUT/hand/scan-sheet.png (the pictures on one sheet).
set -euo pipefail
: "${SK:?}" "${OUT:?}"
out="$OUT/hand/scan"
mkdir -p "$out"
"$SK" hand scan -q -o "$out"
s="$out"
"$SK" sheet -q --columns 3 --tile-size 640 --border 1 --text-scale 2 \
  --title "Yasumuro 2000, sec. 4.1: the scan-to-surface pipeline on the hand surface" \
  --label "palm scan (Fig. 4.3)" "$s/scan-palm.png" --label "back scan" "$s/scan-back.png" \
  --label "registered by the 9 markers" "$s/registered.png" \
  --label "slices and their points (Fig. 4.5)" "$s/slices.png" \
  --label "polygons, slice by slice (Fig. 4.7)" "$s/polygons-thesis.png" \
  --label "polygons with the neighbouring slices" "$s/polygons.png" \
  --label "96 Bezier patches (Fig. 4.10)" "$s/patches.png" \
  --label "patches moved with their links" "$s/patches-posed.png" \
  -o "$OUT/hand/scan-sheet.png"
cat "$out/table-4.1.txt"
