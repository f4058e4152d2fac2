#!/usr/bin/env bash
# The README's showcase (examples/showcase.xml) shows what the README says it shows, and
# stays cheap enough for the README's first command to render it in well under a minute:
# - it holds a sor, a lathe, text, CSG, an area light, a sky, fog, a colour map, absorption
#   and library materials (`lucent check` and the scene's own text);
# - its picture has them where they were placed (a small render's regions: the blue sky,
#   the amber of the vase's absorption, the red die, the white pawn, the dark granite slab
#   before a warm marble floor);
# - the full render at the scene's own settings traces at most 15 million rays (measured:
#   12.3 million, 8 s of CPU on this machine's cores; a ray count does not depend on load).
# Usage: bash showcase_scene.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
scene=$src/examples/showcase.xml

"$lucent" check "$scene" >"$tmp/check.txt" 2>&1 || fail "lucent check failed: $(cat "$tmp/check.txt")"
for shape in sor lathe text difference intersection; do
  grep -q "^nodes:.* $shape: [0-9]" "$tmp/check.txt" || fail "no $shape in the showcase"
done
grep -q "^lights:.*area: 1" "$tmp/check.txt" || fail "no area light in the showcase"
for element in '<sky>' '<fog ' '<color-map>' 'absorption=' 'src="lucent:'; do
  grep -q "$element" "$scene" || fail "the showcase has no $element"
done

# A 160x120 render, one ray a pixel: the mean colour of a few boxes of pixels.
"$lucent" render "$scene" -w 160 -h 120 -s 1 -q -o "$tmp/small.ppm" || fail "render failed"
regions=$(python3 - "$tmp/small.ppm" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
header = b"P6\n160 120\n255\n"
assert data.startswith(header), "not a 160x120 PPM"
def mean(x0, y0, x1, y1):
    total = [0, 0, 0]
    for y in range(y0, y1):
        for x in range(x0, x1):
            o = len(header) + 3 * (y * 160 + x)
            total = [t + v for t, v in zip(total, data[o:o + 3])]
    n = (x1 - x0) * (y1 - y0)
    return " ".join(str(round(t / n)) for t in total)
for name, box in [("sky", (0, 0, 160, 12)), ("vase", (20, 66, 40, 84)),
                  ("die", (106, 84, 122, 98)), ("pawn", (58, 90, 74, 96)),
                  ("slab", (52, 56, 58, 64)), ("floor", (0, 108, 40, 120))]:
    print(name, mean(*box))
PY
) || fail "could not read the render"
rgb() { awk -v n="$1" '$1 == n { print $2, $3, $4 }' <<<"$regions"; }
read -r r g b <<<"$(rgb sky)"
[ $((b - r)) -ge 25 ] || fail "the sky is not blue at the top: $r $g $b"
read -r r g b <<<"$(rgb vase)"
[ $((r - b)) -ge 60 ] || fail "the vase is not amber (absorption): $r $g $b"
read -r r g b <<<"$(rgb die)"
[ "$r" -ge $((2 * g)) ] || fail "the die is not red: $r $g $b"
read -r r g b <<<"$(rgb pawn)"
{ [ "$r" -ge 190 ] && [ "$g" -ge 190 ] && [ "$b" -ge 190 ]; } || fail "the pawn is not white: $r $g $b"
read -r fr fg fb <<<"$(rgb floor)"
[ $((fr - fb)) -ge 15 ] || fail "the marble floor is not warm: $fr $fg $fb"
read -r r g b <<<"$(rgb slab)"
[ $((10 * (r + g + b))) -le $((6 * (fr + fg + fb))) ] || fail "the granite slab is not darker than the floor: $r $g $b"

# The README's command at the scene's own settings: the ray budget.
"$lucent" render "$scene" --stats -q -o "$tmp/full.png" >"$tmp/stats.txt" 2>&1 || fail "full render failed"
rays=$(awk '$1 == "rays:" { print $2 }' "$tmp/stats.txt")
[ -n "$rays" ] || fail "no ray count in --stats: $(cat "$tmp/stats.txt")"
[ "${rays:-0}" -le 15000000 ] || fail "the showcase traces $rays rays, above its budget of 15 million"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "showcase: every promised feature is in it, the picture has them in place, $rays rays"
