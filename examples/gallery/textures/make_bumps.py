#!/usr/bin/env python3
"""Writes bumps.png, the height map of examples/gallery/bump-map.xml: a 64x64 8-bit grey
PNG of round studs (a smooth cosine dome on each 16x16 cell) crossed by one groove, written
with the standard library only. Run from this folder: python3 make_bumps.py"""
import math
import struct
import zlib

SIZE = 64


def height(x, y):
    # A dome of radius 7 pixels centred in each 16x16 cell, on a flat ground of 0.2.
    cx, cy = x % 16 - 7.5, y % 16 - 7.5
    r = math.hypot(cx, cy) / 7.0
    h = 0.2 + (0.8 * (0.5 + 0.5 * math.cos(math.pi * r)) if r < 1 else 0.0)
    # A diagonal groove, to show a direction the studs do not have.
    d = abs(((x - y) % 32) - 16) / 3.0
    if d < 1:
        h *= 0.5 + 0.5 * d
    return h


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


rows = b"".join(b"\0" + bytes(round(255 * height(x, y)) for x in range(SIZE)) for y in range(SIZE))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
with open("bumps.png", "wb") as f:
    f.write(png)
