#!/usr/bin/env bash
# Every example scene exports to POV-Ray and POV-Ray 3.7 parses and renders the result
# without an error (a tiny 8x6 render: exit status 0). Also: what cannot be exported exits
# with status 2 and an error at the element's file:line:col, and writes no file.
# Usage: bash povray_export_examples.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

povray=${LUCENT_POVRAY:-$(command -v povray)}
[ -n "$povray" ] || { echo "FAIL: povray is not installed (scripts/install-deps installs it)" >&2; exit 1; }

count=0
for scene in "$src"/examples/*.xml; do
  name=$(basename "$scene" .xml)
  if ! "$lucent" export-pov "$scene" -o "$tmp/$name.pov" 2>"$tmp/$name.export.log"; then
    fail "$name: export-pov failed: $(cat "$tmp/$name.export.log")"
    continue
  fi
  head -n 5 "$tmp/$name.pov" | grep -q '^#version 3.7;$' || fail "$name: no #version 3.7 header"
  grep -q 'assumed_gamma 1.0' "$tmp/$name.pov" || fail "$name: no assumed_gamma 1.0"
  if ! "$povray" "+I$tmp/$name.pov" "+O$tmp/$name.png" +W8 +H6 -D -V -GS -GR -A \
       >"$tmp/$name.pov.log" 2>&1; then
    fail "$name: povray exited with $?: $(grep -iE 'error' "$tmp/$name.pov.log" | head -5)"
    continue
  fi
  # POV-Ray reports parse problems it recovers from as "Parse Warning"s.
  if grep -q 'Parse Warning\|Possible Parse Error' "$tmp/$name.pov.log"; then
    fail "$name: povray warned: $(grep -A2 'Parse Warning\|Possible Parse Error' "$tmp/$name.pov.log" | head -6)"
  fi
  [ -s "$tmp/$name.png" ] || fail "$name: povray wrote no image"
  count=$((count + 1))
done
[ "$count" -gt 0 ] || fail "no example was exported"

# A camera POV-Ray has no equivalent for: exit 2, the element's location, no file.
cat > "$tmp/lens.xml" <<'XML'
<scene version="1">
  <camera type="thin-lens" position="0 1 4" look-at="0 1 0"/>
  <sphere/>
</scene>
XML
"$lucent" export-pov "$tmp/lens.xml" -o "$tmp/lens.pov" 2>"$tmp/lens.err"
status=$?
[ "$status" -eq 2 ] || fail "thin-lens export: exit status $status, expected 2"
grep -q "lens.xml:2:3: error: <camera type=\"thin-lens\">: POV-Ray has no equivalent camera" "$tmp/lens.err" ||
  fail "thin-lens export: unexpected message: $(cat "$tmp/lens.err")"
[ ! -e "$tmp/lens.pov" ] || fail "thin-lens export wrote a file"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "povray_export_examples: $count examples exported and rendered by POV-Ray"
