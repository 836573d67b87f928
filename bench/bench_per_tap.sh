#!/usr/bin/env bash
# Cost of one depth tap per pixel in the estimators of hbao, ssao and pcss (never part of the
# tests), issue 12: each estimator pass is timed at a low and a high tap count with everything
# else fixed, and the difference is divided by the extra taps per pixel and the frame's pixels,
# so per-pixel work (set-up, noise, writes) cancels. Rounds are interleaved and the median is
# taken, so a change in the machine's load hits every setting alike.
#   hbao  `hbao.estimate` on cornell: 8 directions x 2 steps (16 taps) against 8 x 12 (96)
#   ssao  `ssao.estimate` on cornell: 8 samples against 48
#   pcss  `pcss.visibility` on contact: 8 blocker + 8 filter samples against 48 + 48
# Usage: bash bench/bench_per_tap.sh [path/to/rtlab]
#   env: SIZE=1280x720 FRAMES=5 ROUNDS=3; RTLAB_DATA_DIR selects the shaders (another checkout's
#   shaders/ to compare a change). Timing is rtlab's auto method: cpu-finish on llvmpipe,
#   GL timer queries on a hardware GPU (the stats say which).
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "bench_per_tap: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
size=${SIZE:-1280x720}
frames=${FRAMES:-5}
rounds=${ROUNDS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pixels=$(( ${size%x*} * ${size#*x} ))

# name scene technique pass taps_lo sets_lo taps_hi sets_hi
cases=(
  "hbao|cornell|hbao|hbao.estimate|16|hbao.directions=8 hbao.steps=2|96|hbao.directions=8 hbao.steps=12"
  "ssao|cornell|ssao|ssao.estimate|8|ssao.samples=8|48|ssao.samples=48"
  "pcss|contact|pcss|pcss.visibility|16|pcss.blocker_samples=8 pcss.filter_samples=8|96|pcss.blocker_samples=48 pcss.filter_samples=48"
)

# Prints the pass's median ms over the measured frames, and the timing method.
pass_ms() { # scene technique pass sets...
  local scene=$1 technique=$2 pass=$3
  shift 3
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  "$rtlab" render --scene "$scene" -t "$technique" --size "$size" --frames "$frames" "${sets[@]}" \
    --aov color --out "$work/frame.pfm" --stats "$work/stats.json" >/dev/null
  python3 - "$work/stats.json" "$pass" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
print(sum(p["ms"] for p in stats["passes"] if p["name"] == sys.argv[2]), stats["timing"], stats["renderer"])
PY
}

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

declare -A lo hi
renderer="" timing=""
for ((r = 0; r < rounds; ++r)); do
  for c in "${cases[@]}"; do
    IFS='|' read -r name scene technique pass tlo slo thi shi <<<"$c"
    read -r ms timing renderer <<<"$(pass_ms "$scene" "$technique" "$pass" $slo)"
    lo[$name]+="$ms "
    read -r ms timing renderer <<<"$(pass_ms "$scene" "$technique" "$pass" $shi)"
    hi[$name]+="$ms "
  done
done

echo "per-tap cost at $size, $frames frames, median of $rounds rounds; timing $timing; renderer $renderer"
printf '%-5s %-16s %10s %10s %16s\n' technique pass "ms (lo)" "ms (hi)" "ns/(pixel*tap)"
for c in "${cases[@]}"; do
  IFS='|' read -r name scene technique pass tlo slo thi shi <<<"$c"
  mlo=$(median ${lo[$name]})
  mhi=$(median ${hi[$name]})
  per=$(awk -v a="$mlo" -v b="$mhi" -v t0="$tlo" -v t1="$thi" -v n="$pixels" 'BEGIN {printf "%.4f", (b - a) * 1e6 / ((t1 - t0) * n)}')
  printf '%-5s %-16s %10.2f %10.2f %16s   (%s taps: %s; %s taps: %s)\n' "$name" "$pass" "$mlo" "$mhi" "$per" "$tlo" "$slo" "$thi" "$shi"
done
