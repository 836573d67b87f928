#!/usr/bin/env bash
# sdf_shadow's trade-off (techniques/sdf_shadow/README.md "Measured"): on SCENE (default
# `contact`) at SIZE (default 640x360), the CPU reference (rtlab reference --aov visibility --spp
# REFSPP), then the AOV `visibility` of sdf_shadow for each SDF resolution in RESOLUTIONS and step
# budget in STEPS, timed over FRAMES frames (the median ms of its passes, summed; the SDF's CPU
# build is not a pass: its own column, from the stats counter sdf_build_ms), compared with the
# reference (RMSE, largest absolute difference), with the rays that ran out of steps, for each
# volume layout in VOLUMES (sdf_shadow.volumes; the setting column is volumes/resolution/steps);
# and shadow_map and pcss at their defaults for comparison. CSV to stdout.
#   bash bench/sdf_shadow_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [SCENE] [REFSPP]
# Environment: VOLUMES (default "scene per_instance"), RESOLUTIONS, STEPS override the lists;
# REF=FILE.exr uses a reference rendered before (the same scene, size and --aov visibility); SET
# adds options to every render (e.g. SET="--set light0.radius=0.3"; the reference's too).
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-640x360} frames=${3:-5} scene=${4:-contact}
refspp=${5:-256}
volumes=${VOLUMES:-"scene per_instance"} resolutions=${RESOLUTIONS:-"32 64 128 256"} steps=${STEPS:-"16 32 64 128"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

source "$(dirname "$0")/tradeoff_common.sh"

read -r -a extra <<<"${SET:-}"
common=(--scene "$scene" --size "$size" "${extra[@]}")
reference_of visibility
echo "scene,technique,setting,ms,bytes,rmse,max_abs,build_ms,exhausted_rays,voxels"
for v in $volumes; do
  for r in $resolutions; do
    for s in $steps; do
      row=$(measure_row visibility sdf_shadow "$v/$r/$s" --set sdf_shadow.volumes=$v --set sdf_shadow.resolution=$r \
        --set sdf_shadow.max_steps=$s)
      echo "$row,$(counter "$tmp/run.json" sdf_build_ms sdf_shadow),$(counter "$tmp/run.json" exhausted_rays sdf_shadow),$(counter "$tmp/run.json" sdf_voxels sdf_shadow)"
    done
  done
done
for t in shadow_map pcss; do echo "$(measure_row visibility $t default),,,"; done
