#!/usr/bin/env bash
# The trade-off charts of techniques/hbao/README.md (never part of the tests): `rtlab sweep` of
# hbao over directions x steps on `cornell` and `contact` at 640x360, --frames 5, reference 256
# spp, each sweep run RUNS times (ms = median over the runs, bench/ao_chart.py), writing
# techniques/hbao/tradeoff_<scene>.svg and printing the median tables.
# Usage: bash bench/hbao_tradeoff.sh [path/to/rtlab]   (env: RUNS=3)
# Timing on Mesa's llvmpipe is cpu-finish on a CPU shared with other work: ranks and ratios.
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "hbao_tradeoff: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
runs=${RUNS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RTLAB_CACHE_DIR="$work/cache"
echo "hbao sweeps, 640x360, --frames 5, reference 256 spp, $runs runs; $("$rtlab" --version), $(nproc) cores"
for scene in cornell contact; do
  csvs=()
  for ((run = 1; run <= runs; ++run)); do
    "$rtlab" sweep --scene "$scene" --size 640x360 --frames 5 --spp 256 -t hbao \
      --vary hbao.directions=2,4,8,16 --vary hbao.steps=2,4,8,16 --out "$work/$scene$run" 2>"$work/log" ||
      { cat "$work/log" >&2; exit 1; }
    csvs+=("$work/$scene$run/results.csv")
  done
  echo
  echo "$scene:"
  python3 bench/ao_chart.py "techniques/hbao/tradeoff_$scene.svg" "hbao on $scene: ao RMSE against ms" \
    "640x360, reference 256 spp, llvmpipe cpu-finish (shared CPU)" hbao.steps hbao.directions "${csvs[@]}"
done
