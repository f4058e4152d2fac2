#!/usr/bin/env bash
# lucent render --stats: rays by kind, searches, intersection tests by kind of
# shape (only the kinds the scene has), time and Mrays/s. A 16x12 image of a sphere on a
# plane, seen from above, under one point light: every pixel's primary ray hits and is lit.
# Usage: bash render_stats.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="16" height="12"/>
  <camera position="0 10 0.001" look-at="0 0 0" fov="20"/>
  <light position="0 20 0"/>
  <plane normal="0 1 0" offset="0"/>
  <sphere center="0 0.5 0" radius="0.5"/>
</scene>
XML

"$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" --stats -q >"$tmp/stdout" 2>"$tmp/stderr" ||
  fail "render --stats exited with $?: $(cat "$tmp/stderr")"
cat "$tmp/stdout"
# number LABEL: the first number on the line starting with LABEL.
number() { sed -n "s/^$1: *\([0-9.]*\).*/\1/p" "$tmp/stdout"; }
[ "$(number rays)" = 384 ] || fail "rays: expected 384 (192 primary + 192 shadow), got '$(number rays)'"
grep -q '^rays: .*(primary 192, shadow 192, reflected 0, refracted 0)' "$tmp/stdout" ||
  fail "rays by kind wrong"
[ "$(number searches)" = 384 ] || fail "searches: expected 384, got '$(number searches)'"
# The plane is tested by every ray (it is unbounded); the sphere by the rays whose path
# crosses its box; nothing else is listed.
grep -q '^tests: .*(spheres [0-9][0-9]*, planes 384)$' "$tmp/stdout" ||
  fail "tests by kind: expected spheres and planes 384 only"
tests=$(number tests)
spheres=$(sed -n 's/^tests:.*spheres \([0-9]*\).*/\1/p' "$tmp/stdout")
[ -n "$spheres" ] && [ "$tests" -eq $((spheres + 384)) ] || fail "tests total $tests is not the sum"
[ "$spheres" -gt 0 ] 2>/dev/null || fail "no sphere tests counted"
grep -q '^time: *[0-9.]* *s' "$tmp/stdout" || fail "no time line"
grep -q '^speed: *[0-9.]* *Mrays/s on [0-9]* threads' "$tmp/stdout" || fail "no speed line"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "--stats prints rays, searches, tests by kind, time and speed"
