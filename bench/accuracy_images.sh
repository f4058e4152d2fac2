#!/usr/bin/env bash
# Renders the POV-Ray comparisons of docs/accuracy.md: every examples/accuracy/*.xml with
# Lucent and its hand-written twin *.pov with POV-Ray 3.7 (320 x 240, no anti-aliasing),
# and their absolute difference scaled by 4, into docs/images/accuracy/. Prints how many
# pixels differ. Needs a built lucent, povray and oiiotool (openimageio-tools).
#
#   bash bench/accuracy_images.sh [path/to/lucent]     # default: build/cli/lucent
set -euo pipefail
cd "$(dirname "$0")/.."
lucent=${1:-build/cli/lucent}
out=docs/images/accuracy
mkdir -p "$out"
for xml in examples/accuracy/*.xml; do
  name=$(basename "$xml" .xml)
  pov=examples/accuracy/$name.pov
  [ -f "$pov" ] || continue  # scaled_1.xml: Lucent only, compared with scaled_1e-4 below
  "$lucent" render "$xml" -o "$out/${name}_lucent.png" -q
  povray +I"$pov" +O"$out/${name}_povray.png" +W320 +H240 -D -V -GS -GR 2>/dev/null
  oiiotool "$out/${name}_lucent.png" "$out/${name}_povray.png" --absdiff --mulc 4 \
    -o "$out/${name}_diff.png"
  echo "$name: $(oiiotool "$out/${name}_lucent.png" "$out/${name}_povray.png" --diff 2>&1 |
    grep -E 'PASS|pixels' | head -1 | sed 's/^ *//')"
done
# Lucent at 1e-4 against the same scene at unit scale.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lucent" render examples/accuracy/scaled_1.xml -o "$work/scaled_1.png" -q
echo "scaled_1e-4 against scaled_1 (Lucent): $(oiiotool "$work/scaled_1.png" \
  "$out/scaled_1e-4_lucent.png" --diff 2>&1 | grep -E 'PASS|pixels' | head -1 | sed 's/^ *//')"
