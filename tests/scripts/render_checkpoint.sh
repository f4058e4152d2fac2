#!/usr/bin/env bash
# Regions and resumable renders on the command line (docs/distributed.md): --region writes
# those pixels, equal to the same pixels of the whole image, and regions stitched with
# oiiotool give the whole image back; an interrupted render leaves a checkpoint that
# --resume completes to the same bytes as an uninterrupted render, in every sampling mode,
# with other thread counts, after a torn write and across an animation's frames; a
# checkpoint of another scene, other options or a changed texture is refused, naming what
# differs; a damaged one is a clear error.
# Usage: bash render_checkpoint.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
command -v oiiotool >/dev/null || skip "oiiotool (openimageio-tools) is not installed"

expect() {
  local want=$1 what=$2
  shift 3
  "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  [ "$got" -eq "$want" ] || fail "$what: exit status $got, expected $want; stderr: $(cat "$tmp/stderr")"
}
# same_pixels A B WHAT: the two images hold the same pixel values (any file format).
same_pixels() {
  oiiotool "$1" "$2" --diff --fail 0 >"$tmp/diff" 2>&1 || fail "$3: pixels differ: $(tail -4 "$tmp/diff")"
}

# A texture for the scene, made by lucent itself.
mkdir "$tmp/tex"
cat > "$tmp/tex/make.xml" <<'XML'
<scene version="1">
  <render width="32" height="32"/>
  <camera position="0 0 4" look-at="0 0 0"/>
  <light position="3 3 5"/>
  <sphere radius="1.2"><material diffuse="1 0.4 0.1"/></sphere>
</scene>
XML
"$lucent" render "$tmp/tex/make.xml" -o "$tmp/tex/wood.png" -q || fail "making the texture"

# MODE: the <render> attributes of a sampling mode.
scene() {
  cat > "$tmp/scene.xml" <<XML
<scene version="1">
  <render width="90" height="60" $1/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light type="area" position="3 5 4" u="1 0 0" v="0 0 1" samples="3 3" jitter="true"/>
  <plane normal="0 1 0"><material diffuse="1"><image src="tex/wood.png" scale="2 2"/></material></plane>
  <sphere center="0.6 0.7 0" radius="0.7"><material transmissive="0.8" ior="1.5" reflective="0.1"/></sphere>
  <box min="-1.8 0 -0.5" max="-0.6 1.2 0.5"><material diffuse="0.3 0.5 1" reflective="0.3"/></box>
</scene>
XML
}

modes=("samples=\"1\"" "samples=\"4\"" "samples=\"16\" adaptive=\"0.05\"" "adaptive=\"0.2\" adaptive-mode=\"corners\" adaptive-depth=\"3\"")
for mode in "${modes[@]}"; do
  scene "$mode"
  "$lucent" render "$tmp/scene.xml" -o "$tmp/whole.png" -q || fail "$mode: whole render"
  # A region equals the same pixels of the whole image; odd bounds on purpose.
  expect 0 "$mode: region" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/region.png" -q --region 13,7,61,45
  oiiotool "$tmp/whole.png" --cut 48x38+13+7 --origin +0+0 -o "$tmp/cut.png" 2>/dev/null
  [ "$(oiiotool --info "$tmp/region.png" | grep -o '48 x  *38')" != "" ] || fail "$mode: region size: $(oiiotool --info "$tmp/region.png")"
  same_pixels "$tmp/region.png" "$tmp/cut.png" "$mode: region"
  # Three regions stitched with oiiotool (docs/distributed.md) give the whole image back.
  "$lucent" render "$tmp/scene.xml" -o "$tmp/r1.png" -q --region 0,0,50,60
  "$lucent" render "$tmp/scene.xml" -o "$tmp/r2.png" -q --region 50,0,90,25
  "$lucent" render "$tmp/scene.xml" -o "$tmp/r3.png" -q --region 50,25,90,60
  oiiotool "$tmp/r1.png" --pattern constant:color=0,0,0 90x60 3 --paste +0+0 \
           "$tmp/r2.png" --swap --paste +50+0 "$tmp/r3.png" --swap --paste +50+25 -d uint8 -o "$tmp/stitched.png"
  same_pixels "$tmp/stitched.png" "$tmp/whole.png" "$mode: stitched regions"

  # Interrupted after 3 tiles (of 6 at --tile-size 32) on 2 threads, resumed on 1.
  rm -f "$tmp/out.png"
  LUCENT_TEST_INTERRUPT_AFTER_TILES=3 expect 3 "$mode: interrupted render" -- \
    "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q -t 2 --tile-size 32 --checkpoint-interval 0.001
  [ -f "$tmp/out.png.checkpoint" ] || fail "$mode: no checkpoint after the interrupt"
  [ -f "$tmp/out.png" ] && fail "$mode: an interrupted render wrote its image"
  expect 0 "$mode: resumed render" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -t 1 --tile-size 32 --resume
  grep -q "resuming '$tmp/out.png': [1-6] of 6 tiles from the checkpoint" "$tmp/stderr" ||
    fail "$mode: resume message: $(cat "$tmp/stderr")"
  cmp -s "$tmp/out.png" "$tmp/whole.png" || fail "$mode: the resumed image differs from an uninterrupted one"
  [ -f "$tmp/out.png.checkpoint" ] && fail "$mode: the checkpoint was not removed when the image was written"
