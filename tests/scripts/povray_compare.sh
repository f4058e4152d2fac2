#!/usr/bin/env bash
# lucent compare against POV-Ray 3.7 on two simple scenes (tests/povray/scenes): a sphere on
# a plane under a point light, and a box in front of a mirror. The exported scene rendered
# by POV-Ray must match Lucent's render: PSNR >= 40 dB and SSIM >= 0.99 (from report.json),
# and the report folder must hold both images, the heat map and report.html.
# Usage: bash povray_compare.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

if ! command -v povray >/dev/null 2>&1 && [ -z "${LUCENT_POVRAY:-}" ]; then
  echo "FAIL: povray is not installed (scripts/install-deps installs it)" >&2
  exit 1
fi

# json_number FILE KEY: the number on the line "KEY": value (report.json has one key a
# line); "null" stays "null".
json_number() { sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1"; }

for scene in sphere_plane box_mirror; do
  out="$tmp/$scene"
  if ! "$lucent" compare "$src/tests/povray/scenes/$scene.xml" -o "$out" >"$tmp/stdout" 2>"$tmp/stderr"; then
    fail "$scene: lucent compare exited with $?: $(cat "$tmp/stderr")"
    continue
  fi
  for f in lucent.png povray.png diff.png lucent-linear16.png povray-linear16.png scene.pov report.json report.html; do
    [ -s "$out/$f" ] || fail "$scene: $f missing or empty"
  done
  psnr=$(json_number "$out/report.json" psnr_db)
  ssim=$(json_number "$out/report.json" ssim)
  [ -n "$psnr" ] && [ -n "$ssim" ] || { fail "$scene: no psnr_db/ssim in report.json"; continue; }
  # A null PSNR means identical images (infinite PSNR).
  if [ "$psnr" != "null" ] && ! awk -v p="$psnr" 'BEGIN { exit !(p >= 40) }'; then
    fail "$scene: PSNR $psnr dB < 40 dB"
  fi
  awk -v s="$ssim" 'BEGIN { exit !(s >= 0.99) }' || fail "$scene: SSIM $ssim < 0.99"
  grep -q '^psnr:' "$tmp/stdout" || fail "$scene: no metrics printed"
  echo "$scene: PSNR $psnr dB, SSIM $ssim"
done

# --pov FILE: a hand-written POV-Ray scene (here the export from above, moved aside) is
# rendered instead of a fresh export, with the same metrics.
if [ -s "$tmp/sphere_plane/scene.pov" ]; then
  cp "$tmp/sphere_plane/scene.pov" "$tmp/hand.pov"
  if "$lucent" compare "$src/tests/povray/scenes/sphere_plane.xml" --pov "$tmp/hand.pov" \
       -o "$tmp/hand" >"$tmp/stdout" 2>"$tmp/stderr"; then
    grep -q '"pov_scene_hand_written": true' "$tmp/hand/report.json" ||
      fail "--pov: report.json does not say the scene was hand-written"
    [ ! -e "$tmp/hand/scene.pov" ] || fail "--pov: an export was written anyway"
    ssim=$(json_number "$tmp/hand/report.json" ssim)
    awk -v s="$ssim" 'BEGIN { exit !(s >= 0.99) }' || fail "--pov: SSIM $ssim < 0.99"
  else
    fail "--pov: lucent compare exited with $?: $(cat "$tmp/stderr")"
  fi
  # Without #version 3.7 POV-Ray applies 3.62 rules: the user is told.
  grep -v '^#version' "$tmp/hand.pov" > "$tmp/old.pov"
  "$lucent" compare "$src/tests/povray/scenes/sphere_plane.xml" --pov "$tmp/old.pov" \
    -o "$tmp/old" >/dev/null 2>"$tmp/stderr"
  grep -q "old.pov: no #version directive" "$tmp/stderr" ||
    fail "--pov without #version: no warning: $(cat "$tmp/stderr")"
fi

# No povray: exit status 3 and how to install it.
LUCENT_POVRAY=/nonexistent/povray "$lucent" compare "$src/tests/povray/scenes/sphere_plane.xml" \
  -o "$tmp/none" >/dev/null 2>"$tmp/stderr"
status=$?
[ "$status" -eq 3 ] || fail "without povray: exit status $status, expected 3"
grep -q "apt-get install povray" "$tmp/stderr" || fail "without povray: no install hint: $(cat "$tmp/stderr")"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "povray_compare: all checks passed"
