#!/usr/bin/env bash
# Regenerates the pictures of techniques/bloom/README.md ("Artifacts") with rtlab itself, on the
# built-in `glow` scene (rows joined by bench/png_row.py). Not a test; about a minute on llvmpipe.
# Usage: bash bench/bloom_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "bloom_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/bloom/images
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { /usr/bin/python3 bench/png_row.py "$@"; }
bloom() { "$rtlab" render --scene glow -t bloom "$@" 2>/dev/null; }

# The hard cut pops, the knee does not: the bright pass on the snow panel (luma 0.9 on the right to
# 1.1 on the left), with light 0 at 97% and 103% of its intensity. With the hard cut the part above
# T = 1 jumps from 0 to the full colour at a line that moves across the panel; with the knee the
# bright part grows smoothly from luma 0.5 on.
v=(--size 320x180 --set camera.position=0,0.7,4.2 --set camera.target=0,0.7,0 --set camera.fov=20
   --aov bloom.bright --range 0:1.1)
for cut in true false; do
  for i in 238 252; do bloom "${v[@]}" --set bloom.hard_cut=$cut --set light0.intensity=$i --out "$work/k_${cut}_$i.png"; done
done
row "$out/hard_cut.png" "$work/k_true_238.png" "$work/k_true_252.png"
row "$out/soft_knee.png" "$work/k_false_238.png" "$work/k_false_252.png"

# Fireflies: the sparks of luma 1e3, 4, 2 and 1 px across (the emitters of luma 1, 10 and 100
# above them), the bloom AOV with Karis's average off and on, the camera panned half a pixel
# between the two frames of each pair. 320x180 at fov 20.6 keeps the scene's pixel size (0.0162 at
# z = 0, as 640x360 at fov 40). Without Karis a spark blooms with all its energy wherever it lands
# on the pixel grid; with it, the first level damps isolated bright texels.
v=(--size 320x180 --set camera.fov=20.6 --aov bloom --range 0:4)
for k in false true; do
  bloom "${v[@]}" --set bloom.karis=$k --set camera.position=-1.8,2.2,8 --set camera.target=-1.8,2.2,0 --out "$work/f_${k}_0.png"
  bloom "${v[@]}" --set bloom.karis=$k --set camera.position=-1.792,2.2,8 --set camera.target=-1.792,2.2,0 --out "$work/f_${k}_1.png"
done
row "$out/fireflies_no_karis.png" "$work/f_false_0.png" "$work/f_false_1.png"
row "$out/fireflies_karis.png" "$work/f_true_0.png" "$work/f_true_1.png"

# The mip chain's blockiness: one wide octave (sigma 16 px) around the emitters of luma 100 and 1e3,
# the exact Gaussian, the mip chain's approximation (levels 3 and 4, sigma 9.7 and 19.6 px, mixed),
# and where they differ (rtlab compare's heat map): the chain's halo is a rounded square (its
# filters are box-like along the axes), and its flanks are too steep on the diagonals.
v=(--size 320x180 --set camera.position=0,3.1,8 --set camera.target=0,3.1,0 --set camera.fov=20
   --set bloom.sigma=16 --set bloom.octaves=1 --set bloom.intensity=1 --aov bloom)
bloom "${v[@]}" --set bloom.method=gaussian --range 0:40 --out "$work/b_gauss.png"
bloom "${v[@]}" --set bloom.method=mip --set bloom.karis=false --range 0:40 --out "$work/b_mip.png"
bloom "${v[@]}" --set bloom.method=gaussian --out "$work/b_gauss.exr"
bloom "${v[@]}" --set bloom.method=mip --set bloom.karis=false --out "$work/b_mip.exr"
"$rtlab" compare "$work/b_gauss.exr" "$work/b_mip.exr" --heatmap "$work/b_diff.png" >/dev/null
row "$out/mip_vs_gaussian.png" "$work/b_gauss.png" "$work/b_mip.png" "$work/b_diff.png"

# The whole scene: without bloom, with bloom (defaults), and the bloom AOV alone.
"$rtlab" render --scene glow --size 320x180 --out "$work/s_off.png" 2>/dev/null
bloom --size 320x180 --out "$work/s_on.png"
bloom --size 320x180 --aov bloom --range 0:4 --out "$work/s_aov.png"
row "$out/glow.png" "$work/s_off.png" "$work/s_on.png" "$work/s_aov.png"
echo "bloom_pictures: wrote $(ls "$out" | wc -l) pictures into $out"
