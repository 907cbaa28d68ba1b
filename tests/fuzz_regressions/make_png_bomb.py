#!/usr/bin/env python3
"""Writes scene/png_bomb_16x16_inflates_40mb.glb: a synthetic stand-in for issue 12's fuzz find
(a mutated shared-scene GLB, not kept), a one-triangle GLB whose base colour texture is a 16x16
RGBA8 PNG (1,040 bytes of filtered rows declared) with a zlib stream of 40,000,000 zero bytes
(38.9 KB at zlib level 9). stb_image's inflater doubles its buffer from the declared 1,040 bytes
to 1,040 x 2^16 = 68.2 MB for it; the replay runs with ASan's max_allocation_size_mb=64, so that
request aborts it where the decoder is unbounded. Usage: tests/fuzz_regressions/make_png_bomb.py
"""
import json
import pathlib
import struct
import zlib

INFLATED = 40_000_000


def chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png_bomb() -> bytes:
    ihdr = struct.pack(">IIBBBBB", 16, 16, 8, 6, 0, 0, 0)  # 16x16, 8-bit RGBA, not interlaced
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(bytes(INFLATED), 9)) +
            chunk(b"IEND", b""))


def pad4(data: bytes, fill: bytes) -> bytes:
    return data + fill * (-len(data) % 4)


def glb(image: bytes) -> bytes:
    triangle = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2)
    triangle = pad4(triangle, b"\0")
    binary = pad4(triangle + image, b"\0")
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}],
        "images": [{"bufferView": 2, "mimeType": "image/png"}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 6},
            {"buffer": 0, "byteOffset": len(triangle), "byteLength": len(image)},
        ],
        "buffers": [{"byteLength": len(binary)}],
    }
    text = pad4(json.dumps(gltf, separators=(",", ":")).encode(), b" ")
    body = (struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary)
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


if __name__ == "__main__":
    out = pathlib.Path(__file__).resolve().parent / "scene" / "png_bomb_16x16_inflates_40mb.glb"
    data = glb(png_bomb())
    out.write_bytes(data)
    print(f"{out}: {len(data)} bytes")
