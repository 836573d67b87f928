#!/usr/bin/env bash
# hbao against ssao on `cornell` at 1280x720 (never part of the tests), issue 6:
#   1. errors: one `rtlab sweep` (--frames 1) of hbao over directions x steps x half resolution
#      and of ssao with 64 samples, ao RMSE against the ray-traced reference (--spp, default 1024);
#   2. times: hbao at its defaults, ssao with 64 samples and the cheapest hbao settings whose
#      RMSE is at or below ssao-64's, each rendered `--frames 5` in ROUNDS rounds with the order
#      turned every round (interleaved, so that a change in the machine's load hits every setting
#      alike); `ms` is the median over the rounds of the technique's passes summed (each a median
#      over the 5 frames);
#      (the TIMED with the fewest taps per frame pixel, plus the cheapest at full resolution);
#   3. the cheapest qualifying hbao setting by measured time, and its time over ssao-64's.
# Usage: bash bench/bench_hbao_sweep.sh [path/to/rtlab]
#   env: ROUNDS=5 SPP=1024 TIMED=6; KEEP=1 keeps the work folder (sweep, stats) and prints it
# On Mesa's llvmpipe timing is cpu-finish on a CPU shared with other work: compare rows of one
# run only.
set -euo pipefail
cd "$(dirname "$0")/.."
rtlab=$(realpath "${1:-build/rtlab}")
[ -x "$rtlab" ] || { echo "bench_hbao_sweep: no rtlab binary at $rtlab (cmake --build build first)" >&2; exit 1; }
rounds=${ROUNDS:-5}
spp=${SPP:-1024}
timed=${TIMED:-6} # qualifying hbao settings timed, the fewest taps first
work=$(mktemp -d)
if [ -n "${KEEP:-}" ]; then echo "work folder: $work"; else trap 'rm -rf "$work"' EXIT; fi
export RTLAB_CACHE_DIR="$work/cache"
frame=(--scene cornell --size 1280x720)

echo "hbao and ssao on cornell, 1280x720, reference $spp spp; $("$rtlab" --version), $(nproc) cores"
"$rtlab" sweep "${frame[@]}" --frames 1 --spp "$spp" -t hbao,ssao \
  --vary hbao.directions=2,3,4,6,8 --vary hbao.steps=2,3,4,6,8 --vary hbao.half_resolution=false,true \
  --vary ssao.samples=64 --out "$work/errors" 2>"$work/log" || { cat "$work/log" >&2; exit 1; }
head -1 "$work/errors/results.csv" | grep -q '^technique,hbao.directions,hbao.steps,hbao.half_resolution,ssao.samples,ms,frame_ms,rmse' ||
  { echo "bench_hbao_sweep: unexpected results.csv columns" >&2; exit 1; }

# settings.txt: label<TAB>rmse<TAB>rtlab options, for the defaults, ssao-64 and the candidates.
python3 - "$work/errors/results.csv" "$timed" >"$work/settings.txt" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ssao = next(r for r in rows if r["technique"] == "ssao")
limit = float(ssao["rmse"])
hbao = [r for r in rows if r["technique"] == "hbao"]
def opts(r):
    return (f"-t hbao --set hbao.directions={r['hbao.directions']} --set hbao.steps={r['hbao.steps']} "
            f"--set hbao.half_resolution={r['hbao.half_resolution']}")
def label(r):
    return f"hbao {r['hbao.directions']}x{r['hbao.steps']}" + (" half" if r["hbao.half_resolution"] == "true" else "")
print(f"ssao 64\t{ssao['rmse']}\t-t ssao --set ssao.samples=64")
default = next(r for r in hbao if (r["hbao.directions"], r["hbao.steps"], r["hbao.half_resolution"]) == ("8", "6", "false"))
print(f"hbao defaults (8x6)\t{default['rmse']}\t-t hbao")
ok = [r for r in hbao if float(r["rmse"]) <= limit]
# Fewest taps per frame pixel first (directions x steps, a quarter at half resolution).
cost = lambda r: int(r["hbao.directions"]) * int(r["hbao.steps"]) / (4 if r["hbao.half_resolution"] == "true" else 1)
timed = sorted(ok, key=cost)[:int(sys.argv[2])]
full = [r for r in sorted(ok, key=cost) if r["hbao.half_resolution"] == "false"][:1]
for r in timed + [r for r in full if r not in timed]:
    print(f"{label(r)}\t{r['rmse']}\t{opts(r)}")
print(f"# {len(ok)} of {len(hbao)} hbao settings have rmse <= ssao-64's {limit:.5f}", file=sys.stderr)
PY
echo
echo "all hbao settings (--frames 1; ms is a single frame, for orientation only):"
echo "directions,steps,half_resolution,ms,rmse"
awk -F, 'NR > 1 && $1 == "hbao" { printf "%s,%s,%s,%.1f,%.5f\n", $2, $3, $4, $6, $8 }' "$work/errors/results.csv"

cat >"$work/summary.py" <<'PY'
import statistics, sys
rows = []
for line in sys.stdin:
    label, rmse, times = line.rstrip("\n").split("\t")
    t = [float(x) for x in times.split()]
    rows.append((label, float(rmse), statistics.median(t), t))
print("%-22s %8s %8s  %s" % ("setting", "rmse", "ms", "ms per round"))
for label, rmse, ms, t in rows:
    print("%-22s %8.5f %8.1f  %s" % (label, rmse, ms, " ".join("%.0f" % x for x in t)))
ssao, rest = rows[0], rows[2:]
if not rest:
    best = min(rows[1:], key=lambda r: r[1])
    print("no hbao setting reaches ssao-64's rmse %.5f; the lowest is %s at %.5f" % (ssao[1], best[0], best[1]))
else:
    best = min(rest, key=lambda r: r[2])
    print("cheapest hbao with rmse <= ssao-64's (%.5f): %s, %.1f ms, rmse %.5f; ssao-64 %.1f ms; ratio %.3f"
          % (ssao[1], best[0], best[2], best[1], ssao[2], best[2] / ssao[2]))
PY
mapfile -t settings < <(grep -v '^#' "$work/settings.txt")
n=${#settings[@]}
for ((round = 0; round < rounds; ++round)); do
  for ((j = 0; j < n; ++j)); do
    i=$(( (j + round) % n ))
    IFS=$'\t' read -r _ _ options <<<"${settings[$i]}"
    # shellcheck disable=SC2086 # options are words
    "$rtlab" render "${frame[@]}" --frames 5 $options --aov ao --out "$work/ao.exr" --stats "$work/s.json" 2>>"$work/log"
    python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(sum(p["ms"] for p in d["passes"] if p["technique"]), d["timing"])' \
      "$work/s.json" >>"$work/times_$i.txt"
  done
done

echo
echo "timed interleaved: $rounds rounds of --frames 5 (ms: median over rounds of the technique's passes)"
for ((i = 0; i < n; ++i)); do
  IFS=$'\t' read -r label rmse _ <<<"${settings[$i]}"
  printf '%s\t%s\t%s\n' "$label" "$rmse" "$(cut -d' ' -f1 "$work/times_$i.txt" | tr '\n' ' ')"
done | python3 "$work/summary.py"
echo "timing method: $(cut -d' ' -f2 "$work/times_0.txt" | sort -u | tr '\n' ' ')"
