#!/usr/bin/env python3
"""Writes the generated part of the fuzz seed corpora (docs/testing.md "Fuzzing"): small valid
inputs of every format, each exercising a feature (glTF materials, lights, cameras, textures in a
.glb; PFM of both byte orders; PNG gray/RGB/alpha/palette/16-bit; uncompressed EXR; presets,
scripts, bookmark files and command lines). The rest of each corpus is copied from the assets and
docs (assets/sample.gltf, assets/lecture/*.json, docs/images/viewer_shots.json). Deterministic:
rerunning it rewrites the same files.

Usage: tests/fuzz/make_seeds.py   (from the repository root)
"""
import base64, json, os, shutil, struct, zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS = os.path.join(ROOT, "tests", "fuzz", "corpus")


def put(target, name, data):
    d = os.path.join(CORPUS, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def copy(target, src, name=None):
    d = os.path.join(CORPUS, target)
    os.makedirs(d, exist_ok=True)
    shutil.copyfile(os.path.join(ROOT, src), os.path.join(d, name or os.path.basename(src)))


# ---- PNG ----
def png(width, height, color_type, bit_depth, rows, palette=None, trns=None):
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))
    raw = b"".join(b"\0" + r for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0))
    if palette: out += chunk(b"PLTE", palette)
    if trns: out += chunk(b"tRNS", trns)
    return out + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")

put("png", "gray_3x2.png", png(3, 2, 0, 8, [bytes([0, 128, 255]), bytes([10, 20, 30])]))
put("png", "rgb_2x2.png", png(2, 2, 2, 8, [bytes([255, 0, 0, 0, 255, 0]), bytes([0, 0, 255, 9, 9, 9])]))
put("png", "rgba_2x1.png", png(2, 1, 6, 8, [bytes([1, 2, 3, 4, 5, 6, 7, 8])]))
put("png", "gray_alpha_1x2.png", png(1, 2, 4, 8, [bytes([7, 255]), bytes([8, 0])]))
put("png", "palette_2x2.png", png(2, 2, 3, 8, [bytes([0, 1]), bytes([1, 0])], palette=bytes([255, 0, 0, 0, 0, 255]), trns=bytes([255, 128])))
put("png", "gray16_2x1.png", png(2, 1, 0, 16, [bytes([0x12, 0x34, 0xff, 0xff])]))
put("png", "gray1_8x1.png", png(8, 1, 0, 1, [bytes([0b10110010])]))
copy("png", "assets/ltc/fit_error.png")

# ---- PFM ----
def pfm(channels, width, height, little, values):
    head = ("PF" if channels == 3 else "Pf") + "\n%d %d\n%s\n" % (width, height, "-1.0" if little else "1.0")
    return head.encode() + struct.pack(("<" if little else ">") + "%df" % len(values), *values)

put("pfm", "rgb_le_2x2.pfm", pfm(3, 2, 2, True, [0.1 * i for i in range(12)]))
put("pfm", "gray_be_3x1.pfm", pfm(1, 3, 1, False, [0.5, 1.5, -2.0]))
put("pfm", "gray_le_1x1_inf.pfm", pfm(1, 1, 1, True, [float("inf")]))
put("pfm", "rgb_be_1x2.pfm", pfm(3, 1, 2, False, [1, 2, 3, 4, 5, 6]))

