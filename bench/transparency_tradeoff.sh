#!/usr/bin/env bash
# The transparency stage's trade-off (docs/performance.md "Issue 16"; the READMEs of wboit,
# depth_peeling and abuffer): on each scene (default `panes` and `layers`) at SIZE (default
# 1280x720), the exact reference (rtlab reference --aov transparency), then the AOV `transparency`
# of
#   wboit for every weight function x accumulation format x revealage format,
#   depth_peeling for each layer count (tail dropped, and blended),
#   abuffer (max_fragments 32),
# each timed over FRAMES frames (the median ms of the technique's passes, summed: stats "passes"
# attributed to it) and compared with the reference: RMSE and the largest absolute difference,
# with the bytes of the technique's frame resources and owned buffers. Writes CSV to stdout, then
# the headline per scene: the time of wboit at its best weight (lowest RMSE, default formats)
# divided by the time of the cheapest depth_peeling setting whose RMSE is at or below it.
#   bash bench/transparency_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [SCENES] [LAYERS]
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5}
scenes=${4:-"panes layers"} layers=${5:-"1 2 4 8 16 24 32"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

source "$(dirname "$0")/tradeoff_common.sh"

{
echo "scene,technique,setting,ms,bytes,rmse,max_abs"
for scene in $scenes; do
  common=(--scene "$scene" --size "$size")
  ref=$tmp/ref_$scene.exr
  "$rtlab" reference "${common[@]}" --aov transparency --out "$ref" 2>/dev/null
  run() { # technique setting --set...
    local t=$1 setting=$2; shift 2
    local out=$tmp/run.exr stats=$tmp/run.json
    "$rtlab" render "${common[@]}" -t "$t" --aov transparency --frames "$frames" --stats "$stats" --out "$out" "$@"
    echo "$scene,$t,$setting,$(cost "$stats" "$t"),$(metric "$ref" "$out" rmse),$(metric "$ref" "$out" max_abs)"
  }
  for w in eq7 eq8 eq9 eq10 color9; do
    for a in rgba16f rgba32f; do
      for r in r8 r16f; do
        run wboit "$w/$a/$r" --set wboit.weight=$w --set wboit.accum_format=$a --set wboit.reveal_format=$r
      done
    done
  done
  for n in $layers; do
    run depth_peeling "$n/drop" --set depth_peeling.layers=$n --set depth_peeling.tail=drop
    run depth_peeling "$n/blend" --set depth_peeling.layers=$n --set depth_peeling.tail=blend
  done
  run abuffer "32" --set abuffer.max_fragments=32
done
} | tee "$tmp/all.csv"
echo
$py - "$tmp/all.csv" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for scene in dict.fromkeys(r["scene"] for r in rows):
    w = [r for r in rows if r["scene"] == scene and r["technique"] == "wboit" and r["setting"].endswith("/rgba16f/r8")]
    best = min(w, key=lambda r: float(r["rmse"]))
    peels = [r for r in rows if r["scene"] == scene and r["technique"] == "depth_peeling" and float(r["rmse"]) <= float(best["rmse"])]
    if not peels:
        print("%s: wboit best %s (%.2f ms, rmse %s): no depth_peeling setting is as accurate" % (scene, best["setting"], float(best["ms"]), best["rmse"]))
        continue
    cheap = min(peels, key=lambda r: float(r["ms"]))
    print("%s: wboit best %s %.2f ms rmse %s; cheapest depth_peeling at or below: %s %.2f ms rmse %s; headline ratio %.3f"
          % (scene, best["setting"], float(best["ms"]), best["rmse"], cheap["setting"], float(cheap["ms"]), cheap["rmse"],
             float(best["ms"]) / float(cheap["ms"])))
PYEOF
