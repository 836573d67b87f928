#!/usr/bin/env bash
# The arealight stage's trade-off (docs/performance.md "Issue 17"; the READMEs of ltc and area_mc):
# on SCENE (default `arealight`) at SIZE (default 1280x720), the CPU reference (rtlab reference
# --aov arealight --spp REFSPP), then the AOV `arealight` of
#   ltc for each table size (16, 32, 64) and edge formula (rational, acos),
#   area_mc for each sample count in SAMPLES,
# each timed over FRAMES frames (the median ms of the technique's passes, summed: stats "passes"
# attributed to it) and compared with the reference (RMSE, largest absolute difference), with the
# bytes of the technique's frame resources and owned textures. CSV to stdout, then the headline:
# the area_mc sample count whose RMSE equals ltc's (default settings), interpolated in log-log
# between the two measured counts around it (Monte-Carlo error falls as a power of the count), its
# time interpolated linearly in the count, and the time ratio ltc / that area_mc.
#   bash bench/arealight_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [SCENE] [REFSPP] [SAMPLES]
# REF=FILE.exr uses a reference rendered before (the same scene, size and --aov arealight).
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5} scene=${4:-arealight}
refspp=${5:-1024} samples=${6:-"1 2 4 8 16 32 64 128 256"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

source "$(dirname "$0")/tradeoff_common.sh"

common=(--scene "$scene" --size "$size")
reference_of arealight
{
echo "scene,technique,setting,ms,bytes,rmse,max_abs"
run() { measure_row arealight "$@"; } # technique setting --set...
for n in 16 32 64; do
  for e in rational acos; do run ltc "$n/$e" --set ltc.table_size=$n --set ltc.edge=$e; done
done
for s in $samples; do run area_mc "$s" --set area_mc.samples=$s; done
} | tee "$tmp/all.csv"
echo
$py - "$tmp/all.csv" <<'PYEOF'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ltc = next(r for r in rows if r["technique"] == "ltc" and r["setting"] == "64/rational")
mc = sorted((r for r in rows if r["technique"] == "area_mc"), key=lambda r: int(r["setting"]))
target = float(ltc["rmse"])
print("ltc (64, rational): %.2f ms, rmse %s" % (float(ltc["ms"]), ltc["rmse"]))
for a, b in zip(mc, mc[1:]):
    ea, eb = float(a["rmse"]), float(b["rmse"])
    if ea >= target >= eb and ea > eb:
        na, nb = int(a["setting"]), int(b["setting"])
        t = (math.log(ea) - math.log(target)) / (math.log(ea) - math.log(eb))
        n = math.exp(math.log(na) + t * (math.log(nb) - math.log(na)))
        ms = float(a["ms"]) + (n - na) / (nb - na) * (float(b["ms"]) - float(a["ms"]))
        print("area_mc reaches ltc's rmse at %.1f samples per pixel per light (between %d: rmse %.5f, %.2f ms and %d: rmse %.5f, %.2f ms), about %.2f ms; headline ratio ltc / area_mc %.3f"
              % (n, na, ea, float(a["ms"]), nb, eb, float(b["ms"]), ms, float(ltc["ms"]) / ms))
        break
else:
    lo = mc[0]
    if float(lo["rmse"]) <= target:
        print("area_mc at %s sample(s) is already at or below ltc's rmse (%s): ratio ltc / area_mc(%s) %.3f"
              % (lo["setting"], lo["rmse"], lo["setting"], float(ltc["ms"]) / float(lo["ms"])))
    else:
        hi = mc[-1]
        print("area_mc never reaches ltc's rmse %s up to %s samples (rmse %s, %.2f ms)" % (ltc["rmse"], hi["setting"], hi["rmse"], float(hi["ms"])))
PYEOF
