# A minimal PNG writer (grey or RGB, 8 or 16 bits), for make_references.sh.
import zlib, struct
def write_png(path, w, h, rows, depth=8, ctype=0, palette=None):
    # rows: list of lists of ints (grey) or of tuples (rgb)
    raw = b''
    for r in rows:
        raw += b'\x00'
        for v in r:
            vals = v if isinstance(v, tuple) else (v,)
            for c in vals:
                raw += struct.pack('>H', c) if depth == 16 else bytes([c])
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    ihdr = struct.pack('>IIBBBBB', w, h, depth, ctype, 0, 0, 0)
    plte = chunk(b'PLTE', bytes(c for rgb in palette for c in rgb)) if palette else b''
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + plte + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
