#!/usr/bin/env bash
# POV-Ray's own sample scenes (tests/data/sdl/samples, copied from povray-examples) imported
# by `lucent compare SCENE.pov` and held to POV-Ray's image of the same file at 160x120: each
# must reach the PSNR scenes.txt gives it.
# Usage: bash pov_sample_scenes.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

command -v povray >/dev/null || skip "povray is not installed (scripts/install-deps)"
samples=$src/tests/data/sdl/samples
cp -r "$samples" "$tmp/samples"
cd "$tmp/samples"
checked=0
while read -r scene origin least rest; do
  case "$scene" in "" | \#*) continue ;; esac
  checked=$((checked + 1))
  # A scene with an .ini file beside it is an animation: its middle frame, as POV-Ray's.
  args=()
  ini=${scene%.pov}.ini
  if [ -f "$ini" ]; then
    first=$(sed -n 's/^Initial_Frame=//p' "$ini")
    last=$(sed -n 's/^Final_Frame=//p' "$ini")
    args=(--pov-ini "$ini" --frame $(((${last:-1} - ${first:-1}) / 2 + 1)))
  fi
  out=${scene//\//_}
  if ! "$lucent" compare "$scene" "${args[@]}" -w 160 -h 120 -o "cmp-$out" >"$out.out" 2>"$out.err"; then
    fail "$scene ($origin): compare exited with $?: $(tail -3 "$out.err")"
    continue
  fi
  psnr=$(sed -n 's/^psnr: *\([0-9.]*\) dB.*/\1/p; s/^psnr: *inf.*/inf/p' "$out.out")
  [ -n "$psnr" ] || { fail "$scene: no PSNR in $(cat "$out.out")"; continue; }
  if [ "$psnr" != inf ] && ! awk -v p="$psnr" -v l="$least" 'BEGIN { exit !(p >= l) }'; then
    fail "$scene ($origin): $psnr dB against POV-Ray, below $least dB"
  fi
done <scenes.txt
[ "$checked" -ge 12 ] || fail "only $checked scenes listed in scenes.txt"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "pov_sample_scenes: $checked sample scenes at their PSNR"
