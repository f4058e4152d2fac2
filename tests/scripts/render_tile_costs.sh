#!/usr/bin/env bash
# lucent render --tile-costs FILE (the trace bench/tile_schedule reads, in the format of
# bench/tile_cost_trace.h): the header names the image, tile size, threads, samples, load
# time and scene; every tile has one line, in row order (the tiles are rendered one after
# another, so each time is the tile's own); the image is the same bytes as without it; a
# region's trace lists the region's tiles; an animation needs one frame.
# Usage: bash render_tile_costs.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="90" height="60" samples="4"/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light position="3 5 4"/>
  <plane normal="0 1 0"><material diffuse="0.8"/></plane>
  <sphere center="0.6 0.7 0" radius="0.7"><material diffuse="1 0.4 0.1" reflective="0.2"/></sphere>
</scene>
XML

"$lucent" render "$tmp/scene.xml" -o "$tmp/plain.png" -q || fail "render without --tile-costs"
"$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q -t 2 --tile-size 32 --tile-costs "$tmp/costs.txt" \
  2>"$tmp/stderr" || fail "render --tile-costs exited with $?: $(cat "$tmp/stderr")"
cmp -s "$tmp/out.png" "$tmp/plain.png" || fail "--tile-costs changed the image"
[ "$(sed -n 1p "$tmp/costs.txt")" = "# lucent tile costs 1" ] || fail "first line: $(sed -n 1p "$tmp/costs.txt")"
grep -qx "# image 90 60 tile 32 threads 2 samples 4 load [0-9]*\.[0-9]\{6\} scene $tmp/scene.xml" "$tmp/costs.txt" ||
  fail "header: $(sed -n 2p "$tmp/costs.txt")"
[ "$(sed -n 3p "$tmp/costs.txt")" = "x0 y0 x1 y1 seconds" ] || fail "column line: $(sed -n 3p "$tmp/costs.txt")"
# 3 x 2 tiles of 32, the last column and row cut to the image, in row order.
expected="0 0 32 32
32 0 64 32
64 0 90 32
0 32 32 60
32 32 64 60
64 32 90 60"
[ "$(sed -n '4,$p' "$tmp/costs.txt" | cut -d' ' -f1-4)" = "$expected" ] ||
  fail "tiles: $(sed -n '4,$p' "$tmp/costs.txt")"
awk 'NR > 3 && !($5 ~ /^[0-9]+\.[0-9]+$/ && length($5) - index($5, ".") == 9 && $5 > 0) { bad = 1 }
     END { exit bad }' "$tmp/costs.txt" ||
  fail "a tile's seconds are not a positive number with 9 decimals: $(cat "$tmp/costs.txt")"

# A region: its own tiles only.
"$lucent" render "$tmp/scene.xml" -o "$tmp/region.png" -q -t 1 --region 10,5,50,45 --tile-size 32 \
  --tile-costs "$tmp/region.txt" || fail "region with --tile-costs"
[ "$(sed -n '4,$p' "$tmp/region.txt" | cut -d' ' -f1-4)" = "10 5 42 37
42 5 50 37
10 37 42 45
42 37 50 45" ] || fail "region tiles: $(cat "$tmp/region.txt")"
grep -q "^# image 90 60 tile 32 threads 1 " "$tmp/region.txt" || fail "region header: $(sed -n 2p "$tmp/region.txt")"

# An animation: one frame's tiles or none.
sed 's#<scene version="1">#<scene version="1">\n  <animation frames="3"/>#' "$tmp/scene.xml" >"$tmp/anim.xml"
"$lucent" render "$tmp/anim.xml" -o "$tmp/anim#.png" -q --tile-costs "$tmp/anim.txt" 2>"$tmp/stderr"
[ $? -eq 1 ] || fail "--tile-costs over an animation's frames: expected exit status 1"
grep -q "error: --tile-costs records the tiles of one frame: give --frames F or -D frame=F" "$tmp/stderr" ||
  fail "animation message: $(cat "$tmp/stderr")"
"$lucent" render "$tmp/anim.xml" -o "$tmp/anim#.png" -q --frames 2 --tile-size 32 --tile-costs "$tmp/anim.txt" ||
  fail "--tile-costs with --frames 2"
[ "$(sed -n '4,$p' "$tmp/anim.txt" | wc -l)" -eq 6 ] || fail "frame 2's tiles: $(cat "$tmp/anim.txt")"

[ "$failures" -eq 0 ] && echo "render_tile_costs: all checks passed"
exit $((failures > 0))
