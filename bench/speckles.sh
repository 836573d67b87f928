#!/usr/bin/env bash
# Umbra speckle share (issue 12; techniques/vssm/README.md, "Speckles"): on `stacked` and
# `contact` at 640x360 (defaults), the share of the reference's deep umbra (visibility exactly 0,
# eroded by 3 px) where each technique's visibility exceeds 0.05, and the visibility RMSE against
# the same reference. Runs on any OpenGL 4.5 driver (no GPU-specific code).
# Usage: bash bench/speckles.sh [path/to/rtlab] [reference spp, default 256]
# Builds build/bench/rtlab_bench_speckles (not in the default build) into the configured build/.
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
spp=${2:-256}
measure=build/bench/rtlab_bench_speckles
[ -x "$rtlab" ] || { echo "speckles: no rtlab binary at $rtlab" >&2; exit 1; }
[ -f build/CMakeCache.txt ] || { echo "speckles: no build/ (bash scripts/setup.sh first)" >&2; exit 1; }
cmake --build build -j"$(nproc 2>/dev/null || echo 2)" --target rtlab_bench_speckles >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RTLAB_CACHE_DIR="$work/cache"
size=640x360
for scene in stacked contact; do
  "$rtlab" reference --scene "$scene" --size "$size" --aov visibility --spp "$spp" --out "$work/${scene}_ref.exr"
  for variant in pcss vssm msm msm:msm.format=rgba32f msm:msm.format=rgba16_optimized msm:msm.format=rgba16f_optimized; do
    technique=${variant%%:*}
    sets=()
    [ "$variant" = "$technique" ] || sets=(--set "${variant#*:}")
    out="$work/${scene}_${variant//[:=.]/_}.exr"
    "$rtlab" render --scene "$scene" --size "$size" -t "$technique" "${sets[@]}" --aov visibility --out "$out"
    share=$("$measure" "$work/${scene}_ref.exr" "$out" | sed 's/.*umbra/umbra/')
    rmse=$("$rtlab" compare "$out" "$work/${scene}_ref.exr" --json | sed -n 's/.*"rmse": *\([0-9.e-]*\).*/\1/p')
    printf '%-8s %-32s %s  rmse %s\n' "$scene" "$variant" "$share" "$rmse"
  done
done
