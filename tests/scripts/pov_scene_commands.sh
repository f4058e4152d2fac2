#!/usr/bin/env bash
# `lucent check` and `lucent render` read POV-Ray scenes: the extension decides, --format
# overrides; every unsupported feature is an error at its place (exit 2); the image is
# POV-Ray's default size unless -w/-h; --skip-unsupported, --pov-library, --pov-ini,
# --pov-max-tokens; a
# mirrored, non-square camera; `convert` of the shapes the XML writes with lists, children
# and functions (a quartic as <poly>), rendered to the same bytes; `compare SCENE.pov` against POV-Ray on the scene itself.
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

# --skip-unsupported: the rest is rendered, each kind said once with its count of places.
"$lucent" render --skip-unsupported media.pov -w 20 -h 15 -o media.png -q 2>skip.err ||
  fail "render --skip-unsupported media.pov exited with $?: $(cat skip.err)"
[ -s media.png ] || fail "render --skip-unsupported wrote no image"
grep -qF "media.pov:1:33: warning: left out (--skip-unsupported): 'media' is not supported by Lucent (participating media" skip.err ||
  fail "--skip-unsupported: media not said in: $(cat skip.err)"
grep -qF "'photons' is not supported by Lucent (photon mapping of caustics); 1 place" skip.err ||
  fail "--skip-unsupported: photons not counted in: $(cat skip.err)"
[ "$(grep -c "left out" skip.err)" -eq 2 ] || fail "--skip-unsupported: not one line per kind: $(cat skip.err)"

# --pov-library: #include searches the folder; --pov-ini: the INI file's size, Declare= and
# animation (frame 3 of 5 has clock 0.5: the sphere's colour says which clock was used).
mkdir -p lib
echo '#declare Tint = rgb <1, 0, 0>;' >lib/tint.inc
cat >anim.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "tint.inc"
camera { location <0, 0, -3> look_at 0 }
background { rgb <clock, frame_number / 10, Size> }
POV
"$lucent" check anim.pov >/dev/null 2>lib.err && fail "anim.pov found tint.inc without --pov-library"
grep -qF "tint.inc" lib.err || fail "anim.pov: the missing include is not named: $(cat lib.err)"
cat >anim.ini <<'INI'
Width=8
Height=6
Initial_Frame=1
Final_Frame=5
Initial_Clock=0
Final_Clock=1
Declare=Size=0.25
Antialias=On
INI
"$lucent" render anim.pov --pov-library lib --pov-ini anim.ini --frames 3 -o anim.ppm -q 2>anim.err ||
  fail "render --pov-ini anim.ini exited with $?: $(cat anim.err)"
frame=anim0003.ppm
[ -s "$frame" ] || fail "render --pov-ini: frame 3 not written as $frame: $(ls)"
# An 8x6 binary PPM: the header, then the first pixel's bytes (linear 0.5, 0.3, 0.25 as sRGB).
pixel=$(tail -c $((8 * 6 * 3)) "$frame" | head -c 3 | od -An -tu1 | tr -s ' ')
[ "$pixel" = " 188 149 137" ] || fail "render --pov-ini frame 3: first pixel '$pixel', not 188 149 137 (clock 0.5, frame_number 3, Size 0.25)"
# A warning of every frame is printed once, as for an XML animation.
echo 'sphere { 0, 1 scale <1, 0, 1> pigment { Tint } }' >>anim.pov
"$lucent" render anim.pov --pov-library lib --pov-ini anim.ini --frames 1..3 -o warn.ppm -q 2>warn.err ||
  fail "render 3 frames exited with $?: $(cat warn.err)"
[ "$(grep -c "scale by 0 is taken as 1" warn.err)" -eq 1 ] ||
  fail "the warning of 3 frames is not printed once: $(cat warn.err)"
"$lucent" check anim.pov --pov-library lib --pov-ini missing.ini >/dev/null 2>ini.err
[ $? -eq 1 ] || fail "check --pov-ini missing.ini: not a usage error"
grep -qF "missing.ini: error: cannot read the INI file" ini.err || fail "--pov-ini missing.ini: $(cat ini.err)"

# A POV-Ray camera with `right -x` and non-square pixels (|right|/|up| is not the image's).
cat >mirror.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> right -2*x up 2*y look_at 0 }
light_source { <0, 0, -10> color rgb 1 }
sphere { <0.5, 0, 0>, 0.3 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
POV
"$lucent" convert mirror.pov -o mirror.xml 2>conv.err || fail "convert mirror.pov: $(cat conv.err)"
grep -q 'mirror="true"' mirror.xml || fail "convert mirror.pov: no mirror in $(grep camera mirror.xml)"
grep -q 'frame-aspect="1"' mirror.xml || fail "convert mirror.pov: no frame-aspect in $(grep camera mirror.xml)"

# The shapes whose parameters are lists, children or a function convert to a scene that
# renders to the same bytes; a quartic is written as the <poly> it is.
cat >shapes.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
#declare K = 0.1;
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0,
  0, 0, 0, 1, 0, 0, 0, -0.5> sturm
  pigment { rgb 1 } translate <-2, 0.5, 0> }
lathe { cubic_spline 6, <0, 0>, <0.5, 0>, <0.6, 0.5>, <0.3, 1>, <0.4, 1.4>, <0, 1.5>
  pigment { rgb <1, 0.5, 0.2> } translate <-1, 0, 1> }
sor { 5, <0, -0.5>, <0.6, 0>, <0.9, 0.4>, <0.4, 1>, <0.5, 1.4> open pigment { rgb 0.7 } }
prism { conic_sweep linear_spline 0.2, 1, 5, <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>,
  <-0.5, 0.5>, <-0.5, -0.5> pigment { rgb <0.2, 0.6, 1> } translate <1, 0, 0> }
