# Shared by the trade-off benchmarks (bench/transparency_tradeoff.sh, bench/arealight_tradeoff.sh):
# source it after setting $rtlab (the binary) and $py (Debian's python3).

# ms and bytes of technique $2's passes and resources in stats JSON $1: the sum of the median ms of
# the passes attributed to it, and of its frame resources' and owned buffers' bytes.
cost() {
  $py - "$1" "$2" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1])); t = sys.argv[2]
ms = sum(p["ms"] for p in d["passes"] if p.get("technique") == t)
b = sum(r["bytes"] for r in d["resources"] if r["name"].startswith(t + ".") or r.get("technique") == t)
print("%.3f,%d" % (ms, b))
PYEOF
}

# The metric $3 (rmse, max_abs, ...) of image $2 against image $1 (rtlab compare).
metric() { "$rtlab" compare "$1" "$2" | awk -v k="$3" '$1 == k {print $2}'; }
