#!/usr/bin/env python3
"""Places 8-bit PNGs (as rtlab writes them: gray, RGB or RGBA, not interlaced) side by side,
separated by a 4-pixel white gap, into one RGB PNG. Standard library only.
Usage: png_row.py OUT.png IN1.png IN2.png ..."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"png_row: {path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, color, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(color)
    if depth != 8 or channels is None or interlace:
        sys.exit(f"png_row: {path}: only 8-bit gray/RGB/RGBA, non-interlaced")
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    rgb = []
    for line in rows:
        out = bytearray()
        for x in range(width):
            px = line[x * channels:(x + 1) * channels]
            out += bytes(px[:1]) * 3 if channels <= 2 else bytes(px[:3])
        rgb.append(out)
    return width, height, rgb


def write_png(path, width, height, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    images = [read_png(p) for p in sys.argv[2:]]
    gap = 4
    height = max(h for _, h, _ in images)
    width = sum(w for w, _, _ in images) + gap * (len(images) - 1)
    rows = []
    for y in range(height):
        row = bytearray()
        for i, (w, h, rgb) in enumerate(images):
            if i:
                row += b"\xff" * (3 * gap)
            row += rgb[y] if y < h else b"\xff" * (3 * w)
        rows.append(row)
    write_png(sys.argv[1], width, height, rows)


main()
