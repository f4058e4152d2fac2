#!/usr/bin/env bash
# The cross-check of docs/speed-vs-error.md: Lucent's images at N samples share their first
# N sub-pixel positions (Halton points 1..N) with Lucent's 256-sample reference, so their
# error against it is lower than against an independent reference. This prints, for the
# images kept by a run of bench/speed_vs_error.sh with LUCENT_SPEED_KEEP=DIR, the sRGB RMSE
# of each against both references: Lucent's and POV-Ray's (+AM1 +A0.0 +R9, jittered).
#
#   LUCENT_SPEED_KEEP=/tmp/keep bash bench/speed_vs_error.sh ... SCENE.xml...
#   bash bench/speed_vs_error_xref.sh /tmp/keep > docs/speed-vs-error-data/xref.tsv
set -euo pipefail
keep=${1:?usage: $0 KEEP_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# sRGB floats in [0, 1]: Lucent's TIFFs are sRGB-encoded already, POV-Ray's PNGs linear.
srgb() {  # image out
  if [ "${1##*.}" = tif ]; then
    oiiotool "$1" --ch R,G,B -d float -o "$2"
  else
    oiiotool "$1" --ch R,G,B --clamp:min=0:max=1 --colorconvert linear sRGB -d float -o "$2"
  fi
}
rmse() { { oiiotool "$1" "$2" --diff 2>&1 || true; } | awk '/RMS error/ {print $4}'; }

printf 'scene\trun\trmse_srgb_vs_lucent_ref\trmse_srgb_vs_povray_ref\n'
for lref in "$keep"/*-lucent-ref.tif; do
  scene=$(basename "$lref" -lucent-ref.tif)
  srgb "$lref" "$work/lref.exr"
  srgb "$keep/$scene-povray-ref.png" "$work/pref.exr"
  printf '%s\t%s\t0\t%s\n' "$scene" "lucent reference" "$(rmse "$work/pref.exr" "$work/lref.exr")"
  for img in $(ls "$keep/$scene"-lucent-[0-9]*.tif | sort -V) "$keep/$scene"-povray-[-+]*.png; do
    run=$(basename "$img"); run=${run#"$scene"-}; run=${run%.*}
    srgb "$img" "$work/img.exr"
    printf '%s\t%s\t%s\t%s\n' "$scene" "$run" "$(rmse "$work/lref.exr" "$work/img.exr")" \
      "$(rmse "$work/pref.exr" "$work/img.exr")"
  done
done
