#!/usr/bin/env bash
# Regenerates the pictures of techniques/depth_peeling/README.md ("Artifacts") with rtlab itself:
# the built-in `layers` scene, and a small glTF of coplanar layers that bench/coplanar_gltf.py
# writes (rows joined by bench/png_row.py). Not a test; a few minutes on llvmpipe.
# Usage: bash bench/depth_peeling_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "depth_peeling_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/depth_peeling/images
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { /usr/bin/python3 bench/png_row.py "$@"; }
size=(--size 640x360)
peel() { "$rtlab" render "${size[@]}" -t depth_peeling "$@" 2>/dev/null; }

# Too few layers on `layers`: 2, 8 and 64 layers (64: every fragment, the exact result), tail
# dropped. The back of the stack (bottom right, up to 24 layers deep) vanishes with few layers and
# the opaque backdrop shows through; the layer count view (0 black .. 24 white) with 64 layers.
for n in 2 8 64; do peel --scene layers --set depth_peeling.layers=$n --out "$work/l_$n.png"; done
peel --scene layers --set depth_peeling.layers=64 --aov depth_peeling.layers --range 0:24 --out "$work/l_count.png"
row "$out/too_few_layers.png" "$work/l_2.png" "$work/l_8.png" "$work/l_64.png"
row "$out/layer_count.png" "$work/l_count.png"

# The tail with 2 layers: dropped, blended, exact (64 layers); and the fragments left behind the
# 2 layers (depth_peeling.remaining, 0 black .. 22 white).
peel --scene layers --set depth_peeling.layers=2 --set depth_peeling.tail=blend --out "$work/t_blend.png"
peel --scene layers --set depth_peeling.layers=2 --aov depth_peeling.remaining --range 0:22 --out "$work/t_remaining.png"
row "$out/tail_drop_blend_exact.png" "$work/l_2.png" "$work/t_blend.png" "$work/l_64.png"
row "$out/remaining.png" "$work/t_remaining.png"

# Coplanar layers: the framework's per-object sorted blending (no transparency technique),
# depth peeling with 8 layers, and its layer count (0 black .. 3 white). Left pair camera-facing
# (equal depths: peeled once, the green layer is lost where they overlap), right pair in a turned
# plane (depths equal up to rounding: stripes where one, then both are peeled).
/usr/bin/python3 bench/coplanar_gltf.py "$work/coplanar.gltf"
"$rtlab" render "${size[@]}" --scene "$work/coplanar.gltf" --out "$work/c_sorted.png" 2>/dev/null
peel --scene "$work/coplanar.gltf" --out "$work/c_peel.png"
peel --scene "$work/coplanar.gltf" --aov depth_peeling.layers --range 0:3 --out "$work/c_count.png"
row "$out/coplanar.png" "$work/c_sorted.png" "$work/c_peel.png" "$work/c_count.png"
echo "depth_peeling_pictures: wrote $(ls "$out" | wc -l) pictures into $out"
