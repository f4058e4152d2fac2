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
for type in pinhole thin-lens orthographic fisheye panini lenslet octahedral cubemap fibonacci; do
  if [ "$type" = pinhole ]; then pattern='<camera position'; else pattern="type=\"$type\""; fi
  grep -l -q "$pattern" "$src"/examples/cameras/*.xml || fail "no example uses a $type camera"
done
[ "$count" -ge 9 ] || fail "only $count camera examples"
if [ $failures -eq 0 ]; then
  echo "camera_examples: OK: $count examples"
  exit 0
fi
echo "camera_examples: FAIL: $failures failures"
exit 1
