#!/usr/bin/env bash
# lucent render --stats prints the shadow cache's hits: shadow rays blocked by the object
# that blocked the previous ray towards the same light, tested first. A 16x16 image (one
# tile) of a floor seen from above with a disc floating over it, whose shadow from a point
# light falls partly in view. The disc is the only blocker, so every blocked shadow ray
# but the first is a cache hit, and each hit spares the floor plane's test: the plane is
# tested by the 256 primary rays and by the 256 shadow rays less the hits.
# Usage: bash render_stats_cache.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="16" height="16"/>
  <camera position="0 20 0" look-at="0 0 0" up="0 0 -1" fov="30"/>
  <light position="3 10 0"/>
  <plane normal="0 1 0" offset="0"/>
  <disc center="0 3 0" normal="0 1 0" radius="1.5"/>
</scene>
XML

"$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" --stats -q >"$tmp/stdout" 2>"$tmp/stderr" ||
  fail "render --stats exited with $?: $(cat "$tmp/stderr")"
cat "$tmp/stdout"
number() { sed -n "s/^$1: *\([0-9.]*\).*/\1/p" "$tmp/stdout"; }
grep -q '^rays: .*(primary 256, shadow 256, reflected 0, refracted 0)' "$tmp/stdout" ||
  fail "expected 256 primary and 256 shadow rays"
hits=$(number "cache hits")
planes=$(sed -n 's/^tests:.*planes \([0-9]*\).*/\1/p' "$tmp/stdout")
[ -n "$hits" ] || fail "no 'cache hits:' line"
[ -n "$hits" ] && [ "$hits" -gt 10 ] 2>/dev/null || fail "cache hits: expected more than 10, got '$hits'"
[ -n "$planes" ] && [ -n "$hits" ] && [ "$planes" -eq $((512 - hits)) ] ||
  fail "plane tests $planes are not 512 - cache hits ($hits)"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "--stats prints the shadow cache's hits, and each spares a plane test"
