#!/usr/bin/env bash
# Regenerates the pictures of techniques/abuffer/README.md ("Artifacts") with rtlab itself, on the
# built-in `layers` scene (rows joined by bench/png_row.py), each image 640x360. Not a test; a few
# minutes on llvmpipe (the resolve walks up to 24 fragments a pixel).
# Usage: bash bench/abuffer_pictures.sh [path/to/rtlab]
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "abuffer_pictures: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
out=techniques/abuffer/images
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
row() { /usr/bin/python3 bench/png_row.py "$@"; }
r() { "$rtlab" render --scene layers --size 640x360 --frames 1 "$@" 2>/dev/null; }

# Exact against object order: the built-in fallback draws the layers back to front by their
# centres, which is right for the stack and wrong where the two crossing layers cut through each
# other; the A-buffer sorts each pixel. Right: where they differ (rtlab compare's heat map).
r --out "$work/fallback.png"
r -t abuffer --out "$work/abuffer.png"
r --aov transparency --out "$work/fallback.exr"
r -t abuffer --aov transparency --out "$work/abuffer.exr"
"$rtlab" compare "$work/abuffer.exr" "$work/fallback.exr" --heatmap "$work/diff.png" >/dev/null
row "$out/exact_vs_object_order.png" "$work/fallback.png" "$work/abuffer.png" "$work/diff.png"

# Depth complexity: fragments per pixel, 0 (black) to 24 (white): the stack grows from 1 layer at
# its top left to 24 at its bottom right; the sphere hides the layers behind it.
r -t abuffer --aov abuffer.complexity --range 0:24 --out "$work/complexity.png"
row "$out/complexity.png" "$work/complexity.png"

# max_fragments too small: 8 and 2 fragments a pixel keep the nearest layers and drop the farthest
# (dark where the far layers of the stack and the HDR layer at depth 17.7 are lost), and the
# dropped view for 8 (0 black to 16 white).
r -t abuffer --set abuffer.max_fragments=8 --out "$work/keep8.png"
r -t abuffer --set abuffer.max_fragments=2 --out "$work/keep2.png"
r -t abuffer --set abuffer.max_fragments=8 --aov abuffer.dropped --range 0:16 --out "$work/dropped8.png"
row "$out/max_fragments.png" "$work/keep8.png" "$work/keep2.png" "$work/dropped8.png"
echo "abuffer_pictures: wrote $(ls "$out" | wc -l) pictures into $out"
