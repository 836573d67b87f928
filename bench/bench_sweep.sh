#!/usr/bin/env bash
# Wall time of a 9-point `rtlab sweep` (never part of the tests): pcf at 3 sample counts x 3
# shadow-map resolutions on `contact`, 640x360, 5 measured frames per point, reference at 64 spp.
#   1. cold: empty reference cache (the reference is rendered), --jobs 1
#   2. warm: the reference comes from the cache, --jobs 1
#   3. warm, --jobs 2
#   4. --emit-jobs, the jobs run one after another by a shell loop, then --collect (warm cache)
# Usage: bash bench/bench_sweep.sh [path/to/rtlab]   (default build/rtlab; build it first)
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "bench_sweep: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RTLAB_CACHE_DIR="$work/cache"
sweep=("$rtlab" sweep --scene contact --size 640x360 --frames 5 --spp 64 -t pcf
       --vary pcf.samples=4:64:3 --vary shadow.resolution=512,1024,2048)

ms_now() { date +%s%N; }
run() { # label, output dir, extra args...
  local label=$1 out=$2 t0 t1
  shift 2
  t0=$(ms_now)
  "${sweep[@]}" --out "$out" "$@" 2>"$work/log" || { cat "$work/log" >&2; exit 1; }
  t1=$(ms_now)
  printf '%-44s %6d ms\n' "$label" $(( (t1 - t0) / 1000000 ))
}

echo "rtlab sweep, 9 points (pcf.samples 4,16,64 x shadow.resolution 512,1024,2048), contact 640x360, --frames 5, --spp 64"
echo "$("$rtlab" --version), $(nproc) cores"
run "cold cache (reference rendered), --jobs 1" "$work/cold"
run "warm cache, --jobs 1" "$work/warm1"
run "warm cache, --jobs 2" "$work/warm2" --jobs 2

t0=$(ms_now)
"${sweep[@]}" --out "$work/emitted" --emit-jobs "$work/jobs.txt" 2>"$work/log"
while IFS= read -r job; do sh -c "$job" || exit 1; done < "$work/jobs.txt"
"$rtlab" sweep --collect "$work/emitted" 2>"$work/log"
t1=$(ms_now)
printf '%-44s %6d ms\n' "--emit-jobs, jobs in a shell loop, --collect" $(( (t1 - t0) / 1000000 ))

t0=$(ms_now)
"$rtlab" sweep --collect "$work/warm1" 2>"$work/log"
t1=$(ms_now)
printf '%-44s %6d ms\n' "--collect alone (metrics, heat maps, report)" $(( (t1 - t0) / 1000000 ))
echo
echo "results.csv of the warm --jobs 1 run:"
cat "$work/warm1/results.csv"
