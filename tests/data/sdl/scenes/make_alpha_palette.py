#!/usr/bin/env python3
"""Writes alpha_palette.png for image_map_alpha.pov: a 4x2 palette PNG of four colours whose
tRNS chunk gives them alphas 255, 128, 0 and 200 (red, green, blue, white), each colour in
two pixels. Standard library only; run from this folder: python3 make_alpha_palette.py"""
import struct
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


palette = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]
alphas = [255, 128, 0, 200]
rows = [[0, 1, 2, 3], [3, 2, 1, 0]]
raw = b"".join(b"\0" + bytes(r) for r in rows)
with open("alpha_palette.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 2, 8, 3, 0, 0, 0)) +
            chunk(b"PLTE", bytes(c for rgb in palette for c in rgb)) + chunk(b"tRNS", bytes(alphas)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