# ---- EXR (scanline, uncompressed, 32-bit float channels; OpenEXR file layout) ----
def exr(width, height, channels, pixels):
    def attr(name, kind, payload):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(payload)) + payload
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in channels) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (attr("channels", "chlist", chlist) + attr("compression", "compression", b"\0") +
              attr("dataWindow", "box2i", box) + attr("displayWindow", "box2i", box) +
              attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    start = 8 + len(header) + 8 * height
    lines, offsets = b"", []
    for y in range(height):
        data = b"".join(struct.pack("<%df" % width, *[pixels[c][y * width + x] for x in range(width)]) for c in range(len(channels)))
        offsets.append(start + len(lines))
        lines += struct.pack("<ii", y, len(data)) + data
    return struct.pack("<ii", 20000630, 2) + header + struct.pack("<%dQ" % height, *offsets) + lines

put("exr", "y_2x2.exr", exr(2, 2, ["Y"], [[0.0, 0.25, 0.5, 1.0]]))
put("exr", "rgb_2x1.exr", exr(2, 1, ["B", "G", "R"], [[0.1, 0.2], [0.3, 0.4], [0.5, 0.6]]))
put("exr", "rgba_1x2.exr", exr(1, 2, ["A", "B", "G", "R"], [[1, 0], [0.1, 0.2], [0.3, 0.4], [0.5, 0.6]]))

# ---- glTF / GLB ----
def gltf_triangle(extra_nodes=(), material=None, camera=False, light=None, indexed=False, image=None):
    pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    nrm = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
    uv = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    buf = pos + nrm + uv + (idx if indexed else b"")
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
             {"buffer": 0, "byteOffset": 72, "byteLength": 24}]
    acc = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
           {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
           {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}]
    prim = {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}
    if indexed:
        views.append({"buffer": 0, "byteOffset": 96, "byteLength": 6})
        acc.append({"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"})
        prim["indices"] = 3
    g = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
         "nodes": [{"mesh": 0, "translation": [0, 0.5, 0]}], "meshes": [{"primitives": [prim]}],
         "accessors": acc, "bufferViews": views, "buffers": [{"byteLength": len(buf)}]}
    if material is not None:
        g["materials"] = [material]
        prim["material"] = 0
    if camera:
        g["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
        g["nodes"].append({"camera": 0, "translation": [0, 1, 4]})
        g["scenes"][0]["nodes"].append(len(g["nodes"]) - 1)
    if light is not None:
        g["extensionsUsed"] = ["KHR_lights_punctual"]
        g["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        g["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.7071068, 0, 0, 0.7071068]})
        g["scenes"][0]["nodes"].append(len(g["nodes"]) - 1)
    for n in extra_nodes:
        g["nodes"].append(n)
        g["scenes"][0]["nodes"].append(len(g["nodes"]) - 1)
    if image is not None:
        while len(buf) % 4: buf += b"\0"
        views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(image)})
        g["images"] = [{"bufferView": len(views) - 1, "mimeType": "image/png"}]
        g["textures"] = [{"source": 0, "sampler": 0}]
        g["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33648}]
        buf += image
        g["buffers"][0]["byteLength"] = len(buf)
    return g, buf

def as_gltf(g, buf):
    g = json.loads(json.dumps(g))
    g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
    return json.dumps(g, indent=1)

def as_glb(g, buf):
    j = json.dumps(g, separators=(",", ":")).encode()
    j += b" " * (-len(j) % 4)
    buf += b"\0" * (-len(buf) % 4)
    body = struct.pack("<I4s", len(j), b"JSON") + j + struct.pack("<I4s", len(buf), b"BIN\0") + buf
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body

tex = png(2, 2, 2, 8, [bytes([255, 0, 0, 0, 255, 0]), bytes([0, 0, 255, 9, 9, 9])])
variants = {
    "triangle": gltf_triangle(),
    "indexed_material": gltf_triangle(indexed=True, material={"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.2, 1], "metallicFactor": 0.1, "roughnessFactor": 0.7}, "emissiveFactor": [0.1, 0, 0], "alphaMode": "MASK", "alphaCutoff": 0.4, "doubleSided": True, "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2}}}),
    "camera_spot": gltf_triangle(camera=True, light={"type": "spot", "intensity": 80, "range": 0, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}, "extras": {"radius": 0.1}}),
    "point_children": gltf_triangle(light={"type": "point", "intensity": 50, "color": [1, 0.9, 0.8]}, extra_nodes=[{"name": "group", "children": [0], "scale": [2, 2, 2]}]),
    "area_light_ambient": gltf_triangle(extra_nodes=[{"name": "panel", "translation": [0, 3, 0], "rotation": [-0.7071068, 0, 0, 0.7071068], "extras": {"rtlab_area_light": {"width": 2, "height": 1, "color": [1, 1, 1], "intensity": 10, "two_sided": True}}}]),
    "textured": gltf_triangle(material={"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 0}}, "normalTexture": {"index": 0, "scale": 0.5}, "occlusionTexture": {"index": 0, "strength": 0.5}}, image=tex),
    "directional": gltf_triangle(light={"type": "directional", "intensity": 3, "extras": {"angle": 1.5}}),
}
variants["point_children"][0]["scenes"][0]["nodes"].remove(0)  # node 0 is the group's child
variants["area_light_ambient"][0]["scenes"][0]["extras"] = {"ambient": [0.08, 0.08, 0.1]}
for name, (g, buf) in variants.items():
    put("gltf", name + ".gltf", as_gltf(g, buf))
    put("glb", name + ".glb", as_glb(g, buf))
copy("gltf", "assets/sample.gltf")

# ---- presets ----
put("preset", "full.json", json.dumps({"schema": 1, "scene": "contact", "techniques": ["sh", "occ"],
    "params": {"sh.samples": 32, "sh.bias": 0.01, "sh.pcf": False, "sh.filter": "poisson", "occ.radius": 1.5,
               "occ.axis": [0, 0, 1], "occ.tint": [1, 0.5, 0.25], "camera.fov": 50, "camera.position": [0, 2, 6],
               "light0.intensity": 2}}, indent=1))
put("preset", "empty.json", "{}")
put("preset", "scene_only.json", '{"schema": 1, "scene": "sample.gltf"}')
put("preset", "techniques_none.json", '{"techniques": []}')

# ---- viewer scripts ----
script = [
    {"action": "technique", "stage": "shadow", "id": "sh"},
    {"action": "technique", "stage": "ao", "id": "off"},
    {"action": "set", "key": "sh.samples", "value": 32},
    {"action": "reset", "key": "sh.samples"},
    {"action": "camera", "position": [0, 2.5, 6], "target": [0, 0.5, 0], "fov": 40},
    {"action": "orbit", "yaw": 30, "pitch": -5},
    {"action": "view", "aov": "visibility", "mode": "pip", "min": 0, "max": 1, "false_color": True},
    {"action": "view", "aov": "sh.depth", "mode": "full"},
    {"action": "compare", "mode": "reference", "divider": 0.5},
    {"action": "snapshot"},
    {"action": "wait", "frames": 5},
    {"action": "wait_samples", "samples": 64, "timeout_s": 120},
    {"action": "screenshot", "file": "shot.png"},
    {"action": "save_preset", "file": "p.json"},
    {"action": "load_preset", "file": "p.json"},
    {"action": "report", "file": "r.json"},
    {"action": "render_scale", "value": 0.5},
    {"action": "lecture", "on": True},
    {"action": "bookmark", "index": 1},
    {"action": "panel", "on": False},
    {"action": "section", "name": "Debug view", "open": True},
    {"action": "ramp", "key": "occ.radius", "from": 0, "to": 2, "frames": 30},
    {"action": "record", "dir": "."},
    {"action": "stop"},
    {"action": "quit"},
]
put("script", "every_action.json", json.dumps(script, indent=1))
put("script", "docs_example.json", json.dumps(script[:1] + script[4:13] + [{"action": "quit"}]))
copy("script", "docs/images/viewer_shots.json")

# ---- bookmarks ----
put("bookmarks", "every_field.json", json.dumps({"schema": 1, "bookmarks": [
    {"name": "shadows", "scene": "contact", "techniques": ["sh"], "params": {"sh.samples": 32, "light0.intensity": 2},
     "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov": 45},
     "view": {"aov": "visibility", "mode": "full", "min": 0, "max": 1, "false_color": True},
     "compare": {"mode": "reference", "divider": 0.5}, "notes": "Say *this*.", "panel": False,
     "sections": {"Debug view": True}},
    {"name": "other scene", "scene": "sample.gltf", "params": {"light3.intensity": 1}},
    {"name": "plain"}]}, indent=1))
for f in sorted(os.listdir(os.path.join(ROOT, "assets", "lecture"))):
    copy("bookmarks", os.path.join("assets", "lecture", f))

# ---- command lines (arguments separated by NUL bytes) ----
lines = {
    "everything": ["--scene", "contact", "-t", "sh,occ", "--set", "sh.samples=32", "--set", "camera.position=0,1,5",
                   "--preset", "p.json", "--save-preset", "q.json", "--size", "320x180", "--frames", "3",
                   "--seed", "7", "--backend", "osmesa", "--timing", "cpu-finish"],
    "inline_values": ["--size=640x360", "--technique=none", "--set=occ.tint=1,0.5,0.25", "--set=sh.pcf=false"],
    "help": ["--help"],
    "positional": ["scene.gltf", "--seed", "4294967295"],
    "negative_number": ["--set", "camera.fov", "-1"],
}
for name, args in lines.items():
    put("cli", name, "\0".join(args))
