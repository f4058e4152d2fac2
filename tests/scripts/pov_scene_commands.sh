#!/usr/bin/env bash
# `lucent check` and `lucent render` read POV-Ray scenes: the extension decides, --format
# overrides; every unsupported feature is an error at its place (exit 2); the image is
# POV-Ray's default size unless -w/-h.
# Usage: bash pov_scene_commands.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cd "$tmp"
cat >ball.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> right x*4/3 look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.5, 0.2> } }
plane { y, 0 pigment { rgb 0.8 } }
POV
"$lucent" check ball.pov >check.out 2>check.err || fail "check ball.pov exited with $?: $(cat check.err)"
grep -q "sphere" check.out || fail "check ball.pov: no summary in: $(cat check.out)"
"$lucent" render ball.pov -w 40 -h 30 -o ball.png -q 2>render.err ||
  fail "render ball.pov exited with $?: $(cat render.err)"
[ -s ball.png ] || fail "render ball.pov wrote no image"

cp ball.pov ball.txt
"$lucent" check ball.txt >/dev/null 2>&1 && fail "check ball.txt read a .txt file as XML without error"
"$lucent" check --format pov ball.txt >/dev/null 2>check.err ||
  fail "check --format pov ball.txt exited with $?: $(cat check.err)"

cat >media.pov <<'POV'
sphere { 0, 1 hollow interior { media { emission 1 } } }
sphere { 0, 1 photons { target } }
POV
"$lucent" check media.pov >/dev/null 2>check.err
status=$?
[ "$status" -eq 2 ] || fail "check media.pov exited with $status, not 2"
grep -qF "media.pov:1:33: error: 'media' is not supported by Lucent" check.err ||
  fail "check media.pov: no media error in: $(cat check.err)"
grep -qF "media.pov:2:15: error: 'photons' is not supported by Lucent" check.err ||
  fail "check media.pov: no photons error in: $(cat check.err)"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "pov_scene_commands: all checks passed"
