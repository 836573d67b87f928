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
hbao() { "$rtlab" render -t hbao --aov ao "$@"; }

# Halos: the height-field assumption behind the blocks of cornell with a large radius.
v=(--scene cornell --size 240x240 --set ao.radius=1.5)
ref "${v[@]}" --out "$work/h_ref.png"
hbao "${v[@]}" --out "$w/h_def.png"
row "$out/halos.png" "$work/h_ref.png" "$work/h_def.png"
