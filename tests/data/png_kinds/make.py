# PNG files of the kinds a PNG reader must widen or reorder (bits below 8, grey with alpha,
# RGBA of 16 bits, Adam7 interlacing, a grey tRNS), for tests/images/builtin_png_read_test.cpp,
# which reads each through libpng and through OpenImageIO and compares; and of the kinds
# OpenImageIO labels or premultiplies in its own way (a palette with tRNS, alpha with and
# without a gAMA chunk, sRGB and gAMA 1 chunks), for tests/images/builtin_texture_read_test.cpp.
# Run: python3 make.py
import struct, zlib

W, H = 11, 7

def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)

def pack_row(samples, depth):
    if depth == 16:
        return b''.join(struct.pack('>H', s) for s in samples)
    if depth == 8:
        return bytes(samples)
    out, acc, n = bytearray(), 0, 0
    for s in samples:
        acc = (acc << depth) | s
        n += depth
        if n == 8:
            out.append(acc)
            acc, n = 0, 0
    if n:
        out.append(acc << (8 - n))
    return bytes(out)

def write(path, ctype, depth, pixel, interlace=False, extra=b''):
    per = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    def rows(xs, ys):
        raw = b''
        for y in ys:
            samples = []
            for x in xs:
                samples += list(pixel(x, y))[:per]
            raw += b'\x00' + pack_row(samples, depth)
        return raw
    if not interlace:
        raw = rows(range(W), range(H))
    else:  # Adam7: seven passes of sub-images
        raw = b''
        for x0, y0, dx, dy in [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4),
                               (1, 0, 2, 2), (0, 1, 1, 2)]:
            xs, ys = range(x0, W, dx), range(y0, H, dy)
            if len(xs) and len(ys):
                raw += rows(xs, ys)
    ihdr = struct.pack('>IIBBBBB', W, H, depth, ctype, 0, 0, 1 if interlace else 0)
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + extra +
                           chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))

for d in (1, 2, 4):
    write('grey%d.png' % d, 0, d, lambda x, y, d=d: ((x * 3 + y) % (1 << d),))
write('grey_alpha8.png', 4, 8, lambda x, y: ((x * 23 + y * 5) % 256, (x * 7) % 256))
write('rgba16.png', 6, 16, lambda x, y: ((x * 5000) % 65536, (y * 9000) % 65536,
                                         (x * y * 777) % 65536, 65535 - x * 100))
write('interlaced8.png', 0, 8, lambda x, y: ((x * 19 + y * 31) % 256,), interlace=True)
write('interlaced_rgb16.png', 2, 16, lambda x, y: (x * 4000, y * 7000, (x + y) * 1000),
      interlace=True)
write('grey_trns8.png', 0, 8, lambda x, y: ((x * 11 + y) % 256,), extra=chunk(b'tRNS', struct.pack('>H', 12)))

palette = bytes(sum(([i * 17, 255 - i * 13, (i * 50) % 256] for i in range(16)), []))
write('palette4_trns.png', 3, 4, lambda x, y: ((x + 2 * y) % 16,),
      extra=chunk(b'PLTE', palette) + chunk(b'tRNS', bytes([0, 40, 128, 200, 255, 7])))
write('rgba8.png', 6, 8, lambda x, y: ((x * 23) % 256, (y * 37) % 256, (x * y * 7) % 256,
                                       (x * 25 + y * 3) % 256))
write('rgba8_gamma22.png', 6, 8, lambda x, y: ((x * 23) % 256, (y * 37) % 256, 200,
                                               (x * 25 + y * 3) % 256),
      extra=chunk(b'gAMA', struct.pack('>I', 45455)))
write('grey_alpha16_gamma18.png', 4, 16, lambda x, y: (x * 6000, 65535 - y * 9000),
      extra=chunk(b'gAMA', struct.pack('>I', 55556)))
write('rgb8_srgb.png', 2, 8, lambda x, y: ((x * 23) % 256, (y * 37) % 256, 99),
      extra=chunk(b'sRGB', bytes([0])))
write('grey8_linear.png', 0, 8, lambda x, y: ((x * 20 + y) % 256,),
      extra=chunk(b'gAMA', struct.pack('>I', 100000)))
