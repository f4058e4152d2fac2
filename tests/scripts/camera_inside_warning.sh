#!/usr/bin/env bash
# A camera below a plane whose normal points up is inside that solid: `lucent check` and
# `lucent render` both print the same located warning (and still succeed); with the camera
# above the plane neither prints anything on stderr but render's own line.
# Usage: bash camera_inside_warning.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cd "$tmp"
cat >below.xml <<'XML'
<scene version="1">
  <render width="16" height="12"/>
  <camera position="0 -1 3" look-at="0 1 0"/>
  <light position="0 5 0"/>
  <plane normal="0 1 0" offset="0">
    <material ambient="0.2" diffuse="0.7"/>
  </plane>
</scene>
XML
sed 's/position="0 -1 3" look-at="0 1 0"/position="0 1 3" look-at="0 0 0"/' below.xml >above.xml
grep -q 'position="0 1 3"' above.xml || fail "above.xml was not written"

expected='below.xml:5:3: warning: the camera at below.xml:3:3 is inside this opaque <plane>: its rays start inside it, so the surfaces they meet from inside lose their ambient term (inside an object it is multiplied by the transmissive colour, 0 here); to put the camera outside and keep the surface, negate the normal and the offset: normal="0 -1 0" offset="0"'

"$lucent" check below.xml >/dev/null 2>check.err || fail "check below.xml exited with $?"
[ "$(cat check.err)" = "$expected" ] || fail "check below.xml: stderr is: $(cat check.err)"
"$lucent" render below.xml -o below.png >/dev/null 2>render.err || fail "render below.xml exited with $?"
grep -qxF "$expected" render.err || fail "render below.xml: no warning in: $(cat render.err)"
[ -s below.png ] || fail "render below.xml wrote no image"

"$lucent" check above.xml >/dev/null 2>check.err || fail "check above.xml exited with $?"
[ ! -s check.err ] || fail "check above.xml: unexpected stderr: $(cat check.err)"
"$lucent" render above.xml -o above.png >/dev/null 2>render.err || fail "render above.xml exited with $?"
! grep -q "warning" render.err || fail "render above.xml: unexpected warning: $(cat render.err)"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "camera_inside_warning: all checks passed"
