#!/usr/bin/env python3
"""Writes the synthetic PNG fixtures under scene/ (stand-ins for fuzz finds that were mutations of
shared scenes, which are not kept). Each is a one-triangle GLB whose base colour texture is a PNG:

png_bomb_16x16_inflates_40mb.glb: a 16x16 RGBA8 PNG (1,040 bytes of filtered rows declared) with
  a zlib stream of 40,000,000 zero bytes (38.9 KB at zlib level 9). stb_image's inflater doubles
  its buffer from the declared 1,040 bytes to 1,040 x 2^16 = 68.2 MB for it; the replay runs with
  ASan's max_allocation_size_mb=64, so that request aborts it where the decoder is unbounded.
png_empty_idat_first.glb: a valid 2x1 RGB PNG with an empty IDAT chunk before the one with the
  data (PNG allows it); stb copied it with memcpy(nullptr, data, 0), which UBSan reports.

Usage: tests/fuzz_regressions/make_png_fixtures.py
"""
import json
import pathlib
import struct
import zlib

INFLATED = 40_000_000


def chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png(width: int, height: int, colour: int, idats: list) -> bytes:
    ihdr = struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0)  # 8-bit, not interlaced
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + b"".join(chunk(b"IDAT", d) for d in idats) +
            chunk(b"IEND", b""))


def png_bomb() -> bytes:
    return png(16, 16, 6, [zlib.compress(bytes(INFLATED), 9)])


def png_empty_idat_first() -> bytes:
    rows = bytes([0, 255, 0, 0, 0, 0, 255])  # filter 0, a red and a blue pixel
    return png(2, 1, 2, [b"", zlib.compress(rows, 9)])


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
    folder = pathlib.Path(__file__).resolve().parent / "scene"
    for name, image in (("png_bomb_16x16_inflates_40mb.glb", png_bomb()),
                        ("png_empty_idat_first.glb", png_empty_idat_first())):
        data = glb(image)
        (folder / name).write_bytes(data)
        print(f"{folder / name}: {len(data)} bytes")
