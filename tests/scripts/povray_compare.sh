#!/usr/bin/env bash
# lucent compare against POV-Ray 3.7 on two simple scenes (tests/povray/scenes): a sphere on
# a plane under a point light, and a box in front of a mirror. The exported scene rendered
# by POV-Ray must match Lucent's render: PSNR >= 40 dB and SSIM >= 0.99 (from report.json),
# and the report folder must hold both images, the heat map and report.html.
# Usage: bash povray_compare.sh <path-to-lucent> <source-dir>
set -u
lucent=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

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

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "povray_compare: all checks passed"