blob { threshold 0.5 sphere { <0, 0, 0>, 0.8, 1 } cylinder { <0, 0, 0>, <0, 1, 0>, 0.3, 1 }
  pigment { rgb <0.4, 1, 0.4> } translate <2, 0, 0> }
isosurface { function { sqrt(x*x + y*y + z*z) - 0.5 + K*sin(10*x) }
  contained_by { sphere { 0, 0.8 } } max_gradient 2 pigment { rgb 1 } translate <0, 2, 0> }
mesh { triangle { <-3, 0, 2>, <3, 0, 2>, <3, 0, 4> } triangle { <-3, 0, 2>, <3, 0, 4>, <-3, 0, 4> }
  pigment { rgb 0.5 } }
POV
"$lucent" convert shapes.pov -o shapes.xml 2>conv.err || fail "convert shapes.pov: $(cat conv.err)"
grep -q '<poly order="4"' shapes.xml || fail "convert shapes.pov: no <poly> in $(grep -c . shapes.xml) lines"
"$lucent" render shapes.pov -w 40 -h 30 -q -o shapes.pov.ppm 2>shapes.err ||
  fail "render shapes.pov: $(cat shapes.err)"
"$lucent" render shapes.xml -w 40 -h 30 -q -o shapes.xml.ppm 2>shapes.err ||
  fail "render shapes.xml: $(cat shapes.err)"
cmp -s shapes.pov.ppm shapes.xml.ppm || fail "convert shapes.pov: the XML renders differently"

# --pov-max-tokens: the evaluation's token limit, named in the refusal; raised, the scene reads.
cat >loop.pov <<'POV'
#declare I = 0;
#while (I < 200) sphere { <I, 0, 0>, 0.4 } #declare I = I + 1; #end
POV
"$lucent" check loop.pov --pov-max-tokens 500 >/dev/null 2>tokens.err
[ $? -eq 2 ] || fail "check --pov-max-tokens 500 loop.pov did not refuse it: $(cat tokens.err)"
grep -qF "error: the scene reads more than 500 tokens (the limit of an evaluation, which --pov-max-tokens raises" tokens.err ||
  fail "--pov-max-tokens 500: $(cat tokens.err)"
"$lucent" check loop.pov --pov-max-tokens 100000 >/dev/null 2>tokens.err ||
  fail "check --pov-max-tokens 100000 loop.pov: $(cat tokens.err)"
"$lucent" check loop.pov --pov-max-tokens 0 >/dev/null 2>tokens.err
[ $? -eq 1 ] || fail "--pov-max-tokens 0 is not a usage error: $(cat tokens.err)"

# compare SCENE.pov runs POV-Ray on the scene itself.
if command -v povray >/dev/null; then
  "$lucent" compare ball.pov -w 40 -h 30 -o cmp >cmp.out 2>cmp.err ||
    fail "compare ball.pov exited with $?: $(cat cmp.err)"
  # At least 40 dB (inf when identical).
  psnrAtLeast40() { grep -Eq "^psnr: +(inf|[4-9][0-9]\.|[1-9][0-9][0-9]+\.)" "$1"; }
  psnrAtLeast40 cmp.out || fail "compare ball.pov: $(cat cmp.out)"
  grep -q '"pov_scene_hand_written": true' cmp/report.json || fail "compare ball.pov: not the scene itself"
  "$lucent" compare mirror.pov -w 40 -h 20 -o cmpm >cmpm.out 2>&1 || fail "compare mirror.pov: $(cat cmpm.out)"
  psnrAtLeast40 cmpm.out || fail "compare mirror.pov: $(cat cmpm.out)"
  # An assumed_gamma in an include: POV-Ray's image is read back with it (the scene's own
  # text does not hold it).
  cat >gamma.inc <<'POV'
global_settings { assumed_gamma 2.2 }
camera { location <0, 0, -3> look_at 0 }
light_source { <-2, 3, -4> rgb 1 }
sphere { 0, 1 pigment { rgb <0.2, 0.5, 0.8> } }
POV
  echo '#include "gamma.inc"' >gamma.pov
  # A scene with no #version anywhere (no standard include either) is a legacy scene in
  # POV-Ray 3.7: gamma off (its numbers written as they are), 3.6's opacity of a filtering
  # pigment. The two programs' own PNGs agree.
  cat >legacy.pov <<'POV'
camera { location <0, 0, -4> look_at 0 }
background { rgb <0.2, 0.4, 0.6> }
box { <-1.5, -1, -1>, <0, 1, 1> pigment { rgb 0.5 } finish { ambient 1 diffuse 0 } }
box { <0.2, -1, -1>, <1.5, 1, -0.9> pigment { rgbf <0.7, 0.6, 0.5, 0.6> } finish { ambient 1 diffuse 0 } }
POV
  "$lucent" render legacy.pov -w 32 -h 24 -q -o legacy.lucent.png 2>legacy.err ||
    fail "render legacy.pov: $(cat legacy.err)"
  povray +W32 +H24 -D -GA +Ilegacy.pov +Olegacy.povray.png >legacy.log 2>&1 ||
    fail "povray legacy.pov: $(tail -3 legacy.log)"
  oiiotool legacy.lucent.png legacy.povray.png --diff --fail 0.01 >legacy.diff 2>&1 ||
    fail "a scene without #version: Lucent's PNG is not POV-Ray's: $(cat legacy.diff)"
  "$lucent" compare gamma.pov -w 40 -h 30 -o cmpg >cmpg.out 2>&1 || fail "compare gamma.pov: $(cat cmpg.out)"
  psnrAtLeast40 cmpg.out || fail "compare gamma.pov (assumed_gamma in an include): $(cat cmpg.out)"
fi

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "pov_scene_commands: all checks passed"
