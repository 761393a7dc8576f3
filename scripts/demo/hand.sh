#!/usr/bin/env bash
# Hand demonstrations of Yasumuro's thesis (sec. 4.2.3): drive only the little finger's
# MCP (Fig. 4.19) or DIP (Fig. 4.20), and piano key presses that drive two DOFs of one
# finger (Fig. 4.21); plus Table 3.2 as a constraint set and a calibration round trip.
# Writes into $OUT/hand/: BVH (Blender: File > Import > Motion Capture, scale 0.001), joint
# angles and positions of every frame, a joint-angle plot per demonstration, its
# stick-figure frames (dorsal and radial views) and a strip of key frames from both views,
# and a labelled picture of the skeleton.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
presets="$here/presets/hand"
out="$OUT/hand"
mkdir -p "$out"

# The angle (degrees) of DOF $2 at frame $3 in the angles CSV $1.
angle_at() {
  awk -F, -v dof="$2" -v frame="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == dof) c = i; next }
    $1 == frame { printf "%.0f", $c }' "$1"
}

# A strip of key frames: the dorsal views in the top row, the radial views below.
# strip DEMO TITLE FRAME:LABEL...
strip() {
  local demo=$1 title=$2
  shift 2
  local work="$out/.strip-$demo" args=() view key
  rm -rf "$work"
  for view in dorsal radial; do
    "$SK" hand animate "$presets/$demo.json" -q --bare --views "$view" --png-size 240x280 \
      --frames-dir "$work/$view"
    for key in "$@"; do
      args+=(--label "${key#*:}" "$work/$view/frame_$(printf %04d "${key%%:*}").png")
    done
  done
  "$SK" sheet --columns $# --title "$title" "${args[@]}" -o "$out/$demo-strip.png"
  rm -rf "$work"
}

# FRAME:LABEL for frames of a pinned demonstration, labelled with the pinned angle.
keys_with_angle() {
  local csv=$1 dof=$2 f
  shift 2
  for f in "$@"; do echo "$f:frame $f, $(angle_at "$csv" "$dof" "$f") deg"; done
}

for demo in little-mcp little-dip piano-key; do
  "$SK" hand animate "$presets/$demo.json" -q \
    --bvh "$out/$demo.bvh" --angles "$out/$demo-angles.csv" --positions "$out/$demo-positions.csv" \
    --frames-dir "$out/$demo-frames"
done

# joint-angle plots: the driven DOF and the DOFs that follow it
"$SK" hand animate "$presets/little-mcp.json" -q --plot "$out/little-mcp-plot.png" --plot-size 720x540 \
  --plot-title "Fig. 4.19: little-finger MCP driven" \
  --plot-dofs L.MCP.flex,R.MCP.flex,M.MCP.flex,L.PIP.flex,L.DIP.flex
"$SK" hand animate "$presets/little-dip.json" -q --plot "$out/little-dip-plot.png" --plot-size 720x540 \
  --plot-title "Fig. 4.20: little-finger DIP driven" \
  --plot-dofs L.DIP.flex,L.PIP.flex,L.MCP.flex,R.MCP.flex,M.MCP.flex
"$SK" hand animate "$presets/piano-key.json" -q --plot "$out/piano-key-plot.png" --plot-size 720x540 \
  --plot-title "Piano key presses (Fig. 4.21)" \
  --plot-dofs I.MCP.flex,I.PIP.flex,I.DIP.flex,M.MCP.flex,R.MCP.flex

# key frames from rest to the peak (and the three key presses)
mapfile -t keys < <(keys_with_angle "$out/little-mcp-angles.csv" L.MCP.flex 0 6 12 18 24)
strip little-mcp "Fig. 4.19: L.MCP driven (top: dorsal view, bottom: radial view)" "${keys[@]}"
mapfile -t keys < <(keys_with_angle "$out/little-dip-angles.csv" L.DIP.flex 0 6 12 18 24)
strip little-dip "Fig. 4.20: L.DIP driven (top: dorsal view, bottom: radial view)" "${keys[@]}"
strip piano-key "Piano key presses (top: dorsal view, bottom: radial view)" \
  "0:at rest" "12:index key" "36:middle key" "60:ring key"

# the same input with the thesis's own Table 3.2 rows, and for a left hand
"$SK" hand animate "$presets/little-mcp.json" -q --constraints yasumuro-table-3.2 \
  --bvh "$out/little-mcp-table-3.2.bvh" --angles "$out/little-mcp-table-3.2-angles.csv" \
  --plot "$out/little-mcp-table-3.2-plot.png" --plot-size 720x540 --plot-title "Fig. 4.19 input, Table 3.2 rows"
"$SK" hand animate "$presets/piano-key.json" -q --side left --bvh "$out/piano-key-left.bvh"

# calibration (sec. 3.2.2): sample the demonstration's own motion and fit rows again
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; print "L.MCP.flex,R.MCP.flex,L.PIP.flex,L.DIP.flex"; next }
         { print $col["L.MCP.flex"] "," $col["R.MCP.flex"] "," $col["L.PIP.flex"] "," $col["L.DIP.flex"] }' \
  "$out/little-mcp-angles.csv" > "$out/little-mcp-samples.csv"
"$SK" hand calibrate "$out/little-mcp-samples.csv" \
  --pairs L.MCP.flex:R.MCP.flex,L.PIP.flex:L.DIP.flex -o "$out/little-mcp-fitted-rows.json" > "$out/calibration.txt"

"$SK" hand pose --pin L.MCP.flex=60 -o "$out/pose-little-mcp-60.json" --bvh "$out/pose-little-mcp-60.bvh" \
  --png "$out/pose-little-mcp-60.png"
"$SK" hand pose -o "$out/pose-relaxed.json" --png "$out/pose-relaxed.png"

# the skeleton, labelled: flat, fingers slightly spread, seen from the back
flat=()
for f in I M R L; do flat+=(--pin "$f.MCP.flex=0" --pin "$f.PIP.flex=0" --pin "$f.DIP.flex=0"); done
"$SK" hand pose --constraints none "${flat[@]}" --pin I.MCP.abd=6 --pin R.MCP.abd=4 --pin L.MCP.abd=8 \
  --pin T.CMC.flex=-10 --pin T.CMC.abd=10 --pin T.MCP.flex=0 --pin T.IP.flex=0 \
  --views dorsal --png-size 640x760 --labels \
  --caption "CMC, MCP: flex + abd; PIP, DIP, IP: flex" \
  -o "$out/skeleton-flat.json" --png "$out/skeleton.png"