done

# The same for a region, in float EXR (every bit of every pixel).
scene "samples=\"16\" adaptive=\"0.05\""
"$lucent" render "$tmp/scene.xml" -o "$tmp/region.exr" -q --region 20,10,77,51 || fail "EXR region"
LUCENT_TEST_INTERRUPT_AFTER_TILES=2 expect 3 "interrupted region" -- \
  "$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q --region 20,10,77,51 --tile-size 16 --checkpoint-interval 0.001
expect 1 "resume without the region" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q --tile-size 16 --resume
grep -q "error: --resume: the checkpoint '$tmp/out.exr.checkpoint' was made for another render; --region: '20,10,77,51' in the checkpoint, 'the whole image' in this render" "$tmp/stderr" ||
  fail "resume without the region: $(cat "$tmp/stderr")"
expect 0 "resumed region" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q --region 20,10,77,51 --tile-size 16 --resume
cmp -s "$tmp/out.exr" "$tmp/region.exr" || same_pixels "$tmp/out.exr" "$tmp/region.exr" "resumed EXR region"

# A checkpoint whose last write was cut short (a crash while writing): the whole records
# before it are used, the torn one dropped, and the image is the same.
scene "samples=\"4\""
"$lucent" render "$tmp/scene.xml" -o "$tmp/whole.png" -q
LUCENT_TEST_INTERRUPT_AFTER_TILES=4 expect 3 "interrupted for a torn write" -- \
  "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 --checkpoint-interval 0.001
size=$(stat -c %s "$tmp/out.png.checkpoint")
truncate -s $((size - 100)) "$tmp/out.png.checkpoint"
expect 0 "resume after a torn write" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" --tile-size 16 --resume
grep -q "resuming '$tmp/out.png': [0-9]* of 24 tiles" "$tmp/stderr" || fail "torn: $(cat "$tmp/stderr")"
cmp -s "$tmp/out.png" "$tmp/whole.png" || fail "the image resumed after a torn write differs"

# What does not belong is refused, saying what differs: other samples, a changed texture,
# a changed scene.
interrupted() {
  rm -f "$tmp/out.png.checkpoint"
  LUCENT_TEST_INTERRUPT_AFTER_TILES=2 "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 \
    --checkpoint-interval 0.001 2>/dev/null
}
interrupted
expect 1 "resume with other samples" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 -s 2 --resume
grep -q "was made for another render; --samples: 'the scene's' in the checkpoint, '2' in this render" "$tmp/stderr" ||
  fail "other samples: $(cat "$tmp/stderr")"
expect 1 "resume with another tile size" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --resume
grep -q -- "--tile-size: '16' in the checkpoint, 'the default' in this render" "$tmp/stderr" || fail "tile size: $(cat "$tmp/stderr")"
cp "$tmp/tex/wood.png" "$tmp/tex/wood-old.png"
"$lucent" render "$tmp/tex/make.xml" -o "$tmp/tex/wood.png" -q -w 16 -h 16
expect 1 "resume with a changed texture" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 --resume
grep -q "digest of $tmp/tex/wood.png: '[0-9a-f]*' in the checkpoint, '[0-9a-f]*' in this render" "$tmp/stderr" ||
  fail "changed texture: $(cat "$tmp/stderr")"
mv "$tmp/tex/wood-old.png" "$tmp/tex/wood.png"
interrupted
sed -i 's/radius="0.7"/radius="0.65"/' "$tmp/scene.xml"
expect 1 "resume with a changed scene" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 --resume
grep -q "digest of the scene XML: '[0-9a-f]*' in the checkpoint, '[0-9a-f]*' in this render" "$tmp/stderr" ||
  fail "changed scene: $(cat "$tmp/stderr")"
