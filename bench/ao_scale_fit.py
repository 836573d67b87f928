#!/usr/bin/env python3
"""Raw and scale-fitted RMSE of an ao image against its reference, both one-channel PFM as rtlab
writes them (`rtlab render --aov ao --out a.pfm`, `rtlab reference --aov ao --out r.pfm`, same
scene, size and settings). The fit is one least-squares scale s of the occlusion,
ao' = 1 - s (1 - ao), over surface pixels (background: 0 in both). Standard library only.
Usage: ao_scale_fit.py REFERENCE.pfm AO.pfm"""
import array
import math
import sys


def read_pfm(path):
    data = open(path, "rb").read()
    kind, size, scale, pixels = data.split(b"\n", 3)
    if kind != b"Pf" or float(scale) >= 0:
        sys.exit(f"ao_scale_fit: {path}: expected a little-endian one-channel PFM")
    width, height = map(int, size.split())
    values = array.array("f")
    values.frombytes(pixels[:width * height * 4])
    return values


if len(sys.argv) != 3:
    sys.exit(__doc__)
ref, ao = read_pfm(sys.argv[1]), read_pfm(sys.argv[2])
if len(ref) != len(ao):
    sys.exit("ao_scale_fit: the images differ in size")
pairs = [(r, a) for r, a in zip(ref, ao) if r > 0 or a > 0]
if not pairs:
    sys.exit("ao_scale_fit: no surface pixels")
raw = math.sqrt(sum((r - a) ** 2 for r, a in pairs) / len(pairs))
den = sum((1 - a) ** 2 for _, a in pairs)
s = sum((1 - a) * (1 - r) for r, a in pairs) / den if den > 0 else 1.0
fitted = math.sqrt(sum((r - (1 - s * (1 - a))) ** 2 for r, a in pairs) / len(pairs))
print(f"raw {raw:.4f} fitted {fitted:.4f} (occlusion scale {s:.2f})")
