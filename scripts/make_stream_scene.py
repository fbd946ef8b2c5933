#!/usr/bin/env python3
"""Writes a paper-scale glTF scene for the streaming measurements (docs/player/streaming.md):
a height-field grid of about TRIANGLES triangles with one SIZE x SIZE base-colour
texture (PNG), standard library only. Bake it with build/baker/lfd-bake.

usage: make_stream_scene.py OUT_DIR [--triangles 1000000] [--texture-size 16384]
"""
import argparse
import json
import math
import os
import struct
import zlib


def write_png(path, size):
    # A checker with a gradient: cheap to generate row by row, compresses well, and every
    # mip level differs (so a wrong level shows).
    def row(y):
        cell = (y // 256) % 2
        line = bytearray()
        pattern = bytes([200, 60 + (y * 150) // size, 40, 255]) * 256
        other = bytes([30, 90, 200 - (y * 150) // size, 255]) * 256
        for x in range(size // 256):
            line += pattern if (x + cell) % 2 == 0 else other
        return b"\x00" + bytes(line)

    comp = zlib.compressobj(1)
    chunks = []
    for y in range(size):
        chunks.append(comp.compress(row(y)))
    chunks.append(comp.flush())
    data = b"".join(chunks)

    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0)))
        f.write(chunk(b"IDAT", data))
        f.write(chunk(b"IEND", b""))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--triangles", type=int, default=1_000_000)
    p.add_argument("--texture-size", type=int, default=16384)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    n = max(1, round(math.sqrt(a.triangles / 2)))
    pos, nrm, uv = bytearray(), bytearray(), bytearray()
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n - 0.5, j / n - 0.5
            z = 0.02 * math.sin(12 * x) * math.cos(12 * y)
            pos += struct.pack("<3f", x, y, z)
            nrm += struct.pack("<3f", 0.0, 0.0, 1.0)
            uv += struct.pack("<2f", i / n, 1.0 - j / n)
    idx = bytearray()
    for j in range(n):
        for i in range(n):
            a0 = j * (n + 1) + i
            idx += struct.pack("<6I", a0, a0 + 1, a0 + n + 2, a0, a0 + n + 2, a0 + n + 1)
    blob = bytes(pos + nrm + uv + idx)
    with open(os.path.join(a.out, "stream.bin"), "wb") as f:
        f.write(blob)
    write_png(os.path.join(a.out, "stream.png"), a.texture_size)
    v = (n + 1) * (n + 1)
    views = [(0, len(pos)), (len(pos), len(nrm)), (len(pos) + len(nrm), len(uv)), (len(pos) + len(nrm) + len(uv), len(idx))]
    gltf = {
        "asset": {"version": "2.0"},
        "buffers": [{"uri": "stream.bin", "byteLength": len(blob)}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": l} for o, l in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": v, "type": "VEC3",
             "min": [-0.5, -0.5, -0.02], "max": [0.5, 0.5, 0.02]},
            {"bufferView": 1, "componentType": 5126, "count": v, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": v, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5125, "count": n * n * 6, "type": "SCALAR"},
        ],
        "images": [{"uri": "stream.png"}],
        "textures": [{"source": 0}],
        "materials": [{"name": "stream", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "meshes": [{"name": "grid", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                     "indices": 3, "material": 0}]}],
        "nodes": [{"mesh": 0, "name": "grid"}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    with open(os.path.join(a.out, "stream.gltf"), "w") as f:
        json.dump(gltf, f)
    print(f"{a.out}/stream.gltf: {2 * n * n} triangles, {a.texture_size}^2 texture")


if __name__ == "__main__":
    main()
