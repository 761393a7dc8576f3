#!/usr/bin/env bash
# The hand's skin surface (Yasumuro 2000, sec. 4.1 and 4.2) ray-traced with its baked skin
# texture, shaded as the thesis does (0.3 shading : 0.7 texture, presets/hand/skin-scene.json):
# the relaxed hand, Fig. 4.17-style poses, the keyframe animation of Fig. 4.18 (19 frames, keys
# at 1, 9 and 19), the constrained curls of Figs. 4.19 / 4.20 as image sequences and contact
# sheets, and rigid vs LBS vs DQS skinning on a fully flexed index finger; the skinned hand as
# glTF binary, posed and animated. Writes into $OUT/hand/: surface-*.png, fig4.17-poses.png,
# fig4.18-* (fig4.18.glb: the animation), fig4.19-*, fig4.20-*, skinning-*, hand.glb.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
presets="$here/presets/hand"
out="$OUT/hand"
work="$out/surface"
mkdir -p "$work"
cp "$here/presets/hand/skin-scene.json" "$work/hand-skin.json"
cd "$work"

# render MESH PNG [render options...]: the hand-skin scene with another mesh
render() {
  local mesh=$1 png=$2
  shift 2
  "$SK" render hand-skin.json -q --set "objects[0].file=$mesh" -o "$png" "$@"
}
# sheet_of DIR FRAMES TITLE OUT COLUMNS: a contact sheet of DIR/frame_NNNN.png labelled "frame N"
sheet_of() {
  local dir=$1 frames=$2 title=$3 sheet=$4 columns=$5 args=() f i=1
  for f in ${frames//,/ }; do
    args+=(--label "$6$i" "$dir/$(printf 'frame_%04d' "$f").png")
    i=$((i + 1))
  done
  "$SK" sheet --columns "$columns" --title "$title" --text-scale 1 --border 1 "${args[@]}" -o "$sheet"
}

# the relaxed hand and its texture (the atlas: back on the left, palm on the right)
"$SK" hand mesh -o hand.obj --texture skin -q
render hand.obj "$out/surface-relaxed.png" --size 480x600 --spp 16
"$SK" sheet --tile-size 400 --label "albedo (back | palm)" skin-albedo.png --label "normal map" skin-normal.png \
  -o "$out/surface-atlas.png"

# Fig. 4.17: poses set joint by joint that glove sensors measure badly
poses=()
for p in point horns spread ring; do
  "$SK" hand mesh --pose "$presets/fig4.17-$p.json" -o "pose-$p.obj" -q
  render "pose-$p.obj" "pose-$p.png"
  poses+=(--label "$p" "pose-$p.png")
done
"$SK" sheet --columns 4 --title "Fig. 4.17-style poses (DQS skinning)" "${poses[@]}" -o "$out/fig4.17-poses.png"
# the pointing pose as glTF: skeleton, skin, the 3 levels of detail, the baked texture
"$SK" hand mesh --pose "$presets/fig4.17-point.json" -o "$out/hand.glb" -q

# Fig. 4.18: 3 keys, every joint DOF by Bezier curves; 19 frames with the keys at 1, 9, 19
frames=0,5,10,15,20,25,30,35,40,44,48,52,56,60,64,68,72,76,80
"$SK" hand animate "$presets/fig4.18-keys.json" -q --meshes-dir fig4.18 --mesh-frames "$frames" \
  --landmarks "$out/fig4.18-landmarks.csv" --glb "$out/fig4.18.glb"
mkdir -p "$out/fig4.18-frames"
for f in ${frames//,/ }; do
  name=$(printf 'frame_%04d' "$f")
  render "fig4.18/$name.obj" "$out/fig4.18-frames/$name.png" --size 240x300
done
sheet_of "$out/fig4.18-frames" "$frames" "Fig. 4.18: keyframe animation (keys: frames 1, 9, 19)" "$out/fig4.18-sheet.png" 5 "frame "

# Figs. 4.19 / 4.20: only the little finger's MCP (L2), then only its DIP (L4), is driven
for demo in little-mcp:fig4.19:MCP little-dip:fig4.20:DIP; do
  keys=${demo%%:*} rest=${demo#*:} fig=${rest%%:*} joint=${demo##*:}
  frames=0,3,6,9,12,15,18,21,24
  "$SK" hand animate "$presets/$keys.json" -q --meshes-dir "$fig" --mesh-frames "$frames"
  mkdir -p "$out/$fig-frames"
  for f in ${frames//,/ }; do
    name=$(printf 'frame_%04d' "$f")
    # seen from the little finger's side, where the curl is
    render "$fig/$name.obj" "$out/$fig-frames/$name.png" --size 240x300 --set "camera.position=[-230,170,-250]"
  done
  sheet_of "$out/$fig-frames" "$frames" "${fig/fig/Fig. }: only the little finger's $joint is driven" "$out/$fig-sheet.png" 9 ""
done

# the thesis's defect (4.1.5) and its fix: a fully flexed index finger, rigid / LBS / DQS
# (shading only, from the palm side past the thumb, so the geometry at the joints shows)
close=(--size 300x300 --set "camera.position=[170,40,200]" --set "camera.target=[22,88,18]" --set camera.fov_deg=22
  --set materials[0].texture_weight=0 --set "materials[0].albedo=[0.8,0.62,0.55]" --set "lights[0].direction=[-0.5,0.3,-0.8]")
sheet=()
for m in rigid lbs dqs; do
  "$SK" hand mesh --constraints none --pin I.MCP.flex=90 --pin I.PIP.flex=100 --pin I.DIP.flex=80 \
    --skinning "$m" -o "flexed-$m.obj" -q
  render "flexed-$m.obj" "flexed-$m.png" "${close[@]}"
  sheet+=(--label "$m" "flexed-$m.png")
done
"$SK" sheet --columns 3 --title "Fully flexed index: rigid links (thesis) vs LBS vs DQS" "${sheet[@]}" \
  -o "$out/skinning-comparison.png"
