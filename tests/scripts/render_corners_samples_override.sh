#!/usr/bin/env bash
# A scene with adaptive-mode="corners" renders on its pixel corners: a flat 16x12 image
# (one tile, the background only) takes its 17 x 13 corners and nothing else. `-s N` asks
# for N samples a pixel instead, and gets them everywhere (corner sampling gives way).
# Usage: bash render_corners_samples_override.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="16" height="12" background="0.2 0.3 0.4" adaptive="0.3" adaptive-mode="corners"/>
  <camera position="0 0 5"/>
</scene>
XML

"$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" --stats -q >"$tmp/corners" 2>"$tmp/stderr" ||
  fail "render exited with $?: $(cat "$tmp/stderr")"
grep -q '^rays: .*(primary 221,' "$tmp/corners" ||
  fail "corners: expected 17 x 13 = 221 primary rays: $(grep '^rays' "$tmp/corners")"
"$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -s 4 --stats -q >"$tmp/samples" 2>"$tmp/stderr" ||
  fail "render -s 4 exited with $?: $(cat "$tmp/stderr")"
grep -q '^rays: .*(primary 768,' "$tmp/samples" ||
  fail "-s 4: expected 4 x 16 x 12 = 768 primary rays: $(grep '^rays' "$tmp/samples")"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "corner sampling traces the corners; -s N replaces it by N samples a pixel"
