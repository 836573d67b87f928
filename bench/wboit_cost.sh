#!/usr/bin/env bash
# wboit's cost and error (techniques/wboit/README.md "Measured cost"): on `panes` and `layers` at
# SIZE (default 1280x720), the framework's fallback (no technique: sorted Over per object), then
# wboit with each weight function at the default formats (RGBA16F / R8) and each format pair with
# color9, each timed over FRAMES frames (median ms per pass, cpu-finish on llvmpipe). Memory: the
# bytes of wboit's resources (accumulation and revealage) in the stats. Error: RMSE of the
# `transparency` AOV against `rtlab reference --aov transparency` where that reference exists,
# else against the fallback's Over. Writes CSV to stdout.
#   bash bench/wboit_cost.sh [RTLAB] [SIZE] [FRAMES]
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Median ms of the passes whose name starts with $2, summed, and the bytes of resources starting
# with $2, from a stats JSON.
stat() {
  $py - "$1" "$2" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); prefix = sys.argv[2]
ms = {p["name"]: p["ms"] for p in s["passes"] if p["name"].startswith(prefix)}
mem = sum(r["bytes"] for r in s["resources"] if r["name"].startswith(prefix))
print(";".join("%s=%.2f" % kv for kv in ms.items()) + ",%.2f,%.1f,%.1f" % (sum(ms.values()), s["frame_ms"], mem / 2**20))
PY
}
rmse() { "$rtlab" compare "$1" "$2" | awk '$1 == "rmse" {print $2}'; }

echo "scene,technique,weight,accum_format,reveal_format,passes_ms,technique_ms,frame_ms,technique_MiB,rmse,against"
for scene in panes layers; do
  common=(--scene "$scene" --size "$size" --aov transparency)
  "$rtlab" render "${common[@]}" --frames "$frames" --stats "$tmp/fb.json" --out "$tmp/over.pfm" 2>/dev/null
  ref=$tmp/over.pfm against=over
  if "$rtlab" reference "${common[@]}" --out "$tmp/ref.pfm" 2>/dev/null; then ref=$tmp/ref.pfm against=reference; fi
  echo "$scene,fallback,,,,$(stat "$tmp/fb.json" transparent),$(rmse "$tmp/over.pfm" "$ref"),$against"
  run() { # weight accum reveal
    "$rtlab" render "${common[@]}" -t wboit --frames "$frames" --stats "$tmp/w.json" --out "$tmp/w.pfm" \
      --set wboit.weight="$1" --set wboit.accum_format="$2" --set wboit.reveal_format="$3" 2>/dev/null
    echo "$scene,wboit,$1,$2,$3,$(stat "$tmp/w.json" wboit),$(rmse "$tmp/w.pfm" "$ref"),$against"
  }
  for w in eq7 eq8 eq9 eq10 color9; do run "$w" rgba16f r8; done
  run color9 rgba16f r16f
  run color9 rgba32f r8
  run color9 rgba32f r16f
done
