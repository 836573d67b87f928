#!/usr/bin/env bash
# Measures the cost of depth_peeling per layer count for techniques/depth_peeling/README.md
# ("Measured cost"): `rtlab render --frames 5 --stats` at 1280x720 on `panes` and `layers`, for
# 1, 2, 4, 8, 16, 24 and 32 layers (tail dropped) and 2 and 8 layers with the tail blended, then
# one table row per run: the median ms of the frame, of a layer pass (mean over the layers), of an
# under pass, of the tail and of the composite, and the technique's pool memory (depth_peeling.*
# resources). Not a test; on llvmpipe about half an hour on two cores.
# Usage: bash bench/depth_peeling_cost.sh [path/to/rtlab] [OUTDIR] (runs already in OUTDIR are kept)
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "depth_peeling_cost: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
dir=${2:-$(mktemp -d)}
mkdir -p "$dir"
for scene in panes layers; do
  for run in 1:drop 2:drop 4:drop 8:drop 16:drop 24:drop 32:drop 2:blend 8:blend; do
    n=${run%%:*} tail=${run##*:} name=$dir/${scene}_${n}_${tail}
    [ -f "$name.json" ] && continue # an earlier run of the script measured it (resume)
    "$rtlab" render --scene $scene -t depth_peeling --set depth_peeling.layers=$n --set depth_peeling.tail=$tail \
      --size 1280x720 --frames 5 --stats "$name.json" --out "$name.png" 2>"$name.log"
  done
done
/usr/bin/python3 - "$dir" <<'EOF'
import json, os, sys
d = sys.argv[1]
print("| scene | layers | tail | frame ms | layer pass ms (mean) | under ms (mean) | tail ms | composite ms | depth_peeling memory MiB |")
print("|---|---|---|---|---|---|---|---|---|")
for scene in ("panes", "layers"):
    for run in ("1:drop", "2:drop", "4:drop", "8:drop", "16:drop", "24:drop", "32:drop", "2:blend", "8:blend"):
        n, tail = run.split(":")
        s = json.load(open(os.path.join(d, f"{scene}_{n}_{tail}.json")))
        passes = {p["name"]: p["ms"] for p in s["passes"]}
        layer = [v for k, v in passes.items() if k.startswith("depth_peeling.layer")]
        under = [v for k, v in passes.items() if k.startswith("depth_peeling.under")]
        mem = sum(r["bytes"] for r in s["resources"] if r["name"].startswith("depth_peeling."))
        print(f"| {scene} | {n} | {tail} | {s['frame_ms']:.0f} | {sum(layer) / len(layer):.1f} | "
              f"{sum(under) / len(under):.1f} | {passes.get('depth_peeling.tail', 0):.1f} | "
              f"{passes['depth_peeling.composite']:.1f} | {mem / 2**20:.1f} |")
print(f"\n{s['renderer']}, timing {s['timing']}, {s['size']}")
EOF
