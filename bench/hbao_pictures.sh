#!/usr/bin/env bash
# Regenerates the pictures of techniques/hbao/README.md with rtlab itself (reference | hbao rows
# joined by bench/png_row.py). Not a test; takes about a minute on llvmpipe.
# Usage: bash bench/hbao_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "hbao_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/hbao/images
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { python3 bench/png_row.py "$@"; }
ref() { "$rtlab" reference --spp 256 --aov ao "$@"; }
hbao() { "$rtlab" render -t hbao "$@"; }

# Halos: contact's sphere in front of the ground, ao.radius 3: the ground just behind the
# sphere's silhouette sees its near side within the radius and takes it for a solid.
v=(--scene contact --size 240x180 --set ao.radius=3 --set camera.position=0.6,0.9,4.2 --set camera.target=0.6,0.5,0)
ref "${v[@]}" --out "$work/h_ref.png"
hbao "${v[@]}" --aov ao --out "$work/h_def.png"
row "$out/halos.png" "$work/h_ref.png" "$work/h_def.png"

# Grazing floor: reference, default, no angle bias at half resolution without blur.
v=(--scene contact --size 240x160 --set camera.position=2.5,0.1,-1 --set camera.target=2.5,0,-6)
ref "${v[@]}" --out "$work/g_ref.png"
hbao "${v[@]}" --aov ao --out "$work/g_def.png"
hbao "${v[@]}" --set hbao.angle_bias=0 --set hbao.blur=false --set hbao.half_resolution=true --aov ao --out "$work/g_worst.png"
row "$out/grazing.png" "$work/g_ref.png" "$work/g_def.png" "$work/g_worst.png"

# Off-screen occluder: cornell's floor with the back wall just above the top edge.
v=(--scene cornell --size 240x240 --set camera.position=1.2,2.2,-1.0 --set camera.target=1.2,0,-1.75)
ref "${v[@]}" --out "$work/o_ref.png"
hbao "${v[@]}" --aov ao --out "$work/o_def.png"
row "$out/offscreen.png" "$work/o_ref.png" "$work/o_def.png"

# Debug views: raw, blurred, pattern.
v=(--scene cornell --size 320x240)
hbao "${v[@]}" --aov hbao.raw --out "$work/d_raw.png"
hbao "${v[@]}" --aov hbao.blurred --out "$work/d_blur.png"
hbao "${v[@]}" --aov hbao.pattern --out "$work/d_pat.png"
row "$out/debug_views.png" "$work/d_raw.png" "$work/d_blur.png" "$work/d_pat.png"
echo "wrote $out/{halos,grazing,offscreen,debug_views}.png"
