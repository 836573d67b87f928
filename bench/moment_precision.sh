#!/usr/bin/env bash
# Issue 19's moment precision, measured (docs/performance.md, "Issue 19: moment precision"): vssm
# and msm at 640x360 on `stacked` and `contact`, defaults and with the precision keys
# (`<id>.sat_bits` 64, `msm.centred`), against a 256-spp visibility reference: the visibility RMSE
# and the technique's ms (sum of its passes' medians over 5 frames, cpu-finish on llvmpipe),
# median over RUNS alternating runs. With BEFORE=path/to/old/rtlab its defaults are measured too,
# in the same alternation.
#   bash bench/moment_precision.sh [RUNS] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
out=${2:-$(mktemp -d)}
rtlab=$(realpath build/rtlab)
py=/usr/bin/python3
mkdir -p "$out"
# shellcheck source=bench/tradeoff_common.sh
source bench/tradeoff_common.sh

variants=(vssm vssm:vssm.sat_bits=64 msm msm:msm.sat_bits=64 msm:msm.centred=true "msm:msm.centred=true,msm.sat_bits=64")
for scene in stacked contact; do
  ref=$out/${scene}_ref.exr
  [[ -f $ref ]] || "$rtlab" reference --scene "$scene" --size 640x360 --aov visibility --spp 256 --out "$ref" 2>/dev/null
done
echo "scene,binary,variant,run,ms,rmse,max_abs" > "$out/rows.csv"
for run in $(seq "$runs"); do
  for scene in stacked contact; do
    ref=$out/${scene}_ref.exr
    binaries=("$rtlab")
    [[ -n "${BEFORE:-}" ]] && binaries+=("$(realpath "$BEFORE")")
    for binary in "${binaries[@]}"; do
      for variant in "${variants[@]}"; do
        t=${variant%%:*}
        sets=()
        if [[ $variant != "$t" ]]; then
          [[ $binary == "$rtlab" ]] || continue # the old binary has no precision keys
          IFS=, read -ra assignments <<< "${variant#*:}"
          for a in "${assignments[@]}"; do sets+=(--set "$a"); done
        fi
        img=$out/run.exr stats=$out/run.json
        "$binary" render --scene "$scene" --size 640x360 -t "$t" --aov visibility --frames 5 --stats "$stats" \
          --out "$img" "${sets[@]}" 2>/dev/null
        label=after; [[ $binary == "$rtlab" ]] || label=before
        echo "$scene,$label,${variant//,/+},$run,$(cost "$stats" "$t" | cut -d, -f1),$(metric "$ref" "$img" rmse),$(metric "$ref" "$img" max_abs)" \
          >> "$out/rows.csv"
      done
    done
  done
done
$py - "$out/rows.csv" <<'PYEOF'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = []
for r in rows:
    k = (r["scene"], r["binary"], r["variant"])
    if k not in keys: keys.append(k)
print("| scene | binary | variant | ms (median) | RMSE | max |")
print("|---|---|---|---:|---:|---:|")
for k in keys:
    sel = [r for r in rows if (r["scene"], r["binary"], r["variant"]) == k]
    print("| %s | %s | %s | %.1f | %.4f | %.3f |" % (k[0], k[1], k[2], statistics.median(float(r["ms"]) for r in sel),
          float(sel[0]["rmse"]), float(sel[0]["max_abs"])))
PYEOF
