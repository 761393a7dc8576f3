#!/usr/bin/env bash
# Showcase demo: the four models in one scene. A right hand posed by its natural coupling
# (Yasumuro 2000) with the skin microrelief in its texture (Ishii 1991) plays the first
# seconds of Twinkle, Twinkle on a piano of figured maple (Kawai 2000), its forearm a
# tissue character whose fat swings as the wrist travels (Shigemori & Kawai), at a
# reduced size. Writes into $OUT/showcase/: frames/frame_NNNN.png, showcase.wav,
# fingering.txt, showcase.mp4 (when ffmpeg is present) and still.png (one frame at a
# larger size).
set -euo pipefail
: "${SK:?}" "${OUT:?}"
here=$(cd "$(dirname "$0")/../.." && pwd)
out="$OUT/showcase"
rm -rf "$out"
mkdir -p "$out"
melody="$here/presets/showcase/twinkle.txt"

"$SK" showcase --melody "$melody" --duration 2.5 --size 384x216 --spp 2 --fps 12 --texture-size 512 -q -o "$out"

# a still at a larger size: the hand striking G4 with its ring finger
"$SK" showcase --melody "$melody" --duration 3 --frames 30:30 --size 800x450 --spp 8 --fps 24 --texture-size 1024 \
  --no-video -q -o "$out/still"
cp "$out/still/frames/frame_0030.png" "$out/still.png"
rm -rf "$out/still"
