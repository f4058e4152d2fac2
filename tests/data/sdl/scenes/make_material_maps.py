#!/usr/bin/env python3
"""Writes the images of material_maps.pov: a 6x4 palette PNG of 16 colours (indices 0..15,
so that five textures see indices past their count), a 6x4 RGB PNG whose reds are 0..9 and
a few large ones (red x 255 is the material number), and the same as 16 bits. Standard
library only; run from this folder: python3 make_material_maps.py"""
import random
import struct
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def write_png(path, w, h, rows, depth, ctype, palette=None):
    raw = b""
    for r in rows:
        raw += b"\0"
        for v in r:
            for c in (v if isinstance(v, tuple) else (v,)):
                raw += struct.pack(">H", c) if depth == 16 else bytes([c])
    extra = chunk(b"PLTE", bytes(c for rgb in palette for c in rgb)) if palette else b""
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, 0)) +
                extra + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


random.seed(40)
W, H = 6, 4
palette = [(random.randrange(256), random.randrange(256), random.randrange(256)) for _ in range(16)]
indices = list(range(16)) + [random.randrange(16) for _ in range(W * H - 16)]
random.shuffle(indices)
write_png("mm_palette.png", W, H, [indices[y * W:(y + 1) * W] for y in range(H)], 8, 3, palette)
reds = list(range(10)) + [200, 255, 17, 33] + [random.randrange(12) for _ in range(W * H - 14)]
random.shuffle(reds)
rgb = [[(reds[y * W + x], random.randrange(256), random.randrange(256)) for x in range(W)]
       for y in range(H)]
write_png("mm_rgb.png", W, H, rgb, 8, 2)
rgb16 = [[(max(0, r * 257 + random.randrange(-300, 300)) if 0 < r < 255 else r * 257, g * 257, b * 257)
          for (r, g, b) in row] for row in rgb]
write_png("mm_rgb16.png", W, H, rgb16, 16, 2)
