#!/usr/bin/env bash
# bloom's trade-off (techniques/bloom/README.md "Measured trade-off"; docs/performance.md): on `glow`
# at SIZE (default 1280x720), for each sigma and octave count n of the declared PSF, the exact
# reference (rtlab reference --aov bloom), then the bloom AOV of
#   gaussian with n octaves (the definition, up to its storage format),
#   gaussian with n/2 octaves (the cheaper Gaussian the mip method must beat),
#   mip with n/2 .. n octaves, in each storage format, Karis off (the definition) and on,
# each timed over FRAMES frames (median ms of the bloom passes, summed) and compared with the
# reference of (sigma, n): RMSE and RMSE relative to the reference's RMS. Writes CSV to stdout and
# the headline ratio per (sigma, n): the time of the cheapest mip setting whose error is at or below
# the gaussian method's at n/2 octaves, divided by that gaussian's time.
#   bash bench/bloom_tradeoff.sh [RTLAB] [SIZE] [FRAMES] [SIGMAS] [OCTAVES]
set -euo pipefail
rtlab=$(realpath "${1:-build/rtlab}") size=${2:-1280x720} frames=${3:-5}
sigmas=${4:-"1 2 4"} octaves=${5:-"4 6"}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common=(--scene glow --size "$size")

# The bloom passes' time: the sum of their median ms in a stats JSON.
bloom_ms() { $py -c 'import json,sys; print("%.3f" % sum(p["ms"] for p in json.load(open(sys.argv[1]))["passes"] if p["name"].startswith("bloom.")))' "$1"; }
rmse() { "$rtlab" compare "$1" "$2" | awk '$1 == "rmse" {print $2}'; }
rms() {
  $py - "$1" <<'EOF'
import struct, sys, math
f = open(sys.argv[1], 'rb'); kind = f.readline().strip(); w, h = map(int, f.readline().split()); scale = float(f.readline())
n = w * h * (3 if kind == b'PF' else 1)
v = struct.unpack(('<' if scale < 0 else '>') + '%df' % n, f.read(4 * n))
print('%.6g' % math.sqrt(sum(x * x for x in v) / n))
EOF
}

{
echo "method,sigma,octaves,reference_octaves,format,karis,ms,rmse,relative_rmse"
for s in $sigmas; do
  for n in $octaves; do
    ref=$tmp/ref_${s}_${n}.pfm
    "$rtlab" reference "${common[@]}" --aov bloom --set bloom.sigma="$s" --set bloom.octaves="$n" --out "$ref" 2>/dev/null
    refrms=$(rms "$ref")
    run() { # method octaves format karis
      local out=$tmp/run.pfm stats=$tmp/run.json
      "$rtlab" render "${common[@]}" -t bloom --aov bloom --frames "$frames" --stats "$stats" --out "$out" \
        --set bloom.method="$1" --set bloom.sigma="$s" --set bloom.octaves="$2" --set bloom.format="$3" --set bloom.karis="$4"
      local e; e=$(rmse "$out" "$ref")
      echo "$1,$s,$2,$n,$3,$4,$(bloom_ms "$stats"),$e,$($py -c "print('%.5f' % ($e / $refrms))")"
    }
    half=$((n / 2 > 0 ? n / 2 : 1))
    run gaussian "$n" rgba16f false
    run gaussian "$half" rgba16f false
    for ((m = half; m <= n; m++)); do
      for f in rgba16f r11g11b10f; do
        run mip "$m" "$f" false
        run mip "$m" "$f" true
      done
    done
  done
done
} | tee "$tmp/all.csv"
echo
echo "== headline: cheapest mip at or below the error of gaussian with n/2 octaves, time ratio"
$py - "$tmp/all.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for key in sorted({(r['sigma'], r['reference_octaves']) for r in rows}, key=lambda k: (float(k[0]), int(k[1]))):
    s, n = key
    group = [r for r in rows if (r['sigma'], r['reference_octaves']) == key]
    half = next(r for r in group if r['method'] == 'gaussian' and r['octaves'] == str(max(int(n) // 2, 1)))
    full = next(r for r in group if r['method'] == 'gaussian' and r['octaves'] == n)
    ok = [r for r in group if r['method'] == 'mip' and float(r['rmse']) <= float(half['rmse'])]
    best = min((r for r in group if r['method'] == 'mip'), key=lambda r: float(r['rmse']))
    line = 'sigma %s, n %s: gaussian n %.2f ms (rmse %s), gaussian n/2 %.2f ms (rmse %s); ' % (
        s, n, float(full['ms']), full['rmse'], float(half['ms']), half['rmse'])
    if ok:
        cheap = min(ok, key=lambda r: float(r['ms']))
        line += 'cheapest mip at or below: %s octaves %s karis %s %.2f ms (rmse %s) -> ratio %.3f' % (
            cheap['format'], cheap['octaves'], cheap['karis'], float(cheap['ms']), cheap['rmse'],
            float(cheap['ms']) / float(half['ms']))
    else:
        line += 'never reached: best mip %s octaves %s karis %s rmse %s at %.2f ms' % (
            best['format'], best['octaves'], best['karis'], best['rmse'], float(best['ms']))
    print(line)
EOF
