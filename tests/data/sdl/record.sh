#!/usr/bin/env bash
# Records POV-Ray's #debug output of each script here as NAME.out, the reference the tests
# (tests/sdl/differential_test.cpp) compare Lucent's output with. Run it again after
# changing a script: bash tests/data/sdl/record.sh
# (POV-Ray cuts long #debug lines: the tests cut Lucent's output the same way.)
set -eu
cd "$(dirname "${BASH_SOURCE[0]}")"
for pov in *.pov; do
  name=${pov%.pov}
  rm -f "$name.out"
  povray "+I$pov" -D -F +W1 +H1 -GA "+GD$name.out" >/dev/null 2>&1 || {
    echo "povray failed on $pov" >&2
    exit 1
  }
  touch "$name.out"
done
