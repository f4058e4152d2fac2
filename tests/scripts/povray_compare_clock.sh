#!/usr/bin/env bash
# lucent compare --frame N against a hand-written POV-Ray scene that reads `clock`: POV-Ray
# renders it at the clock of frame N (+K), so a sphere that moves with the clock is where
# Lucent's frame puts it. Frame 4 of 5 (clock 0.75) must reach PSNR >= 40 dB and name +K0.75
# in the report's POV-Ray command; frame 1 (clock 0, POV-Ray's default) passes no +K.
# Usage: bash povray_compare_clock.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

if ! command -v povray >/dev/null 2>&1 && [ -z "${LUCENT_POVRAY:-}" ]; then
  echo "FAIL: povray is not installed (scripts/install-deps installs it)" >&2
  exit 1
fi

json_number() { sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1"; }
scenes="$src/tests/povray/scenes"

for frame in 4 1; do
  out="$tmp/frame$frame"
  if ! "$lucent" compare "$scenes/moving_sphere.xml" --pov "$scenes/moving_sphere.pov" \
    --frame "$frame" -o "$out" >"$tmp/stdout" 2>"$tmp/stderr"; then
    fail "frame $frame: lucent compare exited with $?: $(cat "$tmp/stderr")"
    continue
  fi
  psnr=$(json_number "$out/report.json" psnr_db)
  if [ "$psnr" != "null" ] && ! awk -v p="$psnr" 'BEGIN { exit !(p >= 40) }'; then
    fail "frame $frame: PSNR $psnr dB < 40 dB (POV-Ray at another clock?)"
  fi
  command=$(grep '"povray_command"' "$out/report.json")
  if [ "$frame" = 4 ]; then
    grep -q -- '+K0.75' <<<"$command" || fail "frame 4: no +K0.75 in $command"
  else
    grep -q -- '+K' <<<"$command" && fail "frame 1: a clock was passed: $command"
  fi
  echo "frame $frame: PSNR $psnr dB"
done
[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "povray_compare_clock: all checks passed"
