#!/usr/bin/env python3
"""Writes a glTF scene for the R8 revealage picture of techniques/wboit/README.md: three groups of
N camera-facing layers (black base colour, white emission 1, so each layer's radiance is exactly 1),
alpha 0.0015 (below 1/510, which an R8 revealage loses), 0.004 and 0.02, at view depths 2 to 4 over
a black background; a directional light of intensity 0 and no ambient, so only the layers' emission
shows. Standard library only.
Usage: wboit_faint_layers.py OUT.gltf [N]"""
import base64
import json
import math
import struct
import sys

out = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 40
fov_y = 0.8
half_h = math.tan(fov_y / 2)
half_w = half_h * 16 / 9
groups = [(0.0015, -0.95, -0.35), (0.004, -0.3, 0.3), (0.02, 0.35, 0.95)]  # alpha, NDC x0, x1

positions, normals, indices, materials, meshes, nodes = [], [], [], [], [], []
for g, (alpha, x0, x1) in enumerate(groups):
    materials.append({"name": f"faint_{g}", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, alpha],
                      "metallicFactor": 0, "roughnessFactor": 1}, "emissiveFactor": [1, 1, 1],
                      "alphaMode": "BLEND", "doubleSided": True})
vertex_base = 0
primitives = []
for g, (alpha, x0, x1) in enumerate(groups):
    for k in range(count):
        z = 2.0 + 2.0 * k / max(count - 1, 1)
        first_index = len(indices)
        for (u, v) in ((x0, -0.9), (x1, -0.9), (x1, 0.9), (x0, 0.9)):
            positions += [u * half_w * z, v * half_h * z, -z]
            normals += [0, 0, 1]
        b = vertex_base
        indices += [b, b + 1, b + 2, b, b + 2, b + 3]
        vertex_base += 4
        primitives.append((g, first_index, 6))

pos_bytes = struct.pack(f"<{len(positions)}f", *positions)
nrm_bytes = struct.pack(f"<{len(normals)}f", *normals)
idx_bytes = struct.pack(f"<{len(indices)}I", *indices)
buffer = pos_bytes + nrm_bytes + idx_bytes
n_vertices = len(positions) // 3
accessors = [
    {"bufferView": 0, "componentType": 5126, "count": n_vertices, "type": "VEC3",
     "min": [min(positions[0::3]), min(positions[1::3]), min(positions[2::3])],
     "max": [max(positions[0::3]), max(positions[1::3]), max(positions[2::3])]},
    {"bufferView": 1, "componentType": 5126, "count": n_vertices, "type": "VEC3"},
]
for (g, first, n) in primitives:
    accessors.append({"bufferView": 2, "byteOffset": first * 4, "componentType": 5125, "count": n, "type": "SCALAR"})
    meshes.append({"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": len(accessors) - 1,
                                   "material": g}]})
    nodes.append({"mesh": len(meshes) - 1})
nodes.append({"camera": 0})
nodes.append({"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.7071068, 0, 0, 0.7071068]})
gltf = {
    "asset": {"version": "2.0", "generator": "bench/wboit_faint_layers.py"},
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 0.0}]}},
    "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
    "materials": materials, "accessors": accessors,
    "cameras": [{"type": "perspective", "perspective": {"yfov": fov_y, "aspectRatio": 16 / 9, "znear": 0.5, "zfar": 10}}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(pos_bytes)},
        {"buffer": 0, "byteOffset": len(pos_bytes), "byteLength": len(nrm_bytes)},
        {"buffer": 0, "byteOffset": len(pos_bytes) + len(nrm_bytes), "byteLength": len(idx_bytes)},
    ],
    "buffers": [{"byteLength": len(buffer),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
}
with open(out, "w") as f:
    json.dump(gltf, f)
