#!/usr/bin/env bash
# Renders the coincident-surface comparisons of docs/csg.md: every examples/csg/*.xml
# through `lucent compare` (Lucent's render and POV-Ray 3.7's render of the exported scene,
# 320 x 240, no anti-aliasing), copied to docs/images/csg/<name>_lucent.png and
# <name>_povray.png, with the metrics printed. Needs a built lucent and povray.
#
#   bash bench/csg_images.sh [path/to/lucent]     # default: build/cli/lucent
set -euo pipefail
cd "$(dirname "$0")/.."
lucent=${1:-build/cli/lucent}
out=docs/images/csg
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for xml in examples/csg/*.xml; do
  name=$(basename "$xml" .xml)
  echo "$name:"
  "$lucent" compare "$xml" -o "$work/$name" | sed 's/^/  /'
  cp "$work/$name/lucent.png" "$out/${name}_lucent.png"
  cp "$work/$name/povray.png" "$out/${name}_povray.png"
done
