#!/usr/bin/env bash
# `lucent preview` in a real browser (preview_in_browser.py says what is checked): headless
# Chromium driven by chromedriver over WebDriver.
# Usage: bash preview_in_browser.sh <path-to-lucent> <source-dir>
set -u
lucent=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for tool in chromium chromedriver python3 oiiotool; do
  command -v "$tool" >/dev/null 2>&1 ||
    { echo "FAIL: $tool is not installed (scripts/install-deps installs it)" >&2; exit 1; }
done
# Under AddressSanitizer freed memory is held in quarantine by design, so the process's size
# says nothing of leaks (LeakSanitizer checks those at exit), and everything is slower:
# fewer saves, and no bound on the size.
if grep -q __asan_init "$lucent" 2>/dev/null; then
  export LUCENT_PREVIEW_SAVES=100 LUCENT_PREVIEW_NO_RSS_BOUND=1
fi
if ! python3 "$here/preview_in_browser.py" "$lucent" "$tmp"; then
  keep="${LUCENT_KEEP_DIR:-/tmp}/lucent-preview-in-browser"
  rm -rf "$keep" && mkdir -p "$keep" && cp -r "$tmp"/*.png "$tmp"/*.log "$tmp"/*.xml "$keep"/ 2>/dev/null
  echo "FAIL: screenshots and logs kept in $keep" >&2
  exit 1
fi
