#!/usr/bin/env bash
# The shadow stage's trade-off (docs/performance.md "Issue 19"; the READMEs of the six shadow
# techniques): on `contact` (with light0.radius=0.3, as issue 4's headline) and `stacked`, at SIZE
# (default 1280x720), the CPU reference (rtlab reference --aov visibility --spp REFSPP), then the
# AOV `visibility` of
#   shadow_map, pcf and pcss at their defaults, and the yardstick pcss with 32 blocker and 64
#     filter samples;
#   vssm and msm at each shadow.resolution in RESOLUTIONS (msm also with its four-moment blocker
#     search, and as before issue 19: no bleeding reduction, moments not centred);
#   sdf_shadow with each volume layout in SDF_VOLUMES at each SDF resolution in SDF_RESOLUTIONS
#     and step budget in SDF_STEPS;
# each timed over FRAMES frames (the sum of the median ms of the technique's passes: the shadow
# stage's depth map counts, the SDF's build does not: its own column build_ms, from the stats'
# counter sdf_build_ms) and compared with the reference (RMSE, largest absolute difference). CSV to stdout,
# then per scene the Pareto front and the headline: the cheapest vssm, msm or sdf_shadow setting
# whose RMSE is at or below pcss-32/64's, and its time divided by pcss-32/64's, or the numbers
# that show none is.
#   bash bench/shadow_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [REFSPP]
# Environment: SCENES ("contact stacked"), RESOLUTIONS, SDF_VOLUMES, SDF_RESOLUTIONS, SDF_STEPS override the
# lists; REF_contact=FILE.exr / REF_stacked=FILE.exr use references rendered before (same scene,
# size, light and --aov visibility).
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5} refspp=${4:-256}
scenes=${SCENES:-"contact stacked"}
resolutions=${RESOLUTIONS:-"512 1024 2048"}
sdf_volumes=${SDF_VOLUMES:-"scene per_instance"} sdf_resolutions=${SDF_RESOLUTIONS:-"32 64 128"}
sdf_steps=${SDF_STEPS:-"32 64"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

source "$(dirname "$0")/tradeoff_common.sh"

scene_options() { # the scene's light, as in issue 4's headline for contact
  case $1 in
    contact) echo "--set light0.radius=0.3" ;;
    *) echo "" ;;
  esac
}

{
echo "scene,technique,setting,ms,bytes,rmse,max_abs,build_ms"
for scene in $scenes; do
  # shellcheck disable=SC2207
  common=(--scene "$scene" --size "$size" $(scene_options "$scene"))
  var=REF_$scene
  REF=${!var:-} reference_of visibility
  run() { echo "$(measure_row visibility "$@"),"; } # technique setting --set...
  run shadow_map default
  run pcf default
  run pcss default
  run pcss yardstick --set pcss.blocker_samples=32 --set pcss.filter_samples=64
  for r in $resolutions; do
    run vssm "$r" --set shadow.resolution="$r"
    run msm "$r" --set shadow.resolution="$r"
    run msm "$r/four_moment" --set shadow.resolution="$r" --set msm.blocker_search=four_moment
    run msm "$r/before_issue_19" --set shadow.resolution="$r" --set msm.bleed_reduction=0 --set msm.centred=false
  done
  for v in $sdf_volumes; do
    for r in $sdf_resolutions; do
      for s in $sdf_steps; do
        row=$(measure_row visibility sdf_shadow "$v/$r/$s" --set sdf_shadow.volumes="$v" \
          --set sdf_shadow.resolution="$r" --set sdf_shadow.max_steps="$s")
        echo "$row,$(counter "$tmp/run.json" sdf_build_ms sdf_shadow)"
      done
    done
  done
done
} | tee "$tmp/all.csv"
echo
$py - "$tmp/all.csv" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for scene in dict.fromkeys(r["scene"] for r in rows):
    mine = [r for r in rows if r["scene"] == scene]
    front, best = [], float("inf")
    for r in sorted(mine, key=lambda r: (float(r["ms"]), float(r["rmse"]))):
        if float(r["rmse"]) < best:
            best = float(r["rmse"])
            front.append(r)
    print("%s: Pareto front (ms, rmse): %s" % (scene, "; ".join(
        "%s %s %.1f ms %s" % (r["technique"], r["setting"], float(r["ms"]), r["rmse"]) for r in front)))
    yard = next(r for r in mine if r["technique"] == "pcss" and r["setting"] == "yardstick")
    target, yard_ms = float(yard["rmse"]), float(yard["ms"])
    print("%s: pcss-32/64 %.2f ms, rmse %s" % (scene, yard_ms, yard["rmse"]))
    cand = [r for r in mine if r["technique"] in ("vssm", "msm", "sdf_shadow")]
    ok = sorted((r for r in cand if float(r["rmse"]) <= target), key=lambda r: float(r["ms"]))
    if ok:
        r = ok[0]
        print("%s: cheapest vssm/msm/sdf_shadow at or below it: %s %s, %.2f ms, rmse %s; ratio %.3f"
              % (scene, r["technique"], r["setting"], float(r["ms"]), r["rmse"], float(r["ms"]) / yard_ms))
    for t in ("vssm", "msm", "sdf_shadow"):
        b = min((r for r in cand if r["technique"] == t), key=lambda r: float(r["rmse"]), default=None)
        if b:
            print("%s: best %s: %s, %.2f ms, rmse %s" % (scene, t, b["setting"], float(b["ms"]), b["rmse"]))
PYEOF
