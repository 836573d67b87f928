#!/usr/bin/env bash
# Frame time of whole frames before and after a framework change (docs/performance.md,
# "Framework overhead"): `contact` with pcss and `cornell` with hbao at 1280x720, cpu-finish
# timing (glFinish brackets; llvmpipe's timer queries do not see rasterization). The two builds
# run alternately, ROUNDS times each, so that load on a shared machine hits both alike; the table
# gives the median of the per-run frame_ms medians and the after/before ratio.
#   bash bench/framework_overhead.sh BEFORE_RTLAB AFTER_RTLAB [ROUNDS] [FRAMES]
# Each binary finds its shaders next to it or in its source tree (RTLAB_DATA_DIR overrides).
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: bash bench/framework_overhead.sh BEFORE_RTLAB AFTER_RTLAB [ROUNDS] [FRAMES]" >&2
  exit 2
fi
before=$1 after=$2 rounds=${3:-5} frames=${4:-10}
for bin in "$before" "$after"; do
  [[ -x $bin ]] || { echo "framework_overhead: error: '$bin' is not an executable" >&2; exit 3; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
configs=("contact pcss" "cornell hbao")
frame_ms() { # binary scene technique -> frame_ms of one run
  "$1" render --scene "$2" -t "$3" --size 1280x720 --frames "$frames" --timing cpu-finish \
    --out "$tmp/frame.png" --stats "$tmp/stats.json" >/dev/null
  /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["frame_ms"])' "$tmp/stats.json"
}
declare -A runs
for ((r = 0; r < rounds; r++)); do
  for c in "${configs[@]}"; do
    set -- $c
    runs["$1 $2 before"]+=" $(frame_ms "$before" "$1" "$2")"
    runs["$1 $2 after"]+=" $(frame_ms "$after" "$1" "$2")"
  done
done
median() { printf '%s\n' $1 | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
printf '| scene + technique | before ms | after ms | after/before |\n|---|---|---|---|\n'
for c in "${configs[@]}"; do
  b=$(median "${runs["$c before"]}") a=$(median "${runs["$c after"]}")
  printf '| %s | %.1f | %.1f | %.3f |\n' "$c" "$b" "$a" "$(awk -v a="$a" -v b="$b" 'BEGIN {print a / b}')"
done
