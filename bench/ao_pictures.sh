#!/usr/bin/env bash
# Regenerates the pictures of techniques/ssao/README.md with rtlab itself (reference | technique
# rows joined by bench/png_row.py). Not a test; takes about a minute on llvmpipe.
# Usage: bash bench/ao_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "ao_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/ssao/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { python3 bench/png_row.py "$@"; }
ref() { "$rtlab" reference --spp 256 --aov ao "$@"; }
ssao() { "$rtlab" render -t ssao "$@"; }

# Halos: reference, no range check, default (smooth range check).
v=(--scene cornell --size 240x240)
ref "${v[@]}" --out "$work/h_ref.png"
ssao "${v[@]}" --set ssao.range_check=off --aov ao --out "$work/h_off.png"
ssao "${v[@]}" --aov ao --out "$work/h_def.png"
row "$out/halos.png" "$work/h_ref.png" "$work/h_off.png" "$work/h_def.png"

# Grazing floor: reference, default, the worst setting found.
v=(--scene contact --size 240x160 --set camera.position=2.5,0.1,-1 --set camera.target=2.5,0,-6)
ref "${v[@]}" --out "$work/g_ref.png"
ssao "${v[@]}" --aov ao --out "$work/g_def.png"
ssao "${v[@]}" --set ssao.bias=0 --set ssao.range_check=off --set ssao.blur=false --set ssao.half_resolution=true \
  --set ssao.distribution=uniform --aov ao --out "$work/g_worst.png"
row "$out/grazing.png" "$work/g_ref.png" "$work/g_def.png" "$work/g_worst.png"

# Off-screen occluder: cornell's floor with the back wall just above the top edge.
v=(--scene cornell --size 240x240 --set camera.position=1.2,2.2,-1.0 --set camera.target=1.2,0,-1.75)
ref "${v[@]}" --out "$work/o_ref.png"
ssao "${v[@]}" --aov ao --out "$work/o_def.png"
row "$out/offscreen.png" "$work/o_ref.png" "$work/o_def.png"

# Debug views: raw, blurred, pattern (64 samples).
v=(--scene cornell --size 320x240)
ssao "${v[@]}" --aov ssao.raw --out "$work/d_raw.png"
ssao "${v[@]}" --aov ssao.blurred --out "$work/d_blur.png"
ssao "${v[@]}" --set ssao.samples=64 --aov ssao.pattern --out "$work/d_pat.png"
row "$out/debug_views.png" "$work/d_raw.png" "$work/d_blur.png" "$work/d_pat.png"
echo "wrote $out/{halos,grazing,offscreen,debug_views}.png"
