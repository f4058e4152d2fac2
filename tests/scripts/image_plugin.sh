#!/usr/bin/env bash
# OpenImageIO lives in a plugin (lucent-oiio.so, images/image_plugin.h) loaded only when an
# image other than PNG or JPEG is read, or one other than PNG and PPM written (those have
# built-in readers and writers). With LUCENT_IMAGE_PLUGIN naming a file that is missing or not the plugin:
# commands that need no OpenImageIO still work, and those that do fail with a clear
# message, status 3, and the old output image untouched.
# Usage: bash image_plugin.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="8" height="8"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <sphere radius="1"/>
</scene>
XML

# Commands without images: the plugin is never looked for.
export LUCENT_IMAGE_PLUGIN="$tmp/missing.so"
"$lucent" --version >/dev/null 2>"$tmp/stderr" || fail "--version needs the image library: $(cat "$tmp/stderr")"
"$lucent" check "$tmp/scene.xml" >/dev/null 2>"$tmp/stderr" || fail "check needs the image library: $(cat "$tmp/stderr")"
"$lucent" export-pov "$tmp/scene.xml" -o "$tmp/scene.pov" >/dev/null 2>"$tmp/stderr" ||
  fail "export-pov needs the image library: $(cat "$tmp/stderr")"
grep -q "sphere" "$tmp/scene.pov" 2>/dev/null || fail "export-pov wrote no sphere"
# PNG and PPM are written by the built-in part.
"$lucent" render "$tmp/scene.xml" -o "$tmp/plain.png" -q 2>"$tmp/stderr" ||
  fail "render to PNG needs the image library: $(cat "$tmp/stderr")"
[ "$(head -c 4 "$tmp/plain.png" | tail -c 3)" = "PNG" ] || fail "render without the plugin wrote no PNG"
"$lucent" render "$tmp/scene.xml" -o "$tmp/plain.ppm" -q 2>"$tmp/stderr" ||
  fail "render to PPM needs the image library: $(cat "$tmp/stderr")"
[ "$(head -c 2 "$tmp/plain.ppm")" = "P6" ] || fail "render without the plugin wrote no PPM"

# render to EXR: OpenImageIO must write it, so it fails, and says what was tried.
check_render_fails() {  # <label> <expected text in stderr>
  echo "old image" > "$tmp/out.exr"
  "$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q >/dev/null 2>"$tmp/stderr"
  local status=$?
  [ "$status" -eq 3 ] || fail "$1: exit status $status, expected 3"
  grep -qF "lucent: error: cannot load the image library (lucent-oiio.so, OpenImageIO)" "$tmp/stderr" ||
    fail "$1: message: $(cat "$tmp/stderr")"
  grep -qF -- "$2" "$tmp/stderr" || fail "$1: stderr lacks '$2': $(cat "$tmp/stderr")"
  [ "$(cat "$tmp/out.exr")" = "old image" ] || fail "$1: the old image was changed"
  [ -z "$(ls -A "$tmp" | grep lucent-)" ] || fail "$1: a temporary file was left: $(ls -A "$tmp")"
}
check_render_fails "missing plugin" "$tmp/missing.so: no such file"

echo "not a library" > "$tmp/text.so"
export LUCENT_IMAGE_PLUGIN="$tmp/text.so"
check_render_fails "not a shared library" "$tmp/text.so: "

# A real shared library that is not the plugin (the C library itself).
libc=$(ldd "$lucent" | sed -n 's/.*libc\.so\.6 => \([^ ]*\).*/\1/p')
export LUCENT_IMAGE_PLUGIN="$libc"
check_render_fails "another library" "$libc: not a Lucent image plugin of version"

# PNG and JPEG textures are read by the built-in part too.
"$lucent" render "$src/examples/gallery/image-texture.xml" -o "$tmp/out.png" -q 2>"$tmp/stderr" ||
  fail "a PNG texture needs the image library: $(cat "$tmp/stderr")"
sed 's|textures/uvgrid.png|'"$src"'/tests/data/jpeg_kinds/rgb420.jpg|' \
  "$src/examples/gallery/image-texture.xml" >"$tmp/jpeg-texture.xml"
"$lucent" render "$tmp/jpeg-texture.xml" -o "$tmp/out.png" -q --allow-path "$src" 2>"$tmp/stderr" ||
  fail "a JPEG texture needs the image library: $(cat "$tmp/stderr")"

# A TIFF texture needs the library while the scene is set up: the same message.
unset LUCENT_IMAGE_PLUGIN
"$lucent" render "$tmp/scene.xml" -o "$tmp/grid.tif" -q 2>"$tmp/stderr" || fail "render to TIFF: $(cat "$tmp/stderr")"
sed 's|textures/uvgrid.png|'"$tmp"'/grid.tif|' "$src/examples/gallery/image-texture.xml" >"$tmp/tiff-texture.xml"
export LUCENT_IMAGE_PLUGIN="$libc"
"$lucent" render "$tmp/tiff-texture.xml" -o "$tmp/out.png" -q >/dev/null 2>"$tmp/stderr"
status=$?
[ "$status" -eq 3 ] || fail "TIFF texture: exit status $status, expected 3"
grep -qF "cannot load the image library" "$tmp/stderr" || fail "TIFF texture: message: $(cat "$tmp/stderr")"

unset LUCENT_IMAGE_PLUGIN
# With the real plugin (found beside lucent or where the build wrote it) all works.
"$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q 2>"$tmp/stderr" || fail "render with the plugin: $(cat "$tmp/stderr")"
[ "$(head -c 4 "$tmp/out.exr" | od -An -tx1 | tr -d ' ')" = "762f3101" ] || fail "render with the plugin wrote no EXR"

[ "$failures" -eq 0 ] && echo "image_plugin: all checks passed"
exit $((failures > 0))
