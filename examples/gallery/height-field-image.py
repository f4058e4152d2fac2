#!/usr/bin/env python3
# Writes height-field.png, the 16-bit grey height image of height-field.xml (or, given a
# size and a file, that terrain at another size: bench/shapes/height-field.png is
# `height-field-image.py 257 ../../bench/shapes/height-field.png`): a few hills
# (Gaussian bumps) and a ring-shaped ridge, faded to 0 at the border so that the field's
# edges lie at its water level (where Lucent's walls have no height, as POV-Ray has none).
import math, struct, sys, zlib

N = int(sys.argv[1]) if len(sys.argv) > 1 else 49
out = sys.argv[2] if len(sys.argv) > 2 else 'height-field.png'
def height(x, z):
    u, v = x / (N - 1), z / (N - 1)
    h = 0.55 * math.exp(-((u - 0.32) ** 2 + (v - 0.35) ** 2) / 0.02)
    h += 0.8 * math.exp(-((u - 0.68) ** 2 + (v - 0.62) ** 2) / 0.012)
    r = math.hypot(u - 0.5, v - 0.5)
    h += 0.25 * math.exp(-((r - 0.33) ** 2) / 0.004)
    h += 0.04 * math.sin(17 * u) * math.cos(13 * v)
    fade = min(1.0, 8 * min(u, 1 - u, v, 1 - v))
    return max(0.0, min(1.0, h * fade))

raw = b''
for z in range(N):
    raw += b'\x00' + b''.join(struct.pack('>H', round(height(x, z) * 65535)) for x in range(N))
def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
ihdr = struct.pack('>IIBBBBB', N, N, 16, 0, 0, 0, 0)
with open(out, 'wb') as f:
    f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
