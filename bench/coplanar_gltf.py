#!/usr/bin/env python3
"""Writes a small glTF scene of coplanar transparent layers for techniques/depth_peeling/README.md
("Coplanar layers"): an opaque grey wall, and in front of it, in one plane, a red and a green layer
(alpha 0.5) that overlap in the middle; the left pair are camera-facing (their fragments' depths are
bitwise equal), the right pair share a plane turned 40 degrees about the vertical (their depths
differ by rounding). A blue layer (alpha 0.5) lies behind both pairs. Standard library only.
Usage: coplanar_gltf.py OUT.gltf"""
import base64
import json
import math
import struct
import sys


def quad(center, half_u, half_v):
    """Positions, normals and indices of a rectangle center +- half_u +- half_v."""
    cx, cy, cz = center
    corners = []
    for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        corners.append(tuple(c + su * u + sv * v for c, u, v in zip(center, half_u, half_v)))
    n = (half_u[1] * half_v[2] - half_u[2] * half_v[1], half_u[2] * half_v[0] - half_u[0] * half_v[2],
         half_u[0] * half_v[1] - half_u[1] * half_v[0])
    length = math.sqrt(sum(x * x for x in n))
    return corners, tuple(x / length for x in n), [0, 1, 2, 0, 2, 3]


def main(out):
    c, s = math.cos(math.radians(40)), math.sin(math.radians(40))
    # (name, material, center, half_u, half_v)
    quads = [
        ("wall", 0, (0, 0, -6), (8, 0, 0), (0, 5, 0)),
        ("blue", 3, (0, -0.2, -3.5), (3.2, 0, 0), (0, 0.6, 0)),
        ("facing_red", 1, (-1.9, 0.25, -2), (0.6, 0, 0), (0, 0.8, 0)),
        ("facing_green", 2, (-1.3, -0.25, -2), (0.6, 0, 0), (0, 0.8, 0)),
        ("turned_red", 1, (1.3 - 0.3 * c, 0.25, -2 - 0.3 * s), (0.6 * c, 0, 0.6 * s), (0, 0.8, 0)),
        ("turned_green", 2, (1.3 + 0.3 * c, -0.25, -2 + 0.3 * s), (0.6 * c, 0, 0.6 * s), (0, 0.8, 0)),
    ]
    blob = b""
    views, accessors, meshes, nodes = [], [], [], []
    for name, material, center, hu, hv in quads:
        corners, normal, indices = quad(center, hu, hv)
        for kind, data, count, target in (
                ("VEC3", b"".join(struct.pack("<3f", *p) for p in corners), 4, 34962),
                ("VEC3", b"".join(struct.pack("<3f", *normal) for _ in corners), 4, 34962),
                ("SCALAR", struct.pack("<6H", *indices), 6, 34963)):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
            acc = {"bufferView": len(views) - 1, "componentType": 5126 if kind == "VEC3" else 5123,
                   "count": count, "type": kind}
            if len(accessors) % 3 == 0:  # POSITION needs its bounds
                acc["min"] = [min(p[i] for p in corners) for i in range(3)]
                acc["max"] = [max(p[i] for p in corners) for i in range(3)]
            accessors.append(acc)
            blob += data + b"\0" * (-len(data) % 4)
        base = len(accessors) - 3
        meshes.append({"name": name, "primitives": [
            {"attributes": {"POSITION": base, "NORMAL": base + 1}, "indices": base + 2, "material": material}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    def layer(name, rgb):
        return {"name": name, "alphaMode": "BLEND", "doubleSided": True,
                "pbrMetallicRoughness": {"baseColorFactor": list(rgb) + [0.5], "metallicFactor": 0, "roughnessFactor": 0.8}}

    gltf = {
        "asset": {"version": "2.0", "generator": "rtlab bench/coplanar_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3}]}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes) + 2))}],
        "nodes": nodes + [
            {"name": "camera", "camera": 0, "translation": [0, 0, 2]},
            {"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.17, 0.17, 0, 0.97]},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(45), "znear": 0.1, "zfar": 20}}],
        "materials": [
            {"name": "wall", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0}},
            layer("red", (0.9, 0.1, 0.1)), layer("green", (0.1, 0.9, 0.1)), layer("blue", (0.1, 0.2, 0.95)),
        ],
        "meshes": meshes,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
