#!/usr/bin/env bash
# scripts/animation_gif renders every frame of an animated scene (-D frame=F) and writes one
# looping GIF with a subimage per frame, at the size and frame rate asked for; a scene
# without <animation> is refused and writes nothing.
# Usage: bash animation_gif.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

command -v iinfo >/dev/null || { echo "FAIL: iinfo is not installed (openimageio-tools)" >&2; exit 1; }

# Three frames of a ball crossing the image.
cat >"$tmp/move.xml" <<'XML'
<scene version="1">
  <animation frames="3"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="2 4 5"/>
  <sphere center="${-1.5 + 3 * clock} 0 0" radius="0.6"><material diffuse="0.9 0.3 0.1"/></sphere>
</scene>
XML
if ! bash "$src/scripts/animation_gif" --lucent "$lucent" --size 40x30 --fps 10 \
     "$tmp/move.xml" "$tmp/move.gif" 2>"$tmp/move.log"; then
  fail "animation_gif failed: $(cat "$tmp/move.log")"
else
  info=$(iinfo -v "$tmp/move.gif")
  echo "$info" | grep -q '^ *3 subimages: 40x30' || fail "not 3 subimages of 40x30: $info"
  echo "$info" | grep -q 'FramesPerSecond: 100/10 (10)' || fail "not 10 frames a second: $info"
  echo "$info" | grep -q 'LoopCount: 0' || fail "the GIF does not loop forever: $info"
  # Each frame is its own moment: the first and the last subimage differ (their mean
  # colours; the files of two equal frames differ too, by the GIF's transparency).
  first=$(oiiotool "$tmp/move.gif" --subimage 0 --printstats | grep 'Stats Avg')
  last=$(oiiotool "$tmp/move.gif" --subimage 2 --printstats | grep 'Stats Avg')
  [ -n "$first" ] || fail "oiiotool could not read the GIF's first subimage back"
  [ "$first" != "$last" ] || fail "the first and the last frame are the same: $first"
fi

# No <animation>: an error, no file.
cat >"$tmp/still.xml" <<'XML'
<scene version="1">
  <camera position="0 0 5" look-at="0 0 0"/>
  <sphere/>
</scene>
XML
if bash "$src/scripts/animation_gif" --lucent "$lucent" "$tmp/still.xml" "$tmp/still.gif" \
     2>"$tmp/still.log"; then
  fail "a scene without <animation> was accepted"
fi
grep -q 'has no <animation frames="N">' "$tmp/still.log" || fail "unexpected message: $(cat "$tmp/still.log")"
[ ! -e "$tmp/still.gif" ] || fail "a scene without <animation> wrote a GIF"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "animation_gif: a 3-frame GIF written and read back"
