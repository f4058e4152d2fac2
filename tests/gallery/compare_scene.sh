#!/usr/bin/env bash
# One gallery scene held to POV-Ray 3.7: `lucent compare` against the exported scene and,
# when a hand-written twin NAME.pov sits beside NAME.xml, against the twin too (so that an
# exporter bug cannot hide a renderer bug). Each comparison must reach PSNR >= 40 dB and
# SSIM >= 0.99 (issue 5), read from report.json. The reports stay in OUTDIR to look at.
# Usage: bash compare_scene.sh <path-to-lucent> <scene.xml> <outdir>
set -u
lucent=$1
scene=$2
outdir=$3
name=$(basename "$scene" .xml)
twin="${scene%.xml}.pov"
min_psnr=40
min_ssim=0.99
failures=0
fail() { echo "FAIL: $name: $*" >&2; failures=$((failures + 1)); }

if ! command -v povray >/dev/null 2>&1 && [ -z "${LUCENT_POVRAY:-}" ]; then
  echo "FAIL: povray is not installed (scripts/install-deps installs it)" >&2
  exit 1
fi

# json_number FILE KEY: the value on the line "KEY": value (report.json has one key a line).
json_number() { sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1"; }

# compare LABEL [--pov FILE]: one comparison into $outdir/LABEL, checked against the bounds.
compare() {
  local label=$1
  shift
  local out="$outdir/$label"
  rm -rf "$out"
  mkdir -p "$out"
  "$lucent" compare "$scene" -o "$out" "$@" >"$out/stdout.txt" 2>"$out/stderr.txt"
  local status=$?
  if [ $status -ne 0 ]; then
    fail "$label: lucent compare exited with status $status:"
    cat "$out/stderr.txt" >&2
    return
  fi
  local psnr ssim
  psnr=$(json_number "$out/report.json" psnr_db)
  ssim=$(json_number "$out/report.json" ssim)
  if [ -z "$psnr" ] || [ -z "$ssim" ]; then
    fail "$label: no psnr_db/ssim in $out/report.json"
    return
  fi
  local ok=1
  # A null PSNR means identical images (infinite PSNR).
  if [ "$psnr" != "null" ] && ! awk -v p="$psnr" -v m="$min_psnr" 'BEGIN { exit !(p >= m) }'; then
    fail "$label: PSNR $psnr dB < $min_psnr dB"
    ok=0
  fi
  if ! awk -v s="$ssim" -v m="$min_ssim" 'BEGIN { exit !(s >= m) }'; then
    fail "$label: SSIM $ssim < $min_ssim"
    ok=0
  fi
  echo "$name ($label): PSNR $psnr dB, SSIM $ssim"
  if [ $ok -eq 0 ]; then
    {
      cat "$out/stdout.txt"
      echo "images: $out/lucent.png $out/povray.png, difference $out/diff.png"
      echo "report: $out/report.html"
      [ -s "$out/stderr.txt" ] && { echo "messages:"; cat "$out/stderr.txt"; }
    } >&2
  fi
}

compare export
[ -f "$twin" ] && compare twin --pov "$twin"

[ "$failures" -eq 0 ] || exit 1
