#!/usr/bin/env python3
"""Writes emblem.png, the image of examples/gallery/pattern-image-pattern.xml: a 48x48
palette PNG of 16 colours (a ring, a star and a background) whose tRNS chunk makes the
background see-through, so that image_pattern's grey level and its use_alpha both have
something to read; and emblem_opaque.png, the same without the tRNS chunk (every entry
opaque), for examples/gallery/image-palette-entries.xml. Written with the standard library
only. Run from this folder: python3 make_emblem.py"""
import math
import struct
import zlib

SIZE = 48
# Entry 0 the background (alpha 0), 1..7 the ring's shades, 8..15 the star's.
PALETTE = [(20, 30, 60)] + [(60 + 25 * i, 40 + 10 * i, 30) for i in range(7)] + \
          [(250 - 12 * i, 230 - 20 * i, 80 + 15 * i) for i in range(8)]
ALPHA = [0] + [255] * 7 + [200] * 8


def index(x, y):
    cx, cy = x - 23.5, y - 23.5
    r = math.hypot(cx, cy)
    a = math.atan2(cy, cx)
    star = 9 + 5 * math.cos(5 * a)
    if r < star:
        return 8 + min(7, int(r / 2))
    if 17 < r < 22:
        return 1 + int((a + math.pi) / (2 * math.pi) * 7) % 7
    return 0


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


rows = b"".join(b"\0" + bytes(index(x, y) for x in range(SIZE)) for y in range(SIZE))
for name, transparency in (("emblem.png", chunk(b"tRNS", bytes(ALPHA))), ("emblem_opaque.png", b"")):
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 3, 0, 0, 0)) +
           chunk(b"PLTE", bytes(c for rgb in PALETTE for c in rgb)) + transparency +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    with open(name, "wb") as f:
        f.write(png)
