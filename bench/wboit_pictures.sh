#!/usr/bin/env bash
# Regenerates the pictures of techniques/wboit/README.md ("Artifacts") with rtlab itself, on the
# built-in `layers` and `panes` scenes and a generated scene of faint layers
# (bench/wboit_faint_layers.py); rows joined by bench/png_row.py. "Over" is the framework's
# transparency fallback (no technique: each object drawn back to front with Over), exact on these
# camera-facing layers. Not a test; about a minute on llvmpipe.
# Usage: bash bench/wboit_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "wboit_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/wboit/images
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { /usr/bin/python3 bench/png_row.py "$@"; }
over() { "$rtlab" render --size 320x180 "$@" 2>/dev/null; }
wboit() { "$rtlab" render --size 320x180 -t wboit "$@" 2>/dev/null; }

# The scenes as a whole: Over, wboit at its defaults (color9, RGBA16F, R8), and the depth
# complexity (fragments per pixel, magma 0..24 on layers, 0..4 on panes).
for s in layers panes; do
  max=$([ $s = layers ] && echo 24 || echo 4)
  over --scene $s --out "$work/${s}_over.png"
  wboit --scene $s --out "$work/${s}_wboit.png"
  wboit --scene $s --aov wboit.complexity --range 0:$max --false-color --out "$work/${s}_count.png"
  row "$out/$s.png" "$work/${s}_over.png" "$work/${s}_wboit.png" "$work/${s}_count.png"
done

# A high-alpha layer in front does not hide the layers behind it: layers' `front_high` (white,
# alpha 0.95, depth 2) over `back_low_0..2` (alpha 0.15, depths 3-5), zoomed in. Over: the white
# layer hides them (5% shows through); wboit: reveal = 0.05 x 0.85^k is right, but the average
# colour mixes the back layers' colours in by their weights, and their weights are nearly the
# front layer's at these depths; then rtlab compare's heat map of the two.
v=(--scene layers --set camera.position=0,0,0 --set camera.target=0.746,0.513,-2 --set camera.fov=22)
over "${v[@]}" --out "$work/f_over.png"
wboit "${v[@]}" --out "$work/f_wboit.png"
over "${v[@]}" --aov transparency --out "$work/f_over.exr"
wboit "${v[@]}" --aov transparency --out "$work/f_wboit.exr"
"$rtlab" compare "$work/f_over.exr" "$work/f_wboit.exr" --heatmap "$work/f_diff.png" >/dev/null
row "$out/front_high.png" "$work/f_over.png" "$work/f_wboit.png" "$work/f_diff.png"

# Weights tuned for one depth range: the 24-layer stack from depth 0.1 to 500 with Over, eq7, eq9
# and eq10.
over --scene layers --out "$work/d_over.png"
for w in eq7 eq9 eq10; do wboit --scene layers --set wboit.weight=$w --out "$work/d_$w.png"; done
row "$out/depth_range.png" "$work/d_over.png" "$work/d_eq7.png" "$work/d_eq9.png" "$work/d_eq10.png"

# R8 revealage loses small alpha: 40 white layers per group, alpha 0.0015 (< 1/510), 0.004 and
# 0.02, over black. Over; wboit with R8 (the left group is gone: each 1 x (1 - 0.0015) rounds back
# to 1); wboit with R16F.
/usr/bin/python3 bench/wboit_faint_layers.py "$work/faint.gltf" 40
f=(--scene "$work/faint.gltf" --set scene.ambient=0,0,0)
over "${f[@]}" --out "$work/r_over.png"
wboit "${f[@]}" --set wboit.reveal_format=r8 --out "$work/r_r8.png"
wboit "${f[@]}" --set wboit.reveal_format=r16f --out "$work/r_r16f.png"
row "$out/r8_revealage.png" "$work/r_over.png" "$work/r_r8.png" "$work/r_r16f.png"
echo "wboit_pictures: wrote $(ls "$out" | wc -l) pictures into $out"
