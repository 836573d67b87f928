#!/usr/bin/env bash
# The indirect stage's trade-off (docs/performance.md "Issue 18"; the READMEs of rsm and lpv): on
# SCENE (default `cornell`) at SIZE (default 1280x720), the CPU reference (rtlab reference --aov
# indirect --spp REFSPP), then the AOV `indirect` of
#   rsm for each sample count in SAMPLES at each RSM resolution in RESOLUTIONS (and the sum over
#     every texel within r_max, rsm.sampling=all_texels, at 256^2: its sampling-error-free value),
#   lpv for each grid in GRIDS and iteration count in ITERATIONS,
# each timed over FRAMES frames (the median ms of the technique's passes, summed: stats "passes"
# attributed to it, the light-space G-buffer included) and compared with the reference (RMSE,
# largest absolute difference), with the bytes of its frame resources. CSV to stdout, then the
# headline: the cheapest lpv setting whose RMSE is at or below rsm's with 400 samples (rsm's
# default resolution), and its time divided by that rsm time, or the numbers that show none does.
#   bash bench/indirect_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [SCENE] [REFSPP]
# Environment: SAMPLES, RESOLUTIONS, GRIDS, ITERATIONS override the lists; REF=FILE.exr uses a
# reference rendered before (the same scene, size and --aov indirect) instead of rendering one.
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5} scene=${4:-cornell}
refspp=${5:-1024}
samples=${SAMPLES:-"16 64 100 400 1024"} resolutions=${RESOLUTIONS:-"128 256 512 1024"}
grids=${GRIDS:-"16 32 64"} iterations=${ITERATIONS:-"0 2 4 8 16 32"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

source "$(dirname "$0")/tradeoff_common.sh"

common=(--scene "$scene" --size "$size")
reference_of indirect
{
echo "scene,technique,setting,ms,bytes,rmse,max_abs"
run() { measure_row indirect "$@"; } # technique setting --set...
for r in $resolutions; do
  for s in $samples; do run rsm "$s/$r" --set rsm.samples=$s --set rsm.resolution=$r; done
done
run rsm "all/256" --set rsm.sampling=all_texels --set rsm.resolution=256
for g in $grids; do
  for i in $iterations; do run lpv "$g/$i" --set lpv.grid=$g --set lpv.iterations=$i; done
done
} | tee "$tmp/all.csv"
echo
$py - "$tmp/all.csv" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
rsm = next((r for r in rows if r["technique"] == "rsm" and r["setting"] == "400/512"), None)
if rsm is None:
    sys.exit("indirect_tradeoff: no rsm row with 400 samples at 512^2 (set SAMPLES and RESOLUTIONS to include them)")
target, rsm_ms = float(rsm["rmse"]), float(rsm["ms"])
print("rsm (400 samples, 512^2): %.2f ms, rmse %s" % (rsm_ms, rsm["rmse"]))
lpv = [r for r in rows if r["technique"] == "lpv"]
ok = sorted((r for r in lpv if float(r["rmse"]) <= target), key=lambda r: float(r["ms"]))
if ok:
    r = ok[0]
    print("cheapest lpv at or below rsm-400's rmse: grid/iterations %s, %.2f ms, rmse %s; headline ratio lpv / rsm %.3f"
          % (r["setting"], float(r["ms"]), r["rmse"], float(r["ms"]) / rsm_ms))
else:
    best = min(lpv, key=lambda r: float(r["rmse"]))
    print("no lpv setting reaches rsm-400's rmse %s: the best is grid/iterations %s with rmse %s at %.2f ms"
          % (rsm["rmse"], best["setting"], best["rmse"], float(best["ms"])))
PYEOF
