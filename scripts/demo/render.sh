#!/usr/bin/env bash
# Renderer demo: Ishii 1991 Fig. 20 (skin bump-mapped around a wrist), Kawai 2000 Fig. 9
# (the moving figure sheen, three panels and a light sweep), an oak piano cabinet with a
# close-up, a turntable of the wood species, and the texture/shading blend of Yasumuro's
# thesis (Fig. 4.15), and the piano exported as glTF and OBJ. Writes PNG (tone-mapped sRGB),
# EXR (linear radiance), GLB and OBJ into $OUT/render/.
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
scenes="$here/presets/scenes"
out="$OUT/render"
mkdir -p "$out/fig9-sweep" "$out/turntable"

# Ishii 1991 Fig. 20
"$SK" render "$scenes/wrist.json" -q -o "$out/wrist.png" --exr "$out/wrist.exr"

# Kawai 2000 Fig. 9: a parallel light at delta = +7.2, 0, -7.2 degrees (towards the tree
# top), seen along the board's normal; then a sweep of the light from -14.4 to +14.4
light() { # direction of travel of a light turned by $1 degrees towards the image top
  awk -v d="$1" 'BEGIN { r = d * 3.14159265358979 / 180; printf "[0,%.6f,%.6f]", -sin(r), -cos(r) }'
}
panels=()
for p in "a 7.2" "b 0" "c -7.2"; do
  set -- $p
  "$SK" render "$scenes/fig9-board.json" -q -o "$out/fig9-$1.png" --set "lights[0].direction=$(light "$2")"
  panels+=(--label "$1. delta = $2 deg" "$out/fig9-$1.png")
done
"$SK" sheet --title "Kawai 2000 Fig. 9: moving reflection of figured wood" --columns 3 "${panels[@]}" -o "$out/fig9-sheet.png"
frames=()
i=0
for d in -14.4 -10.8 -7.2 -3.6 0 3.6 7.2 10.8 14.4; do
  f=$(printf "%s/fig9-sweep/frame-%02d.png" "$out" "$i")
  "$SK" render "$scenes/fig9-board.json" -q -o "$f" --size 200x200 --set "lights[0].direction=$(light "$d")"
  frames+=(--label "$d deg" "$f")
  i=$((i + 1))
done
"$SK" sheet --title "Fig. 9 board: the light swept from -14.4 to +14.4 degrees" --columns 9 "${frames[@]}" -o "$out/fig9-sweep-sheet.png"

# an oak piano cabinet, and a close-up of its corner: flat-sawn front, end-grain side
"$SK" render "$scenes/piano.json" -q -o "$out/piano.png" --exr "$out/piano.exr"
"$SK" render "$scenes/piano.json" -q -o "$out/piano-detail.png" --size 960x720 \
  --set camera.position=[950,1150,500] --set camera.target=[720,1050,130] --set camera.fov_deg=22 \
  --set "lights[1].direction=[-0.8,-0.35,-0.5]" --set lights[1].intensity=2.2

# the wood species turning: every sphere turned about y by 30 degrees a frame
frames=()
for i in $(seq 0 11); do
  sets=()
  for o in 0 1 2 3 4 5; do sets+=(--set "objects[$o].transform.rotate_deg=[0,$((i * 30)),0]"); done
  f=$(printf "%s/turntable/frame-%02d.png" "$out" "$i")
  "$SK" render "$scenes/wood-turntable.json" -q -o "$f" "${sets[@]}"
  frames+=(--label "$((i * 30)) deg" "$f")
done
"$SK" sheet --title "Wood species (oak, ash, maple, cherry, birch, Douglas fir) turning" --columns 3 \
  --tile-size 480 "${frames[@]}" -o "$out/turntable-sheet.png"

# Yasumuro 2000 Fig. 4.15: smooth shading of a white surface, the (photo) texture alone,
# and their 0.3 : 0.7 blend; the texture is the skin module's shaded preview
"$SK" skin --preset forearm -q --size 512 -o "$out/skin-texture.png"
texture="$out/skin-texture.png"
"$SK" render "$scenes/hand-blend.json" -q -o "$out/blend-shading.png" \
  --set materials[0].albedo_texture=null --set materials[0].texture_weight=0
"$SK" render "$scenes/hand-blend.json" -q -o "$out/blend-texture.png" \
  --set "materials[0].albedo_texture=$texture" --set materials[0].texture_weight=1
"$SK" render "$scenes/hand-blend.json" -q -o "$out/blend.png" --set "materials[0].albedo_texture=$texture"
"$SK" sheet --title "Yasumuro 2000 Fig. 4.15: shading, texture and their 0.3 : 0.7 blend" --columns 1 \
  --label "smooth shading (white surface)" "$out/blend-shading.png" \
  --label "texture mapping" "$out/blend-texture.png" \
  --label "shading and texture blended 0.3 : 0.7" "$out/blend.png" -o "$out/blend-sheet.png"

# the piano exported for other tools (Blender, game engines): glTF with the oak baked into
# base colour textures, and the same as OBJ + MTL + PNG textures
"$SK" render "$scenes/piano.json" -q --export "$out/piano.glb"
mkdir -p "$out/piano-obj"
"$SK" render "$scenes/piano.json" -q --export "$out/piano-obj/piano.obj"
