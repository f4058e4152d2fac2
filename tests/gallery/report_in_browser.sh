#!/usr/bin/env bash
# The compare report in a real browser: `lucent compare` on a gallery scene, then
# headless Chromium takes a screenshot of report.html, which must show the Lucent render,
# the POV-Ray render and the heat map pixel for pixel, and the metrics table below them
# (screenshot_check.py). The same check on a copy of the report whose image links are
# broken must fail, so the check is known to be able to fail.
# Usage: bash report_in_browser.sh <path-to-lucent> <source-dir>
set -u
lucent=$1
src=$2
here=$(cd "$(dirname "$0")" && pwd)
scene="$src/examples/gallery/sphere-box-shadows.xml"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for tool in chromium python3 oiiotool; do
  command -v "$tool" >/dev/null 2>&1 ||
    { echo "FAIL: $tool is not installed (scripts/install-deps installs it)" >&2; exit 1; }
done

# screenshot HTML PNG: Chromium as root (no sandbox) with a fresh profile, 1:1 pixels.
screenshot() {
  rm -rf "$tmp/profile"
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --hide-scrollbars --force-device-scale-factor=1 \
    --user-data-dir="$tmp/profile" --window-size=1400,1000 --screenshot="$2" \
    "file://$1" >"$tmp/chromium.log" 2>&1
  [ -s "$2" ] || { echo "FAIL: chromium wrote no screenshot of $1:" >&2; cat "$tmp/chromium.log" >&2; exit 1; }
}

# check DIR SHOT: the report's images and table are in the screenshot.
check() {
  for f in lucent povray diff; do oiiotool "$1/$f.png" -o "$tmp/$f.ppm" || exit 1; done
  oiiotool "$2" -o "$tmp/shot.ppm" || exit 1
  python3 "$here/screenshot_check.py" "$tmp/shot.ppm" "$tmp/lucent.ppm" "$tmp/povray.ppm" "$tmp/diff.ppm"
}

if ! "$lucent" compare "$scene" -o "$tmp/report" >"$tmp/compare.log" 2>&1; then
  echo "FAIL: lucent compare failed:" >&2; cat "$tmp/compare.log" >&2; exit 1
fi
screenshot "$tmp/report/report.html" "$tmp/shot.png"
if ! check "$tmp/report" "$tmp/shot.png"; then
  mkdir -p "${LUCENT_KEEP_DIR:-/tmp}/lucent-report-in-browser"
  cp -r "$tmp/report" "$tmp/shot.png" "${LUCENT_KEEP_DIR:-/tmp}/lucent-report-in-browser/"
  echo "FAIL: report.html does not show its images and table; screenshot and report kept in ${LUCENT_KEEP_DIR:-/tmp}/lucent-report-in-browser" >&2
  exit 1
fi

# Negative control: the same report with its image files renamed (broken links).
cp -r "$tmp/report" "$tmp/broken"
for f in lucent povray diff; do mv "$tmp/broken/$f.png" "$tmp/broken/$f-moved.png"; done
screenshot "$tmp/broken/report.html" "$tmp/broken-shot.png"
for f in lucent povray diff; do cp "$tmp/broken/$f-moved.png" "$tmp/broken/$f.png"; done
if check "$tmp/broken" "$tmp/broken-shot.png" >"$tmp/broken.log"; then
  echo "FAIL: the check passed on a report with broken image links:" >&2; cat "$tmp/broken.log" >&2
  exit 1
fi
echo "report_in_browser: images and table shown; broken links detected"
