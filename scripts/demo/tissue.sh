#!/usr/bin/env bash
# The fat model of Shigemori & Kawai: the arm's and the body's generated skins and their
# layers cut open (bone, muscle, fat points, skin), an arm curl and a jump simulated and
# rendered frame by frame, with the plot of tracked skin points (belly and upper arm in the
# jump) with and without the fat layer, and strips of key frames. Writes into $OUT/tissue/:
# rest meshes (OBJ), layer point clouds (PLY), skin.pc2 (Blender: Mesh Cache modifier on
# rest.obj), skin.glb, stats.json, render/NNNN.png and the pictures.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
out="$OUT/tissue"
mkdir -p "$out"

"$SK" tissue skin --character arm -q -o "$out/arm-rest.obj" --layers "$out/arm-layers" --stats "$out/arm-skin.json"
"$SK" tissue skin --character body -q -o "$out/body-rest.obj" --layers "$out/body-layers" --stats "$out/body-skin.json"

"$SK" tissue run --character arm --motion curl --fps 24 -q -o "$out/curl" --render --render-width 240 \
  --plot "$out/curl-plot.png"
"$SK" tissue run --character body --motion jump --fps 24 -q -o "$out/jump" --render --render-width 240 \
  --plot "$out/jump-plot.png"

# key frames: the curl's fast stop at the top (2.7 s) and at the bottom (3.95 s); the jump's
# take-off, flight and landing
strip() {
  local run=$1 title=$2
  shift 2
  local args=() key
  for key in "$@"; do args+=(--label "${key#*:}" "$out/$run/render/$(printf %04d "${key%%:*}").png"); done
  "$SK" sheet --columns $# --title "$title" "${args[@]}" -o "$out/$run-strip.png"
}
strip curl "Arm curl: a fast curl stops at the top, the flesh runs on and settles" \
  "58:2.42 s" "64:2.67 s" "66:2.75 s" "68:2.83 s" "72:3.00 s" "96:4.00 s"
strip jump "Jump: crouch, take-off, flight, landing, settling" \
  "0:0 s" "19:0.79 s" "30:1.25 s" "37:1.54 s" "40:1.67 s" "60:2.50 s"
