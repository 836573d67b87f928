#!/usr/bin/env bash
# Time to grade a class (docs/exercises.md "Measured"): N student folders of one exercise (a third
# untouched, a third with the shipped solution copied in, a third with the solution and a syntax
# error), graded by scripts/grade_class.sh JOBS at a time; then one grade of every exercise alone.
#   bash bench/grade_class.sh [RTLAB] [EXERCISE] [N] [JOBS]
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") id=${2:-pcss} n=${3:-30} jobs=${4:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
files() { /usr/bin/python3 -c 'import json,sys; print(" ".join(json.load(open(sys.argv[1]))["files"]))' "$1/exercise.json"; }
for ((i = 1; i <= n; i++)); do
  d=$tmp/class/s$(printf %03d "$i")
  "$rtlab" exercise new "$id" --out "$d" >/dev/null
  if ((i % 3 != 1)); then for f in $(files "$d"); do cp "$root/$f" "$d/$f"; done; fi
  if ((i % 3 == 0)); then f=$(files "$d" | cut -d' ' -f1); echo "not GLSL" >>"$d/$f"; fi
done
echo "== $n folders of '$id', $jobs at a time ($(nproc) cores)"
bash "$root/scripts/grade_class.sh" "$tmp/class" "$tmp/out" --rtlab "$rtlab" --jobs "$jobs" 2>&1 | tail -1
cut -d, -f7 "$tmp/out/grades.csv" | tail -n +2 | sort | uniq -c
echo "== one grade of each exercise (untouched folder), wall seconds"
for e in $("$rtlab" exercise list --json | /usr/bin/python3 -c 'import json,sys; print(" ".join(x["id"] for x in json.load(sys.stdin)["exercises"]))'); do
  "$rtlab" exercise new "$e" --out "$tmp/one/$e" >/dev/null
  views=$(/usr/bin/python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["views"]))' "$root/assets/exercises/$e.json")
  s=$(date +%s.%N); "$rtlab" exercise grade "$tmp/one/$e" --json >/dev/null; t=$(date +%s.%N)
  /usr/bin/python3 -c 'import sys; print("%-12s %d views  %.2f s" % (sys.argv[1], int(sys.argv[2]), float(sys.argv[4]) - float(sys.argv[3])))' "$e" "$views" "$s" "$t"
done
