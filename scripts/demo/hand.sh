#!/usr/bin/env bash
# Hand demonstrations of Yasumuro's thesis (sec. 4.2.3): drive only the little finger's
# MCP (Fig. 4.19) or DIP (Fig. 4.20), and piano key presses that drive two DOFs of one
# finger (Fig. 4.21); plus Table 3.2 as a constraint set and a calibration round trip.
# Writes BVH (Blender: File > Import > Motion Capture, scale 0.001), joint angles and
# joint positions of every frame into $OUT/hand/.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
presets="$here/presets/hand"
out="$OUT/hand"
mkdir -p "$out"

for demo in little-mcp little-dip piano-key; do
  "$SK" hand animate "$presets/$demo.json" -q \
    --bvh "$out/$demo.bvh" --angles "$out/$demo-angles.csv" --positions "$out/$demo-positions.csv"
done
# the same input with the thesis's own Table 3.2 rows, and for a left hand
"$SK" hand animate "$presets/little-mcp.json" -q --constraints yasumuro-table-3.2 \
  --bvh "$out/little-mcp-table-3.2.bvh" --angles "$out/little-mcp-table-3.2-angles.csv"
"$SK" hand animate "$presets/piano-key.json" -q --side left --bvh "$out/piano-key-left.bvh"

# calibration (sec. 3.2.2): sample the demonstration's own motion and fit rows again
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; print "L.MCP.flex,R.MCP.flex,L.PIP.flex,L.DIP.flex"; next }
         { print $col["L.MCP.flex"] "," $col["R.MCP.flex"] "," $col["L.PIP.flex"] "," $col["L.DIP.flex"] }' \
  "$out/little-mcp-angles.csv" > "$out/little-mcp-samples.csv"
"$SK" hand calibrate "$out/little-mcp-samples.csv" \
  --pairs L.MCP.flex:R.MCP.flex,L.PIP.flex:L.DIP.flex -o "$out/little-mcp-fitted-rows.json" > "$out/calibration.txt"

"$SK" hand pose --pin L.MCP.flex=60 -o "$out/pose-little-mcp-60.json" --bvh "$out/pose-little-mcp-60.bvh"
