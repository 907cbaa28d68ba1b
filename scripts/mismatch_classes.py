#!/usr/bin/env python3
"""The error classes of a `shadowlab render ... --measure --truth --mismatch-out m.png` picture
(docs/bias.md, "Where the false shadow and false light come from").

usage: mismatch_classes.py MISMATCH.png [MORE.png ...]

Each false-shadow (red) and false-light (blue) pixel is classed by its 5 x 5 neighbourhood:
  edge      a receiver within 2 pixels has the other truth (a shadow edge: aliasing of the map)
  border    no shadow edge, but a non-receiver within 2 pixels (terminators, silhouettes)
  interior  neither (acne, or light leaking through a lit face)
Shares are of the receivers (every measured pixel). Standard library only: the picture is the
8-bit RGBA, non-interlaced PNG that the renderer writes.
"""
import struct
import sys
import zlib

# mismatchImage() in app/accuracy.cpp: colour -> (measured, truth lit, verdict)
AGREE_LIT = (190, 190, 185)
AGREE_SHADOW = (95, 95, 100)
FALSE_SHADOW = (230, 40, 30)
FALSE_LIGHT = (40, 90, 255)
NOT_MEASURED = (30, 30, 40)


def read_rgba_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour != 6 or interlace != 0:
                raise ValueError(f"{path}: expected 8-bit RGBA without interlace")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * 4
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        filt, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):  # PNG spec section 9: filter types 0-4
            a = line[i - 4] if i >= 4 else 0
            b = prev[i]
            c = prev[i - 4] if i >= 4 else 0
            if filt == 1:
                line[i] = (line[i] + a) & 255
            elif filt == 2:
                line[i] = (line[i] + b) & 255
            elif filt == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif filt == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows


def classify(path):
    width, height, rows = read_rgba_png(path)
    # truth per pixel: 1 lit, 0 shadow, None not a receiver; mismatch kind per pixel
    truth = [[None] * width for _ in range(height)]
    kind = [[None] * width for _ in range(height)]
    for y in range(height):
        line = rows[y]
        for x in range(width):
            rgb = tuple(line[4 * x:4 * x + 3])
            if rgb == AGREE_LIT:
                truth[y][x] = 1
            elif rgb == AGREE_SHADOW:
                truth[y][x] = 0
            elif rgb == FALSE_SHADOW:
                truth[y][x], kind[y][x] = 1, "shadow"
            elif rgb == FALSE_LIGHT:
                truth[y][x], kind[y][x] = 0, "light"
    receivers = sum(t is not None for row in truth for t in row)
    counts = {(k, c): 0 for k in ("shadow", "light") for c in ("interior", "border", "edge")}
    for y in range(height):
        for x in range(width):
            k = kind[y][x]
            if k is None:
                continue
            edge = border = False
            for yy in range(max(0, y - 2), min(height, y + 3)):
                for xx in range(max(0, x - 2), min(width, x + 3)):
                    t = truth[yy][xx]
                    if t is None:
                        border = True
                    elif t != truth[y][x]:
                        edge = True
            counts[(k, "edge" if edge else "border" if border else "interior")] += 1
    return receivers, counts


def main(paths):
    print("picture | receivers | E_total | false shadow: interior / border / edge | false light: interior / border / edge")
    for path in paths:
        receivers, c = classify(path)
        share = lambda n: 100.0 * n / max(receivers, 1)  # noqa: E731
        total = sum(c.values())
        cells = []
        for k in ("shadow", "light"):
            parts = [f"{c[(k, cls)]} ({share(c[(k, cls)]):.3f}%)" for cls in ("interior", "border", "edge")]
            cells.append(f"{share(sum(c[(k, cls)] for cls in ('interior', 'border', 'edge'))):.3f}%: " + " / ".join(parts))
        print(f"{path} | {receivers} | {share(total):.3f}% | {cells[0]} | {cells[1]}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