[ -f "$tmp/out.png.checkpoint" ] || fail "a refused resume removed the checkpoint"
# A comment changes nothing that is rendered: the checkpoint still belongs.
sed -i 's/radius="0.65"/radius="0.7"/; s|<camera|<!-- a note --><camera|' "$tmp/scene.xml"
expect 0 "resume after a comment was added" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --tile-size 16 --resume
cmp -s "$tmp/out.png" "$tmp/whole.png" || fail "resumed after a comment: the image differs"

# A file that is not a checkpoint, and --resume with none.
echo "not a checkpoint" >"$tmp/out.png.checkpoint"
expect 3 "a damaged checkpoint" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q --resume
grep -q "error: '$tmp/out.png.checkpoint' is not a Lucent checkpoint" "$tmp/stderr" || fail "damaged: $(cat "$tmp/stderr")"
rm -f "$tmp/out.png.checkpoint" "$tmp/out.png"
expect 0 "--resume without a checkpoint" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" --resume
grep -q "no checkpoint '$tmp/out.png.checkpoint' to resume; rendering from the start" "$tmp/stderr" ||
  fail "no checkpoint: $(cat "$tmp/stderr")"
cmp -s "$tmp/out.png" "$tmp/whole.png" || fail "--resume without a checkpoint: the image differs"
# --checkpoint-interval 0 keeps none, even when interrupted.
LUCENT_TEST_INTERRUPT_AFTER_TILES=2 expect 3 "interrupted without checkpoints" -- \
  "$lucent" render "$tmp/scene.xml" -o "$tmp/none.png" -q --tile-size 16 --checkpoint-interval 0
[ -e "$tmp/none.png.checkpoint" ] && fail "--checkpoint-interval 0 left a checkpoint"

# Bad options.
expect 1 "a region outside the image" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/x.png" --region 0,0,91,60
grep -q "error: --region 0,0,91,60: outside the 90x60 image" "$tmp/stderr" || fail "outside: $(cat "$tmp/stderr")"
expect 1 "an empty region" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/x.png" --region 5,5,5,9
expect 1 "a malformed region" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/x.png" --region 1,2,3
grep -q "expected X0,Y0,X1,Y1" "$tmp/stderr" || fail "malformed region: $(cat "$tmp/stderr")"
expect 1 "a tile size of 0" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/x.png" --tile-size 0
expect 1 "a negative interval" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/x.png" --checkpoint-interval -1

# An animation: interrupted in frame 2 of 3, resumed: frame 1 is skipped, not rendered again,
# and every frame equals an uninterrupted run's.
mkdir "$tmp/anim" "$tmp/plain"
sed 's|<render |<animation frames="3"/><render |; s|center="0.6 0.7 0"|center="${clock} 0.7 0"|' "$tmp/scene.xml" >"$tmp/anim.xml"
"$lucent" render "$tmp/anim.xml" -o "$tmp/plain/f.png" -q || fail "plain animation"
LUCENT_TEST_INTERRUPT_AFTER_TILES=30 expect 3 "interrupted animation" -- \
  "$lucent" render "$tmp/anim.xml" -o "$tmp/anim/f.png" -q --tile-size 16 --checkpoint-interval 0.001
[ -f "$tmp/anim/f0001.png" ] || fail "the animation's first frame was not written before the interrupt"
[ -f "$tmp/anim/f0002.png" ] && fail "the interrupted frame was written"
touch -d '2000-01-01' "$tmp/anim/f0001.png"
expect 0 "resumed animation" -- "$lucent" render "$tmp/anim.xml" -o "$tmp/anim/f.png" --tile-size 16 --resume
grep -q "frame 1: '$tmp/anim/f0001.png' was written before; skipped" "$tmp/stderr" || fail "skip: $(cat "$tmp/stderr")"
[ "$(stat -c %Y "$tmp/anim/f0001.png")" -lt 1000000000 ] || fail "the finished frame was rendered again"
for f in 1 2 3; do
  cmp -s "$tmp/anim/f000$f.png" "$tmp/plain/f000$f.png" || fail "resumed animation: frame $f differs"
done
[ -e "$tmp/anim/f.png.checkpoint" ] && fail "the animation's checkpoint was not removed at the end"

[ "$failures" -eq 0 ] && echo "render_checkpoint: all checks passed"
exit $((failures > 0))
