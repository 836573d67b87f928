#!/usr/bin/env python3
"""RMSE against ms for an ao sweep repeated several times (rtlab sweep results.csv files of the
same plan): the median ms of each point over the runs (the RMSE is the same in every run), one
series per combination of the keys in SERIES, each point labelled with LABEL's value; writes an
SVG chart and prints the median table as CSV. Standard library only.
Usage: ao_chart.py OUT.svg TITLE SUBTITLE SERIES(k1,k2) LABEL run1/results.csv [run2/results.csv ...]"""
import csv
import math
import statistics
import sys

if len(sys.argv) < 7:
    sys.exit(__doc__)
out, title, subtitle, series_keys, label_key = sys.argv[1:6]
series_keys = series_keys.split(",")
runs = [list(csv.DictReader(open(path))) for path in sys.argv[6:]]
points = []
for rows in zip(*runs):
    if len({r["rmse"] for r in rows}) != 1:
        print(f"warning: rmse differs between runs: {[r['rmse'] for r in rows]}", file=sys.stderr)
    ms = [float(r["ms"]) for r in rows]
    points.append(dict(rows[0], ms_median=statistics.median(ms), ms_runs=ms))

keys = [k for k in runs[0][0].keys() if k not in ("technique", "ms", "frame_ms", "psnr", "ssim", "flip", "timing")]
print(",".join(keys[:-1] + ["ms_median", "ms_runs", "rmse"]))
for p in points:
    print(",".join([p[k] for k in keys[:-1]] + ["%.1f" % p["ms_median"], "/".join("%.1f" % m for m in p["ms_runs"]),
                                                  "%.4f" % float(p["rmse"])]))

W, H, L, R, T, B = 720, 380, 62, 200, 52, 44
xs = [p["ms_median"] for p in points]
ys = [float(p["rmse"]) for p in points]
x0, x1 = math.log10(min(xs) / 1.2), math.log10(max(xs) * 1.2)
y1 = max(ys) * 1.1
y0 = max(0.0, min(ys) - (y1 - min(ys)) * 0.15)
px = lambda x: L + (math.log10(x) - x0) / (x1 - x0) * (W - L - R)
py = lambda y: T + (1 - (y - y0) / (y1 - y0)) * (H - T - B)
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="sans-serif">',
       f'<rect width="{W}" height="{H}" fill="#fff"/>',
       f'<text x="{L}" y="17" font-size="13" font-weight="bold">{title}</text>',
       f'<text x="{L}" y="33" font-size="11" fill="#444">{subtitle}</text>',
       f'<rect x="{L}" y="{T}" width="{W - L - R}" height="{H - T - B}" fill="#fcfcfc" stroke="#999"/>']
for tick in [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000]:
    if x0 <= math.log10(tick) <= x1:
        svg.append(f'<line x1="{px(tick):.1f}" y1="{T}" x2="{px(tick):.1f}" y2="{H - B}" stroke="#e4e4e4"/>'
                   f'<text x="{px(tick):.1f}" y="{H - B + 14}" font-size="11" text-anchor="middle">{tick}</text>')
base = 10 ** math.floor(math.log10((y1 - y0) / 10))
step = next(base * m for m in (1, 2, 5, 10, 20, 50, 100) if (y1 - y0) / (base * m) <= 6)
y = math.ceil(y0 / step) * step
while y <= y1:
    svg.append(f'<line x1="{L}" y1="{py(y):.1f}" x2="{W - R}" y2="{py(y):.1f}" stroke="#e4e4e4"/>'
               f'<text x="{L - 6}" y="{py(y) + 4:.1f}" font-size="11" text-anchor="end">{y:.3g}</text>')
    y += step
svg.append(f'<text x="{(L + W - R) / 2}" y="{H - 8}" font-size="11" text-anchor="middle">ms (median of {len(runs)} runs, log scale)</text>')
svg.append(f'<text x="14" y="{(T + H - B) / 2}" font-size="11" text-anchor="middle" transform="rotate(-90 14 {(T + H - B) / 2})">ao RMSE</text>')
colors = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"]
groups = {}
for p in points:
    groups.setdefault(tuple(p[k] for k in series_keys), []).append(p)
for i, (name, group) in enumerate(groups.items()):
    c = colors[i % len(colors)]
    path = " ".join(f"{px(p['ms_median']):.1f},{py(float(p['rmse'])):.1f}" for p in group)
    svg.append(f'<polyline points="{path}" fill="none" stroke="{c}" stroke-width="1.5"/>')
    for p in group:
        x, y = px(p["ms_median"]), py(float(p["rmse"]))
        svg.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3" fill="{c}"/>'
                   f'<text x="{x + 4:.1f}" y="{y - 4:.1f}" font-size="9" fill="{c}">{p[label_key]}</text>')
    legend = ", ".join(f"{k.split('.')[-1]}={v}" for k, v in zip(series_keys, name))
    svg.append(f'<rect x="{W - R + 10}" y="{T + 18 * i}" width="10" height="10" fill="{c}"/>'
               f'<text x="{W - R + 24}" y="{T + 18 * i + 9}" font-size="10">{legend}</text>')
svg.append(f'<text x="{W - R + 10}" y="{T + 18 * len(groups) + 12}" font-size="10" fill="#444">labels: {label_key.split(".")[-1]}</text>')
svg.append("</svg>")
open(out, "w").write("\n".join(svg) + "\n")
