#!/usr/bin/env bash
# The camera examples (examples/cameras/*.xml, one per camera type): each passes
# `lucent check` cleanly, renders (small, one sample) with exit status 0, and has its
# picture in docs/images/cameras/ shown by docs/cameras.md.
# Run by CTest as: bash camera_examples.sh <lucent-binary> <source-dir>
set -u
lucent=${1:?usage: camera_examples.sh <lucent-binary> <source-dir>}
src=${2:?usage: camera_examples.sh <lucent-binary> <source-dir>}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

count=0
for f in "$src"/examples/cameras/*.xml; do
  name=$(basename "$f" .xml)
  count=$((count + 1))
  if ! "$lucent" check "$f" >"$work/out" 2>"$work/err"; then
    cat "$work/err"; fail "lucent check $name"
  elif grep -q -e 'warning:' -e 'error:' "$work/err"; then
    cat "$work/err"; fail "lucent check $name is not clean"
  fi
  # 48 x 36 divides into whole cube faces (cross: 12 x 12).
  if ! "$lucent" render "$f" -o "$work/$name.png" -w 48 -h 36 -s 1 -q 2>"$work/err"; then
    cat "$work/err"; fail "lucent render $name"
  elif [ ! -s "$work/$name.png" ]; then
    fail "lucent render $name wrote no image"
  fi
  [ -s "$src/docs/images/cameras/$name.png" ] || fail "docs/images/cameras/$name.png is missing"
  grep -q "images/cameras/$name.png" "$src/docs/cameras.md" || fail "docs/cameras.md does not show $name.png"
done
# One example per camera type of the contract.
for type in pinhole thin-lens orthographic fisheye panini lenslet octahedral cubemap fibonacci \
  spherical; do
  if [ "$type" = pinhole ]; then pattern='<camera position'; else pattern="type=\"$type\""; fi
  grep -l -q "$pattern" "$src"/examples/cameras/*.xml || fail "no example uses a $type camera"
done
[ "$count" -ge 10 ] || fail "only $count camera examples"

# Sizes and angles a camera cannot frame are invalid scenes (exit 2) located at the camera,
# and an existing output is left as it was.
echo keep >"$work/keep.png"
"$lucent" render "$src/examples/cameras/cubemap.xml" -o "$work/keep.png" -w 50 -h 36 -q 2>"$work/err"
status=$?
[ "$status" -eq 2 ] || fail "cube map 50x36: exit status $status, expected 2"
grep -q 'cubemap.xml:8:3: error: a cubemap camera with layout="cross" needs a width divisible by 4 and a height divisible by 3 (got 50x36' "$work/err" ||
  fail "cube map 50x36: unexpected message: $(cat "$work/err")"
[ "$(cat "$work/keep.png")" = keep ] || fail "cube map 50x36 replaced the existing output"
cat >"$work/fold.xml" <<'XML'
<scene version="1">
  <camera type="panini" distance="2" fov="240"/>
  <sphere/>
</scene>
XML
"$lucent" check "$work/fold.xml" >/dev/null 2>"$work/err"
status=$?
[ "$status" -eq 2 ] || fail "panini fov 240 at distance 2: lucent check exit status $status, expected 2"
grep -q "fold.xml:2:43: error: <camera> attribute 'fov': with distance 2 a panini camera's fov must be below 240" "$work/err" ||
  fail "panini fov 240 at distance 2: unexpected message: $(cat "$work/err")"
if [ $failures -eq 0 ]; then
  echo "camera_examples: OK: $count examples"
  exit 0
fi
echo "camera_examples: FAIL: $failures failures"
exit 1
