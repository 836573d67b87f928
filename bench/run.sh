#!/usr/bin/env bash
# Benchmarks (never part of the tests): per-pass times and the full-screen floor (rtlab_bench),
# then the wall time of whole headless `rtlab render` processes: the first run with an empty
# Mesa shader cache, then repeated runs (median of 5) with the cache warm.
#   bash bench/run.sh [extra rtlab_bench options]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The benchmarks are not in the default build (bench/CMakeLists.txt).
cmake --build build -j"$(nproc 2>/dev/null || echo 2)" --target rtlab_bench >/dev/null
build/bench/rtlab_bench "$@"

cache=$(mktemp -d)
trap 'rm -rf "$cache"' EXIT
out="$cache/frame.png"
render=(build/rtlab render --scene contact -t shadow_map --size 1280x720 --out "$out")
ms() { local t0 t1; t0=$(date +%s%N); MESA_SHADER_CACHE_DIR="$cache/mesa" "${render[@]}"; t1=$(date +%s%N); echo $(( (t1 - t0) / 1000000 )); }
first=$(ms)
runs=()
for _ in 1 2 3 4 5; do runs+=("$(ms)"); done
sorted=($(printf '%s\n' "${runs[@]}" | sort -n))
echo "rtlab render process, contact + shadow_map 1280x720: first run ${first} ms (empty shader cache), repeated median ${sorted[2]} ms (runs: ${runs[*]})"
