#!/bin/sh
# POV-Ray 3.7's image_pattern values at chosen points, for tests/render/image_pattern_test.cpp:
# small images of every kind the reader tells apart (a palette with and without tRNS, grey
# of 2 and 8 bits, grey with alpha, RGB and RGBA of 8 bits, grey and RGB of 16 bits), each
# read with every interpolation, with and without use_alpha, through each map_type, some
# once; POV-Ray's own pattern function (`function { pattern { image_pattern {...} } }`)
# gives the value at each point. Writes values.csv: image, map_type, once, interpolate,
# use_alpha, x, y, z, value.
set -e
cd "$(dirname "$0")"
python3 - <<'PY'
import zlib, struct, random
def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
def write_png(path, w, h, rows, depth, ctype, palette=None, trns=None):
    raw = b''
    for r in rows:
        raw += b'\x00'
        if depth < 8:  # pack grey samples, high bits first
            bits, acc, n = 0, 0, 0
            out = b''
            for v in r:
                acc = (acc << depth) | v; n += depth
                if n == 8: out += bytes([acc]); acc, n = 0, 0
            if n: out += bytes([acc << (8 - n)])
            raw += out
            continue
        for v in r:
            for c in (v if isinstance(v, tuple) else (v,)):
                raw += struct.pack('>H', c) if depth == 16 else bytes([c])
    ihdr = struct.pack('>IIBBBBB', w, h, depth, ctype, 0, 0, 0)
    extra = chunk(b'PLTE', bytes(c for rgb in palette for c in rgb)) if palette else b''
    if trns: extra += chunk(b'tRNS', bytes(trns))
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + extra +
                           chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
random.seed(40)
W, H = 5, 4
def grid(f): return [[f(x, y) for x in range(W)] for y in range(H)]
r8 = lambda: random.randrange(256)
r16 = lambda: random.randrange(65536)
palette = [(r8(), r8(), r8()) for _ in range(12)]
idx = grid(lambda x, y: random.randrange(12))
write_png('palette.png', W, H, idx, 8, 3, palette)
write_png('palette_trns.png', W, H, idx, 8, 3, palette, [r8() for _ in range(7)])
write_png('grey2.png', W, H, grid(lambda x, y: random.randrange(4)), 2, 0)
write_png('grey8.png', W, H, grid(lambda x, y: r8()), 8, 0)
write_png('grey_alpha8.png', W, H, grid(lambda x, y: (r8(), r8())), 8, 4)
write_png('rgb8.png', W, H, grid(lambda x, y: (r8(), r8(), r8())), 8, 2)
write_png('rgba8.png', W, H, grid(lambda x, y: (r8(), r8(), r8(), r8())), 8, 6)
write_png('grey16.png', W, H, grid(lambda x, y: r16()), 16, 0)
write_png('rgb16.png', W, H, grid(lambda x, y: (r16(), r16(), r16())), 16, 2)
PY
python3 - > /tmp/image_pattern_probe.pov <<'PY'
import random
random.seed(41)
print('#version 3.7;\nglobal_settings { assumed_gamma 1 }')
images = ['palette', 'palette_trns', 'grey2', 'grey8', 'grey_alpha8', 'rgb8', 'rgba8', 'grey16', 'rgb16']
n = 0
for image in images:
    for interp in [0, 2, 3, 4]:
        for alpha in [0, 1]:
            for map_type, once in [(0, 0), (0, 1), (1, 0), (2, 0), (2, 1), (5, 0)]:
                mods = (' map_type %d' % map_type) + (' once' if once else '') + \
                       (' interpolate %d' % interp if interp else '') + (' use_alpha' if alpha else '')
                print('#declare F%d = function { pattern { image_pattern { png "%s/%s.png"%s } } }'
                      % (n, '@DIR@', image, mods))
                for k in range(6):
                    if map_type == 0: p = (random.uniform(-0.6, 1.6), random.uniform(-0.6, 1.6), random.uniform(-1, 1))
                    else: p = tuple(random.uniform(-1.5, 1.5) for _ in range(3))
                    print('#debug concat("%s,%d,%d,%d,%d,%.9g,%.9g,%.9g,", str(F%d(%.9g, %.9g, %.9g), 0, 15), "\\n")'
                          % ((image, map_type, once, interp, alpha) + p + (n,) + p))
                n += 1
print('camera { location <0, 0, -1> look_at 0 }')
PY
sed -i "s|@DIR@|$PWD|" /tmp/image_pattern_probe.pov
povray +I/tmp/image_pattern_probe.pov -D +W8 +H8 +O/tmp/image_pattern_probe.png 2>&1 >/dev/null |
  grep -E '^[a-z_0-9]+,' > values.csv
