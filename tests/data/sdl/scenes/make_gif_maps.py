#!/usr/bin/env python3
"""Writes gif_plain.gif and gif_transparent.gif for gif_maps.pov: 8x8 GIFs of a global
colour table of four colours (red, blue, white, green) in 2x2 blocks, as POV-Ray's GIF reader
takes them (a global table, not interlaced); gif_transparent.gif marks blue transparent in a
graphic control extension. The LZW stream sends a clear code after every two pixels, so every
code keeps three bits. Standard library only; run from this folder: python3 make_gif_maps.py"""
import struct

palette = [(255, 0, 0), (0, 0, 255), (255, 255, 255), (0, 160, 0)]
pixels = [((x // 2) + (y // 2)) % 4 for y in range(8) for x in range(8)]
CLEAR, END, BITS = 4, 5, 3


def lzw(indices):
    codes = []
    for k in range(0, len(indices), 2):
        codes += [CLEAR] + indices[k:k + 2]
    codes.append(END)
    out, acc, n = bytearray(), 0, 0
    for c in codes:
        acc |= c << n
        n += BITS
        while n >= 8:
            out.append(acc & 0xFF)
            acc >>= 8
            n -= 8
    if n:
        out.append(acc & 0xFF)
    blocks = b"".join(bytes([len(out[i:i + 255])]) + out[i:i + 255] for i in range(0, len(out), 255))
    return bytes([2]) + blocks + b"\0"


def gif(name, transparent):
    head = b"GIF89a" + struct.pack("<HHBBB", 8, 8, 0x80 | 0x01, 0, 0)  # global table of 4
    table = bytes(c for rgb in palette for c in rgb)
    control = b"!\xf9\x04" + struct.pack("<BHB", 1, 0, transparent) + b"\0" if transparent else b""
    image = b"," + struct.pack("<HHHHB", 0, 0, 8, 8, 0) + lzw(pixels)
    with open(name, "wb") as f:
        f.write(head + table + control + image + b";")


gif("gif_plain.gif", None)
gif("gif_transparent.gif", 1)
