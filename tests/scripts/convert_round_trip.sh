#!/usr/bin/env bash
# lucent convert writes every example scene (examples/ and examples/gallery/) as an XML scene
# that renders to the same bytes as the original (40x30, frame 1 of an animation: the
# converted file holds the frame it was converted from), and so does the converted file
# converted again. That second file is not always the same text: a direction is kept
# normalised and a pattern's or sky's transform as its inverse, so the value written is the
# result of a normalisation or an inversion, which done again may move the last bit.
#
# The scenes in NOT_YET hold a construct the writer cannot write yet (none now: every shape
# is written, with its lists, files, function and child elements): each must exit with
# status 2 and an error at the construct's file:line:col, and write no file. A scene that
# converts while listed there fails the test too, so the list only ever shrinks.
# Also: an output in a missing folder or over a folder (status 3), and a failed conversion
# (an invalid scene) leaving an existing output as it was.
# Usage: bash convert_round_trip.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

NOT_YET=""
NOT_YET=" $(echo $NOT_YET) "

# The scenes are converted beside themselves (in a copy), so that the files they name
# (meshes, images, includes) are found from the converted file as from the original.
cp -r "$src/examples" "$tmp/examples"
converted=0
for scene in "$tmp"/examples/*.xml "$tmp"/examples/gallery/*.xml; do
  name=$(basename "$scene" .xml)
  dir=$(dirname "$scene")
  out="$dir/$name.converted.xml"
  "$lucent" convert "$scene" -o "$out" 2>"$tmp/$name.err"
  status=$?
  if [[ "$NOT_YET" == *" $name "* ]]; then
    [ "$status" -eq 2 ] || { fail "$name: exit status $status, expected 2 (listed as not written yet)"; continue; }
    grep -qE "^$scene:[0-9]+:[0-9]+: error: cannot convert: .+ cannot be written yet" "$tmp/$name.err" ||
      fail "$name: unexpected message: $(head -3 "$tmp/$name.err")"
    [ ! -e "$out" ] || fail "$name: a file was written"
    continue
  fi
  [ "$status" -eq 0 ] || { fail "$name: convert exited with $status: $(head -3 "$tmp/$name.err")"; continue; }
  grep -qE "<!-- from $scene:[0-9]+:[0-9]+ -->" "$out" || fail "$name: no comment naming a source line"
  for which in original converted; do
    file=$scene
    [ "$which" = converted ] && file=$out
    "$lucent" render "$file" -D frame=1 -w 40 -h 30 -q -o "$tmp/$name.$which.ppm" \
      2>"$tmp/$name.$which.log" ||
      fail "$name: rendering the $which scene failed: $(head -3 "$tmp/$name.$which.log")"
  done
  cmp -s "$tmp/$name.original.ppm" "$tmp/$name.converted.ppm" ||
    fail "$name: the converted scene renders differently"
  "$lucent" convert "$out" -o "$dir/$name.again.xml" 2>"$tmp/$name.again.err" ||
    fail "$name: converting the converted scene failed: $(head -3 "$tmp/$name.again.err")"
  "$lucent" render "$dir/$name.again.xml" -D frame=1 -w 40 -h 30 -q -o "$tmp/$name.again.ppm" \
    2>"$tmp/$name.again.log" || fail "$name: rendering the twice converted scene failed"
  cmp -s "$tmp/$name.original.ppm" "$tmp/$name.again.ppm" ||
    fail "$name: the twice converted scene renders differently"
  converted=$((converted + 1))
done
[ "$converted" -ge 81 ] || fail "only $converted scenes converted"

# Outputs that cannot be written: status 3, nothing read or written.
"$lucent" convert "$src/examples/gallery/aa-corners.xml" -o "$tmp/no/such/folder/out.xml" \
  2>"$tmp/folder.err"
status=$?
[ "$status" -eq 3 ] || fail "missing folder: exit status $status, expected 3"
grep -q "cannot write '$tmp/no/such/folder/out.xml': folder '$tmp/no/such/folder' does not exist" \
  "$tmp/folder.err" || fail "missing folder: unexpected message: $(cat "$tmp/folder.err")"
mkdir "$tmp/adir"
"$lucent" convert "$src/examples/gallery/aa-corners.xml" -o "$tmp/adir" 2>"$tmp/dir.err"
status=$?
[ "$status" -eq 3 ] || fail "output is a folder: exit status $status, expected 3"
grep -q "'$tmp/adir' is a folder, not an .xml file" "$tmp/dir.err" ||
  fail "output is a folder: unexpected message: $(cat "$tmp/dir.err")"

# An invalid scene: status 2 at its error, and an existing output kept whole.
cat > "$tmp/bad.xml" <<'XML'
<scene version="1">
  <camera position="0 0 5" look-at="0 0 0"/>
  <sphere radius="-1"/>
</scene>
XML
echo "previous content" >"$tmp/kept.xml"
"$lucent" convert "$tmp/bad.xml" -o "$tmp/kept.xml" 2>"$tmp/bad.err"
status=$?
[ "$status" -eq 2 ] || fail "invalid scene: exit status $status, expected 2"
grep -q "^$tmp/bad.xml:3:19: error: <sphere> attribute 'radius': expected a positive number" \
  "$tmp/bad.err" || fail "invalid scene: unexpected message: $(cat "$tmp/bad.err")"
[ "$(cat "$tmp/kept.xml")" = "previous content" ] || fail "invalid scene: the existing output was changed"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "convert_round_trip: $converted scenes converted and rendered byte-identical"
