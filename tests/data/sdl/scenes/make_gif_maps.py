#!/usr/bin/env python3
"""Writes gif_plain.gif and gif_transparent.gif for gif_maps.pov: 8x8 GIFs of a global
colour table of four colours (red, blue, white, green) in 2x2 blocks, as POV-Ray's GIF reader
takes them (a global table, not interlaced); gif_transparent.gif marks blue transparent in a
graphic control extension. And gif_heights.pot, a POT file (a GIF of 256 greys twice as wide
as its 4x3 field: high bytes left, low bytes right). The LZW stream sends a clear code after
every two pixels, so every code keeps the width it starts with. Standard library only; run
from this folder: python3 make_gif_maps.py"""
import struct

palette = [(255, 0, 0), (0, 0, 255), (255, 255, 255), (0, 160, 0)]
pixels = [((x // 2) + (y // 2)) % 4 for y in range(8) for x in range(8)]


def lzw(indices, least=2):
    clear, end, bits = 1 << least, (1 << least) + 1, least + 1
    codes = []
    for k in range(0, len(indices), 2):
        codes += [clear] + indices[k:k + 2]
    codes.append(end)
    out, acc, n = bytearray(), 0, 0
    for c in codes:
        acc |= c << n
        n += bits
        while n >= 8:
            out.append(acc & 0xFF)
            acc >>= 8
            n -= 8
    if n:
        out.append(acc & 0xFF)
    blocks = b"".join(bytes([len(out[i:i + 255])]) + out[i:i + 255] for i in range(0, len(out), 255))
    return bytes([least]) + blocks + b"\0"


def gif(name, width, height, colours, indices, transparent=None):
    size = len(colours).bit_length() - 2  # the table holds 2^(size + 1) entries
    head = b"GIF89a" + struct.pack("<HHBBB", width, height, 0x80 | size, 0, 0)
    table = bytes(c for rgb in colours for c in rgb)
    control = b"!\xf9\x04" + struct.pack("<BHB", 1, 0, transparent) + b"\0" if transparent else b""
    image = b"," + struct.pack("<HHHHB", 0, 0, width, height, 0) + lzw(indices, max(2, size + 1))
    with open(name, "wb") as f:
        f.write(head + table + control + image + b";")


gif("gif_plain.gif", 8, 8, palette, pixels)
gif("gif_transparent.gif", 8, 8, palette, pixels, 1)
# Heights 0x0000 to 0xB0FF over the 4x3 field: high byte 16 (x + 4 z'), low byte 255 - 20 x
# (z' the row from the top).
high = [[16 * (x + 4 * row) for x in range(4)] for row in range(3)]
low = [[255 - 20 * x - row for x in range(4)] for row in range(3)]
gif("gif_heights.pot", 8, 3, [(g, g, g) for g in range(256)],
    [v for row in range(3) for v in high[row] + low[row]])
