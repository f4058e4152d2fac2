#!/usr/bin/env python3
"""Writes the images of image_gamma.pov and image_gamma_36.pov: one 8x4 RGB ramp of code
values stored four ways, a PNG without colour chunks, a PNG with a gAMA chunk of 1/1.8, a PNG
with an sRGB chunk (and the gAMA of 1/2.2 that usually goes with it) and a binary PPM.
Standard library only; run from this folder: python3 make_image_gammas.py"""
import struct
import zlib

W, H = 8, 4


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def pixel(x, y):
    # Reds climb along a row, greens down the rows, blues fall: every code value differs.
    return (16 + 30 * x, 40 + 60 * y, 250 - 28 * x - 9 * y)


rows = [[pixel(x, y) for x in range(W)] for y in range(H)]


def write_png(path, extra):
    raw = b"".join(b"\0" + bytes(c for p in row for c in p) for row in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
                extra + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


write_png("ig_plain.png", b"")
write_png("ig_gama18.png", chunk(b"gAMA", struct.pack(">I", 55556)))
write_png("ig_srgb.png", chunk(b"sRGB", b"\0") + chunk(b"gAMA", struct.pack(">I", 45455)))
with open("ig_ramp.ppm", "wb") as f:
    f.write(b"P6\n%d %d\n255\n" % (W, H) + bytes(c for row in rows for p in row for c in p))
