# Shared by the trade-off benchmarks (bench/transparency_tradeoff.sh, bench/arealight_tradeoff.sh,
# bench/indirect_tradeoff.sh, bench/sdf_shadow_tradeoff.sh, bench/shadow_tradeoff.sh):
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

# The reference of AOV $1 for "${common[@]}" at $refspp spp, into $ref (under $tmp), unless REF
# names one rendered before; says which on stderr.
reference_of() {
  if [[ -n "${REF:-}" ]]; then
    ref=$(realpath "$REF")
    echo "# reference: $ref" >&2
  else
    ref=$tmp/ref.exr
    local start=$(date +%s)
    "$rtlab" reference "${common[@]}" --aov "$1" --spp "$refspp" --out "$ref" 2>/dev/null
    echo "# reference: $refspp spp in $(( $(date +%s) - start )) s" >&2
  fi
}

# One CSV row: AOV $1 of technique $2 (setting label $3, then its --set options) over $frames
# frames, its cost and its error against $ref.
measure_row() {
  local aov=$1 t=$2 setting=$3; shift 3
  local out=$tmp/run.exr stats=$tmp/run.json
  "$rtlab" render "${common[@]}" -t "$t" --aov "$aov" --frames "$frames" --stats "$stats" --out "$out" "$@"
  echo "$scene,$t,$setting,$(cost "$stats" "$t"),$(metric "$ref" "$out" rmse),$(metric "$ref" "$out" max_abs)"
}

# The counter $2 of technique $3 in stats JSON $1 ("" when absent).
counter() {
  $py - "$1" "$2" "$3" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
print(next(("%g" % c["value"] for c in d.get("counters", []) if c["name"] == sys.argv[2] and c["technique"] == sys.argv[3]), ""))
PYEOF
}
