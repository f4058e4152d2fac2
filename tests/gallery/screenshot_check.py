#!/usr/bin/env python3
"""Checks a browser screenshot of a `lucent compare` report.html: each given image must
appear in it at 1:1 scale (every pixel within TOL of the file's), and below the images a
table must be drawn (at least MIN_LINES horizontal border lines of the report's #bbb cell
border, with text between them). Images are binary PPM (P6) files, as `oiiotool -o x.ppm`
writes them. Prints where each image was found; exit status 1 when something is missing.
Usage: screenshot_check.py SHOT.ppm IMAGE.ppm...
"""
import sys

TOL = 4          # per channel, of 255: colour management may round differently
MIN_LINES = 8    # the metrics table has 7 rows, so 8 horizontal borders
BORDER = 187     # #bbb
MIN_RUN = 150    # pixels: a table border, not a letter


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval (comments are not written)
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6" or int(fields[3]) != 255:
        sys.exit(f"{path}: not an 8-bit binary PPM")
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[pos + 1:pos + 1 + width * height * 3]


def matches(shot, image, x, y, pixels):
    sw, _, sp = shot
    iw, _, ip = image
    for (px, py) in pixels:
        s = ((y + py) * sw + x + px) * 3
        i = (py * iw + px) * 3
        for c in range(3):
            if abs(sp[s + c] - ip[i + c]) > TOL:
                return False
    return True


def overlaps(x, y, w, h, taken):
    return any(x < tx + tw and tx < x + w and y < ty + th and ty < y + h
               for (tx, ty, tw, th) in taken)


def find(shot, image, taken):
    """The top-left corner where image appears in shot outside the rectangles already
    taken by other images (two identical renders must be shown twice), or None."""
    sw, sh, _ = shot
    iw, ih, _ = image
    # A coarse probe of spread-out pixels rejects most positions at once; the full
    # comparison confirms.
    probe = [(px, py) for py in range(0, ih, max(1, ih // 6)) for px in range(0, iw, max(1, iw // 8))]
    every = [(px, py) for py in range(ih) for px in range(iw)]
    for y in range(sh - ih + 1):
        for x in range(sw - iw + 1):
            if matches(shot, image, x, y, probe[:1]) and matches(shot, image, x, y, probe) \
                    and not overlaps(x, y, iw, ih, taken) and matches(shot, image, x, y, every):
                return x, y
    return None


def table_below(shot, top):
    """Rows (y >= top) holding a long run of the table's border colour, and dark (text)
    pixels between the first and the last of them."""
    sw, sh, sp = shot
    lines = []
    for y in range(top, sh):
        run = best = 0
        for x in range(sw):
            s = (y * sw + x) * 3
            if all(abs(sp[s + c] - BORDER) <= 12 for c in range(3)):
                run += 1
                best = max(best, run)
            else:
                run = 0
        if best >= MIN_RUN:
            lines.append(y)
    dark = 0
    if lines:
        for y in range(lines[0], lines[-1]):
            for x in range(sw):
                s = (y * sw + x) * 3
                if sp[s] < 100 and sp[s + 1] < 100 and sp[s + 2] < 100:
                    dark += 1
    return lines, dark


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    shot = read_ppm(sys.argv[1])
    ok = True
    bottom = 0
    taken = []
    for path in sys.argv[2:]:
        image = read_ppm(path)
        where = find(shot, image, taken)
        if where is None:
            print(f"MISSING: {path} ({image[0]}x{image[1]}) is not shown in the screenshot")
            ok = False
        else:
            print(f"shown: {path} at {where[0]},{where[1]}")
            taken.append((where[0], where[1], image[0], image[1]))
            bottom = max(bottom, where[1] + image[1])
    lines, dark = table_below(shot, bottom)
    # Borders merge into one line per row boundary; neighbouring rows of one border
    # (anti-aliasing) count once.
    distinct = [y for i, y in enumerate(lines) if i == 0 or y != lines[i - 1] + 1]
    if len(distinct) < MIN_LINES or dark < 200:
        print(f"MISSING: table below the images: {len(distinct)} border lines "
              f"(need {MIN_LINES}), {dark} dark text pixels (need 200)")
        ok = False
    else:
        print(f"shown: table with {len(distinct)} border lines and {dark} text pixels")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
