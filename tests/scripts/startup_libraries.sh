#!/usr/bin/env bash
# Start-up without OpenImageIO (images/image_plugin.h): `--version`, `check` and a render to
# PNG or PPM, with PNG or JPEG textures, load no part of it, while a render to EXR or of a
# scene with a TIFF texture does. And no command but `preview` loads its web server
# (cpp-httplib and the OpenSSL it is built with, cli/preview/http_server.h). Proved from the dynamic linker's own record of every object it loads
# (LD_DEBUG=files), which needs no code in lucent.
# Usage: bash startup_libraries.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="64" height="48"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <sphere radius="1"/>
</scene>
XML

# loaded LABEL -- COMMAND...: runs the command with the linker's trace; prints the objects
# it loaded (one per line) into $tmp/loaded, fails the test if the command fails.
loaded() {
  local label=$1
  shift 2
  rm -f "$tmp"/ld.*
  LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$@" >/dev/null 2>"$tmp/stderr" ||
    fail "$label: exit status $?: $(cat "$tmp/stderr")"
  cat "$tmp"/ld.* 2>/dev/null | sed -n 's/.*file=\([^ ]*\).*/\1/p' | sort -u > "$tmp/loaded"
  # The trace itself works: the C library is always in it.
  grep -q "libc\.so" "$tmp/loaded" || fail "$label: no linker trace (LD_DEBUG ignored?)"
}

without_oiio() {  # LABEL -- COMMAND...
  loaded "$@"
  if grep -E "httplib|lucent-preview-server|libssl" "$tmp/loaded" >"$tmp/found"; then
    fail "$1 loads the preview's web server: $(tr '\n' ' ' < "$tmp/found")"
  fi
  if grep -E "OpenImageIO|lucent-oiio" "$tmp/loaded" >"$tmp/found"; then
    fail "$1 loads OpenImageIO: $(tr '\n' ' ' < "$tmp/found")"
  fi
}

with_oiio() {  # LABEL -- COMMAND...
  loaded "$@"
  grep -q "lucent-oiio\.so" "$tmp/loaded" || fail "$1 does not load the plugin"
  grep -q "libOpenImageIO" "$tmp/loaded" || fail "$1 does not load OpenImageIO"
}

without_oiio "--version" -- "$lucent" --version
without_oiio "check" -- "$lucent" check "$tmp/scene.xml"
without_oiio "render to PNG" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q
[ "$(head -c 4 "$tmp/out.png" | tail -c 3)" = "PNG" ] || fail "render wrote no PNG"
without_oiio "render to PPM" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.ppm" -q
[ "$(head -c 2 "$tmp/out.ppm")" = "P6" ] || fail "render wrote no PPM"

# What needs OpenImageIO still gets it.
with_oiio "render to EXR" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.exr" -q
[ -s "$tmp/out.exr" ] || fail "render wrote no EXR"

# PNG and JPEG textures, and a POV-Ray scene's PNG image_map, are read by the built-in part.
without_oiio "a scene with a PNG texture" -- \
  "$lucent" render "$src/examples/gallery/image-texture.xml" -o "$tmp/texture.png" -q -w 32 -h 24
[ "$(head -c 4 "$tmp/texture.png" | tail -c 3)" = "PNG" ] || fail "the texture scene wrote no PNG"
sed 's|textures/uvgrid.png|'"$src"'/tests/data/jpeg_kinds/rgb420.jpg|' \
  "$src/examples/gallery/image-texture.xml" >"$tmp/jpeg-texture.xml"
without_oiio "a scene with a JPEG texture" -- \
  "$lucent" render "$tmp/jpeg-texture.xml" -o "$tmp/texture.png" -q -w 32 -h 24 --allow-path "$src"
cp "$src/tests/data/png_kinds/rgba8.png" "$tmp/map.png"
cat > "$tmp/map.pov" <<'POV'
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3>, rgb 1 }
plane { z, 1 pigment { image_map { png "map.png" } } finish { ambient 1 diffuse 0 } }
POV
without_oiio "a POV-Ray scene with a PNG image_map" -- "$lucent" render "$tmp/map.pov" -o "$tmp/map-render.png" -q -w 32 -h 24

# An image texture in another format gets it.
"$lucent" render "$tmp/scene.xml" -o "$tmp/grid.tif" -q || fail "render to TIFF failed"
sed 's|textures/uvgrid.png|'"$tmp"'/grid.tif|' "$src/examples/gallery/image-texture.xml" >"$tmp/tiff-texture.xml"
with_oiio "a scene with a TIFF texture" -- \
  "$lucent" render "$tmp/tiff-texture.xml" -o "$tmp/texture.png" -q -w 32 -h 24
[ "$(head -c 4 "$tmp/texture.png" | tail -c 3)" = "PNG" ] || fail "the TIFF texture scene wrote no PNG"

# `preview` loads the server plugin, and with it cpp-httplib; stopped by Ctrl-C once it has
# printed its address.
rm -f "$tmp"/ld.*
LD_DEBUG=files LD_DEBUG_OUTPUT="$tmp/ld" "$lucent" preview "$tmp/scene.xml" >"$tmp/preview.out" 2>&1 &
preview=$!
for _ in $(seq 100); do grep -q "http://" "$tmp/preview.out" && break; sleep 0.1; done
kill -INT "$preview"
wait "$preview" || fail "preview: exit status $? after Ctrl-C: $(cat "$tmp/preview.out")"
cat "$tmp"/ld.* 2>/dev/null | sed -n 's/.*file=\([^ ]*\).*/\1/p' | sort -u > "$tmp/loaded"
grep -q "lucent-preview-server\.so" "$tmp/loaded" || fail "preview does not load its server plugin"
grep -q "libcpp-httplib" "$tmp/loaded" || fail "preview does not load cpp-httplib"

[ "$failures" -eq 0 ] && echo "startup_libraries: all checks passed"
exit $((failures > 0))
