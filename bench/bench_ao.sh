#!/usr/bin/env bash
# AO stage benchmark (never part of the tests), issue 6: ssao at 1280x720 on `cornell`, its
# passes' time (median of --frames 10, `ms` = the technique's passes summed) and its ao RMSE
# against the ray-traced reference (256 spp), at the defaults (16 samples), with 64 samples, and
# both at half resolution; one `rtlab sweep`, so the reference is rendered once.
# Usage: bash bench/bench_ao.sh [path/to/rtlab] [extra sweep options, e.g. --timing gpu-query]
# Timing on Mesa's llvmpipe is cpu-finish on a CPU shared with other work: compare rows of one
# run, not runs on different machines or loads.
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "bench_ao: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
shift || true

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RTLAB_CACHE_DIR="$work/cache"

echo "ssao on cornell, 1280x720, --frames 10, reference 256 spp; $("$rtlab" --version), $(nproc) cores"
"$rtlab" sweep --scene cornell --size 1280x720 --frames 10 --spp 256 -t ssao \
  --vary ssao.samples=16,64 --vary ssao.half_resolution=false,true --out "$work/sweep" "$@" 2>"$work/log" ||
  { cat "$work/log" >&2; exit 1; }
# The error of "no AO" (ao = 1 everywhere) on the same frame, as the yardstick.
"$rtlab" render --scene cornell --size 1280x720 -t none --aov ao --out "$work/none.exr" 2>>"$work/log"
ref=$(ls "$work"/sweep/reference/*.exr | head -1)
none_rmse=$("$rtlab" compare "$work/none.exr" "$ref" --json | sed -n 's/.*"rmse": *\([0-9.e-]*\).*/\1/p')
echo
echo "technique,samples,half_resolution,ms,frame_ms,rmse,timing"
tail -n +2 "$work/sweep/results.csv" | awk -F, '{ printf "%s,%s,%s,%s,%s,%s,%s\n", $1, $2, $3, $4, $5, $6, $10 }'
echo "no AO (ao = 1): rmse $none_rmse"
echo
echo "per pass (ms, median of the frames):"
for stats in "$work"/sweep/points/*/stats.json; do
  python3 - "$stats" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
p = s["params"]
passes = " + ".join(f'{x["name"]} {x["ms"]:.1f}' for x in s["passes"] if x["technique"] == "ssao")
print(f'samples {p["ssao.samples"]}, half_resolution {str(p["ssao.half_resolution"]).lower()}: {passes}')
PY
done
