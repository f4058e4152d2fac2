#!/bin/sh
# POV-Ray 3.7's 16-bit heights of the test images (grey and RGB, 8 and 16 bits, a palette), for
# tests/images/height_map_file_test.cpp: each image is 258 x 3 pixels, the 256 test values
# in columns 1 to 256 of every row; POV-Ray's trace() straight down at the grid points of
# the middle row gives y = h / 65536.
set -e
cd "$(dirname "$0")"
python3 - <<'PY'
from png import write_png
W = 258
row = [0] + list(range(256)) + [0]
write_png('g8.png', W, 3, [row] * 3)
row16 = [0] + [min(65535, i * 257 + (i * 37) % 257) for i in range(256)] + [0]
write_png('g16.png', W, 3, [row16] * 3, 16, 0)
rgb = [(0, 0, 0)] + [((i * 53) % 256, i, (i * 7) % 256) for i in range(256)] + [(0, 0, 0)]
write_png('rgb8.png', W, 3, [rgb] * 3, 8, 2)
rgb16 = [(0, 0, 0)] + [((i * 53 * 257) % 65536, i * 257, (i * 7 * 257) % 65536) for i in range(256)] + [(0, 0, 0)]
write_png('rgb16.png', W, 3, [rgb16] * 3, 16, 2)
# A palette image: its indices 0..255, each a colour that is not its index's grey.
palette = [((i * 97) % 256, (i * 29) % 256, 255 - i) for i in range(256)]
write_png('p8.png', W, 3, [row] * 3, 8, 3, palette)
PY
for f in g8 g16 rgb8 rgb16 p8; do
  cat > /tmp/probe_$f.pov <<POV
#version 3.7;
#declare H = height_field { png "$PWD/$f.png" }
#declare N = <0, 0, 0>;
#for (I, 1, 256)
#declare P = trace(H, <I / 257, 5, 0.5>, <0, -1, 0>, N);
#debug concat(str(P.y * 65536, 0, 0), "\n")
#end
camera { location <0, 0, -1> look_at 0 }
POV
  povray +I/tmp/probe_$f.pov -D +W8 +H8 +O/tmp/probe_$f.png 2>&1 >/dev/null | grep -E '^[0-9]' > $f.pov-heights.txt
done
