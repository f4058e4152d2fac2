#!/usr/bin/env bash
# The accuracy examples (examples/accuracy/*.xml, docs/accuracy.md): each passes
# `lucent check` cleanly and renders; the still life scaled by 1e-4 renders exactly the
# same pixels as at unit scale (no scene-dependent epsilon anywhere); each POV-Ray twin
# (*.pov) parses and renders in POV-Ray (a missing povray fails, as in the other POV-Ray
# tests: scripts/install-deps installs it); the doc shows every comparison.
# Run by CTest as: bash accuracy_examples.sh <lucent-binary> <source-dir>
set -u
lucent=${1:?usage: accuracy_examples.sh <lucent-binary> <source-dir>}
src=${2:?usage: accuracy_examples.sh <lucent-binary> <source-dir>}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

count=0
for f in "$src"/examples/accuracy/*.xml; do
  name=$(basename "$f" .xml)
  count=$((count + 1))
  if ! "$lucent" check "$f" >"$work/out" 2>"$work/err"; then
    cat "$work/err"; fail "lucent check $name"
  elif grep -q -e 'warning:' -e 'error:' "$work/err"; then
    cat "$work/err"; fail "lucent check $name is not clean"
  fi
  if ! "$lucent" render "$f" -o "$work/$name.ppm" -w 80 -h 60 -q 2>"$work/err"; then
    cat "$work/err"; fail "lucent render $name"
  fi
  pov="$src/examples/accuracy/$name.pov"
  if [ -f "$pov" ]; then
    for image in lucent povray diff; do
      [ -s "$src/docs/images/accuracy/${name}_$image.png" ] ||
        fail "docs/images/accuracy/${name}_$image.png is missing"
      grep -q "images/accuracy/${name}_$image.png" "$src/docs/accuracy.md" ||
        fail "docs/accuracy.md does not show ${name}_$image.png"
    done
    if ! command -v povray >/dev/null; then
      fail "povray is not installed (scripts/install-deps installs it): $name.pov is not checked"
    elif ! povray +I"$pov" +O"$work/$name-pov.png" +W32 +H24 -D -V -GS -GR 2>"$work/err"; then
      tail -5 "$work/err"; fail "povray cannot render $name.pov"
    fi
  fi
done
[ "$count" -ge 5 ] || fail "only $count accuracy examples"
# Same pixels at 1e-4 as at unit scale (PPM: the bytes are the pixels).
if ! cmp -s "$work/scaled_1.ppm" "$work/scaled_1e-4.ppm"; then
  fail "the still life scaled by 1e-4 renders differently from the same scene at unit scale"
fi
if [ $failures -eq 0 ]; then
  echo "accuracy_examples: OK: $count examples"
  exit 0
fi
echo "accuracy_examples: FAIL: $failures failures"
exit 1
