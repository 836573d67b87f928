#!/usr/bin/env python3
"""Writes assets/sample.gltf: a small scene for the README's `--scene` example (assets/README.md).

A 10x10 ground, three boxes (one standing, one turned, one lifted on a pillar so its shadow
detaches), a sphere, a KHR_lights_punctual spot light whose emitter radius is in its extras, a
perspective camera, and the scene's ambient radiance in its extras (docs/scene-format.md).
The geometry is generated here and embedded as a base64 buffer, so the file stands alone.
Deterministic: running it again writes the same bytes. Python 3 standard library only.

    python3 scripts/make_sample_gltf.py [OUT]   (default: assets/sample.gltf)
"""
import base64
import json
import math
import struct
import sys
from pathlib import Path


def box():
    """Unit cube centred at the origin: 24 vertices (flat normals), 12 triangles, CCW outside."""
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u = [0.0, 0.0, 0.0]
            v = [0.0, 0.0, 0.0]
            u[(axis + 1) % 3] = 1.0
            v[(axis + 2) % 3] = 1.0
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                pos.append([0.5 * (n[k] + a * u[k] + b * v[k]) for k in range(3)])
                nrm.append(n)
            # u x v = n for sign +1: keep CCW; flip the winding for the negative face.
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return pos, nrm, idx


def plane():
    """Unit square in y = 0 facing +y."""
    pos = [[-0.5, 0, -0.5], [-0.5, 0, 0.5], [0.5, 0, 0.5], [0.5, 0, -0.5]]
    return pos, [[0.0, 1.0, 0.0]] * 4, [0, 1, 2, 0, 2, 3]


def sphere(rings=32, segments=48):
    """Unit-radius UV sphere, smooth normals."""
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            p = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            pos.append(p)
            nrm.append(p)
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r != 0:
                idx += [a, b, a + 1]
            if r != rings - 1:
                idx += [a + 1, b, b + 1]
    return pos, nrm, idx


def quat_from_basis(x, y, z):
    """Rotation quaternion [x, y, z, w] of the matrix with columns x, y, z (orthonormal)."""
    m00, m11, m22 = x[0], y[1], z[2]
    t = m00 + m11 + m22
    if t > 0:
        s = math.sqrt(t + 1.0) * 2
        return [(y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, 0.25 * s]
    if m00 > m11 and m00 > m22:
        s = math.sqrt(1.0 + m00 - m11 - m22) * 2
        return [0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s]
    if m11 > m22:
        s = math.sqrt(1.0 + m11 - m00 - m22) * 2
        return [(y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s]
    s = math.sqrt(1.0 + m22 - m00 - m11) * 2
    return [(z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s]


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def look_at(eye, target):
    """Rotation of a node at `eye` whose -Z axis points at `target` (cameras and spot lights)."""
    back = normalize([e - t for e, t in zip(eye, target)])  # +Z points away from the target
    right = normalize(cross([0.0, 1.0, 0.0], back))
    up = cross(back, right)
    return [round(c, 6) for c in quat_from_basis(right, up, back)]


def yaw(degrees):
    h = math.radians(degrees) / 2
    return [0.0, round(math.sin(h), 6), 0.0, round(math.cos(h), 6)]


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "assets" / "sample.gltf"
    blob = bytearray()
    views, accessors, meshes = [], [], []

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data)
        return len(views) - 1

    def add_mesh(name, geometry, material):
        pos, nrm, idx = geometry
        p = add_view(b"".join(struct.pack("<3f", *v) for v in pos), 34962)
        lo = [min(v[k] for v in pos) for k in range(3)]
        hi = [max(v[k] for v in pos) for k in range(3)]
        accessors.append({"bufferView": p, "componentType": 5126, "count": len(pos), "type": "VEC3",
                          "min": [round(c, 6) for c in lo], "max": [round(c, 6) for c in hi]})
        n = add_view(b"".join(struct.pack("<3f", *v) for v in nrm), 34962)
        accessors.append({"bufferView": n, "componentType": 5126, "count": len(nrm), "type": "VEC3"})
        i = add_view(struct.pack("<%dH" % len(idx), *idx), 34963)
        accessors.append({"bufferView": i, "componentType": 5123, "count": len(idx), "type": "SCALAR"})
        a = len(accessors)
        meshes.append({"name": name, "primitives": [
            {"attributes": {"POSITION": a - 3, "NORMAL": a - 2}, "indices": a - 1, "material": material}]})
        return len(meshes) - 1

    def material(name, rgb, roughness):
        return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": rgb + [1.0], "metallicFactor": 0.0,
                                                       "roughnessFactor": roughness}}

    materials = [material("ground", [0.7, 0.7, 0.7], 0.9), material("red", [0.75, 0.2, 0.15], 0.6),
                 material("blue", [0.2, 0.35, 0.75], 0.5), material("white", [0.85, 0.85, 0.8], 0.35)]
    ground = add_mesh("ground", plane(), 0)
    cube_red = add_mesh("box_red", box(), 1)
    cube_blue = add_mesh("box_blue", box(), 2)
    cube_white = add_mesh("box_white", box(), 3)
    ball = add_mesh("sphere", sphere(), 3)

    nodes = [
        {"name": "ground", "mesh": ground, "scale": [10, 1, 10]},
        {"name": "box_standing", "mesh": cube_red, "translation": [-1.6, 0.6, 0.2], "scale": [0.8, 1.2, 0.8]},
        {"name": "box_turned", "mesh": cube_blue, "translation": [0.3, 0.35, 1.4], "rotation": yaw(35),
         "scale": [1.4, 0.7, 0.7]},
        {"name": "pillar", "mesh": cube_white, "translation": [1.9, 0.5, -1.2], "scale": [0.15, 1.0, 0.15]},
        {"name": "box_lifted", "mesh": cube_white, "translation": [1.9, 1.15, -1.2], "rotation": yaw(-20),
         "scale": [0.9, 0.3, 0.9]},
        {"name": "sphere", "mesh": ball, "translation": [-0.2, 0.7, -0.9], "scale": [0.7, 0.7, 0.7]},
        {"name": "key_light", "translation": [3.5, 6.5, 3.0], "rotation": look_at([3.5, 6.5, 3.0], [0, 0, 0]),
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "camera", "camera": 0, "translation": [0.0, 4.0, 8.0],
         "rotation": look_at([0.0, 4.0, 8.0], [0.0, 0.4, 0.0])},
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "rtlab scripts/make_sample_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "key", "type": "spot", "color": [1.0, 0.96, 0.9], "intensity": 190.0,
             "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.8}, "extras": {"radius": 0.15}}]}},
        "scene": 0,
        "scenes": [{"name": "sample", "nodes": list(range(len(nodes))), "extras": {"ambient": [0.08, 0.08, 0.1]}}],
        "nodes": nodes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.1, "zfar": 100.0}}],
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(gltf, indent=1) + "\n")
    print(f"wrote {out} ({out.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
