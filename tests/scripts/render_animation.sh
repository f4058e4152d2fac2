#!/usr/bin/env bash
# Animated scenes on the command line: render writes every frame to numbered files (0001
# before the extension, or a run of #, padded to the digits the last frame needs),
# --frames picks some and refuses what the scene lacks, -D clock/frame renders one moment
# to -o itself, each frame really shows its clock, the files the frames read are read once,
# check names the first invalid frame, export-pov --frame exports that frame.
# Usage: bash render_animation.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

# A sphere that crosses the image as clock goes from 0 to 1, over 3 frames.
cat > "$tmp/moving.xml" <<'XML'
<scene version="1">
  <animation frames="3"/>
  <render width="32" height="24"/>
  <camera position="0 0 6" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <sphere radius="0.7" transform="translate(${3*clock - 1.5} 0 0)"/>
</scene>
XML
sed 's/frames="3"/frames="12"/' "$tmp/moving.xml" >"$tmp/twelve.xml"
sed '/<animation/d' "$tmp/moving.xml" >"$tmp/still.xml"

# expect STATUS DESCRIPTION -- COMMAND...: runs the command, checks its exit status.
expect() {
  local want=$1 what=$2
  shift 3
  "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    fail "$what: exit status $got, expected $want; stderr: $(cat "$tmp/stderr")"
  fi
}
# files FOLDER: the names in it, one line.
files() { (cd "$1" && ls | tr '\n' ' '); }
# usage_error MESSAGE -- COMMAND...: exit status 1 with exactly "lucent: error: MESSAGE".
usage_error() {
  local message=$1
  shift 2
  expect 1 "$message" -- "$@"
  [ "$(cat "$tmp/stderr")" = "lucent: error: $message" ] ||
    fail "expected 'lucent: error: $message', got: $(cat "$tmp/stderr")"
}

# Naming: 4 digits before the extension by default.
mkdir "$tmp/a"
expect 0 "render every frame" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/a/out.png"
[ "$(files "$tmp/a")" = "out0001.png out0002.png out0003.png " ] || fail "default names: $(files "$tmp/a")"
grep -q "^lucent: wrote '$tmp/a/out0002.png' (frame 2/3, 32x24, " "$tmp/stderr" ||
  fail "no 'wrote' line naming the frame: $(cat "$tmp/stderr")"
# A run of # is the number, as wide as the run...
mkdir "$tmp/b"
expect 0 "render to f_###" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/b/f_###.png" -q
[ "$(files "$tmp/b")" = "f_001.png f_002.png f_003.png " ] || fail "### names: $(files "$tmp/b")"
# ... or as wide as the last frame needs.
mkdir "$tmp/c"
expect 0 "render 12 frames to f_#" -- "$lucent" render "$tmp/twelve.xml" -o "$tmp/c/f_#.png" -q --frames 8..10
[ "$(files "$tmp/c")" = "f_08.png f_09.png f_10.png " ] || fail "# widened: $(files "$tmp/c")"
[ -s "$tmp/stderr" ] && fail "-q printed: $(cat "$tmp/stderr")"

# --frames: one frame, a range; the same pixels as the full run.
mkdir "$tmp/d"
expect 0 "--frames 2" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/d/out.png" -q --frames 2
[ "$(files "$tmp/d")" = "out0002.png " ] || fail "--frames 2 wrote: $(files "$tmp/d")"
cmp -s "$tmp/d/out0002.png" "$tmp/a/out0002.png" || fail "--frames 2 differs from frame 2 of the full run"
expect 0 "--frames 1..2" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/d/out.png" -q --frames 1..2
[ "$(files "$tmp/d")" = "out0001.png out0002.png " ] || fail "--frames 1..2 wrote: $(files "$tmp/d")"

# Each frame shows its own clock: the frames differ, and frame f equals the one image that
# -D clock=clock(f) or -D frame=f renders to -o itself.
cmp -s "$tmp/a/out0001.png" "$tmp/a/out0002.png" && fail "frames 1 and 2 are the same image"
cmp -s "$tmp/a/out0002.png" "$tmp/a/out0003.png" && fail "frames 2 and 3 are the same image"
mkdir "$tmp/e"
expect 0 "-D clock=0.5" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/e/moment.png" -q -D clock=0.5
[ "$(files "$tmp/e")" = "moment.png " ] || fail "-D clock wrote: $(files "$tmp/e")"
cmp -s "$tmp/e/moment.png" "$tmp/a/out0002.png" || fail "-D clock=0.5 differs from frame 2 (clock 0.5)"
expect 0 "-D frame=3" -- "$lucent" render "$tmp/moving.xml" -o "$tmp/e/moment.png" -q -D frame=3
cmp -s "$tmp/e/moment.png" "$tmp/a/out0003.png" || fail "-D frame=3 differs from frame 3"
expect 0 "-D clock=1 on still" -- "$lucent" render "$tmp/still.xml" -o "$tmp/e/still.png" -q -D clock=1
cmp -s "$tmp/e/still.png" "$tmp/a/out0003.png" || fail "the still scene at clock 1 differs from frame 3"

# A scene without <animation>: one image to -o, even with --frames 1.
mkdir "$tmp/f"
expect 0 "still --frames 1" -- "$lucent" render "$tmp/still.xml" -o "$tmp/f/still.png" -q --frames 1
[ "$(files "$tmp/f")" = "still.png " ] || fail "still scene wrote: $(files "$tmp/f")"

# Ranges the scene lacks, or that are not ranges: usage errors, nothing written.
usage_error "--frames 2: the scene has no <animation>, so only frame 1" -- \
  "$lucent" render "$tmp/still.xml" -o "$tmp/f/x.png" --frames 2
usage_error "--frames 2..4: the animation has 3 frames (1..3)" -- \
  "$lucent" render "$tmp/moving.xml" -o "$tmp/f/x.png" --frames 2..4
usage_error "--frames 3..2: the first frame 3 comes after the last 2" -- \
  "$lucent" render "$tmp/moving.xml" -o "$tmp/f/x.png" --frames 3..2
usage_error "--frames 0: frames are numbered from 1" -- \
  "$lucent" render "$tmp/moving.xml" -o "$tmp/f/x.png" --frames 0
usage_error "--frames one..two: expected a frame F or a range A..B of whole numbers (as --frames 5 or --frames 1..24)" -- \
  "$lucent" render "$tmp/moving.xml" -o "$tmp/f/x.png" --frames one..two
usage_error "--frames 2 and -D clock both choose what to render; give one" -- \
  "$lucent" render "$tmp/moving.xml" -o "$tmp/f/x.png" --frames 2 -D clock=0.5
[ "$(files "$tmp/f")" = "still.png " ] || fail "a refused render wrote: $(files "$tmp/f")"

# The files the frames read are read once for the run (--stats counts them), and each
# frame's time is listed with a total.
mkdir "$tmp/g"
cp "$src/tests/data/meshes/cube.obj" "$src/examples/textures/uvgrid.png" "$tmp/g/"
cat > "$tmp/g/files.xml" <<'XML'
<scene version="1">
  <animation frames="3"/>
  <render width="32" height="24"/>
  <camera position="0 1 6" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <sphere radius="0.5" transform="translate(${2*clock - 1} 0 0)">
    <material><image src="uvgrid.png"/></material>
  </sphere>
  <mesh src="cube.obj" transform="translate(0 -1.5 0)"/>
</scene>
XML
expect 0 "render reading files" -- "$lucent" render "$tmp/g/files.xml" -o "$tmp/g/out.png" -q --stats
grep -q "^files: .* 1  mesh files read, 1 image textures loaded, for 3 frames$" "$tmp/stdout" ||
  fail "--stats: the files were not read once: $(cat "$tmp/stdout")"
for f in 1 2 3; do
  grep -q "^frame  *$f: .* s (load .* s, render .* s, write and the rest .* s)$" "$tmp/stdout" ||
    fail "--stats: no time for frame $f: $(cat "$tmp/stdout")"
done
grep -q "^frames:  *3  in .* s a frame" "$tmp/stdout" || fail "--stats: no total: $(cat "$tmp/stdout")"

# On a terminal the progress line names the frame and gives the whole run's ETA (drawn when
# each frame starts, then every 250 ms). -q hides it.
mkdir "$tmp/tty"
tty_render=("$lucent" render "$tmp/moving.xml" -w 320 -h 240 -s 64 -o "$tmp/tty/out.png")
script -qec "$(printf '%q ' "${tty_render[@]}")" "$tmp/tty.log" >/dev/null 2>&1 ||
  fail "render on a terminal exited with $?"
grep -aq 'frame [123]/3 \[[#.]\{30\}\] \+[0-9]\+%  [0-9.]\+ Mrays/s  ETA [0-9?:]\+, all [0-9?:]\+' "$tmp/tty.log" ||
  fail "no frame progress on the terminal: $(tr '\r' '\n' <"$tmp/tty.log" | head -5)"
script -qec "$(printf '%q ' "${tty_render[@]}" -q)" "$tmp/tty-quiet.log" >/dev/null 2>&1 ||
  fail "render -q on a terminal exited with $?"
! grep -aq 'frame [123]/3' "$tmp/tty-quiet.log" || fail "-q still shows the frame progress"

# check: every frame; the summary says how many; the first invalid frame is named.
expect 0 "check an animation" -- "$lucent" check "$tmp/moving.xml"
grep -q "^animation: 3 frames, clock 0 to 1; every frame checked$" "$tmp/stdout" ||
  fail "check summary: $(cat "$tmp/stdout")"
# The radius is 0.6 - clock: below 0 from frame 4 (clock 0.75) of 5 on.
sed 's/radius="0.7"/radius="${0.6 - clock}"/; s/frames="3"/frames="5"/' "$tmp/moving.xml" >"$tmp/shrinking.xml"
expect 2 "check an animation invalid from frame 4" -- "$lucent" check "$tmp/shrinking.xml"
grep -q "^lucent: frame 4 of 5 (clock 0.75) is invalid$" "$tmp/stderr" || fail "check: $(cat "$tmp/stderr")"
[ "$(grep -c "error: <sphere> attribute 'radius'" "$tmp/stderr")" -eq 1 ] ||
  fail "check: not exactly one radius error (frame 4 only): $(cat "$tmp/stderr")"
[ -s "$tmp/stdout" ] && fail "check printed a summary for an invalid animation"
# render stops at that frame, the frames before it written.
mkdir "$tmp/h"
expect 2 "render an animation invalid from frame 4" -- "$lucent" render "$tmp/shrinking.xml" -o "$tmp/h/out.png" -q
# The checkpoint records the frames written, for --resume (render_checkpoint.sh).
[ "$(files "$tmp/h")" = "out.png.checkpoint out0001.png out0002.png out0003.png " ] || fail "render invalid: $(files "$tmp/h")"
grep -q "^lucent: stopped at frame 4; 3 of 5 frames written$" "$tmp/stderr" || fail "render invalid: $(cat "$tmp/stderr")"

# export-pov --frame: that frame (default 1), and out of range is a usage error.
expect 0 "export frame 3" -- "$lucent" export-pov "$tmp/moving.xml" -o "$tmp/f3.pov" --frame 3
expect 0 "export -D frame=3" -- "$lucent" export-pov "$tmp/moving.xml" -o "$tmp/d3.pov" -D frame=3
expect 0 "export frame 1" -- "$lucent" export-pov "$tmp/moving.xml" -o "$tmp/f1.pov"
grep -q "matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  1.5, 0, 0>" "$tmp/f3.pov" || fail "export --frame 3: sphere not at x = 1.5"
grep -q "matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  -1.5, 0, 0>" "$tmp/f1.pov" || fail "export: frame 1 not at x = -1.5"
cmp -s "$tmp/f3.pov" "$tmp/d3.pov" || fail "export --frame 3 differs from -D frame=3"
usage_error "--frame 4: the animation has 3 frames (1..3)" -- \
  "$lucent" export-pov "$tmp/moving.xml" -o "$tmp/x.pov" --frame 4
usage_error "--frame 2: the scene has no <animation>, so only frame 1" -- \
  "$lucent" export-pov "$tmp/still.xml" -o "$tmp/x.pov" --frame 2
usage_error "--frame 0: frames are numbered from 1" -- \
  "$lucent" export-pov "$tmp/moving.xml" -o "$tmp/x.pov" --frame 0
[ -e "$tmp/x.pov" ] && fail "a refused export wrote a file"

# compare --frame: the same, where POV-Ray is installed.
if command -v povray >/dev/null 2>&1 || [ -n "${LUCENT_POVRAY:-}" ]; then
  expect 0 "compare frame 3" -- "$lucent" compare "$tmp/moving.xml" -o "$tmp/cmp3" --frame 3
  grep -q "matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  1.5, 0, 0>" "$tmp/cmp3/scene.pov" ||
    fail "compare --frame 3: the exported sphere is not at x = 1.5"
  usage_error "--frame 4: the animation has 3 frames (1..3)" -- \
    "$lucent" compare "$tmp/moving.xml" -o "$tmp/cmp4" --frame 4
  [ -e "$tmp/cmp4" ] && fail "a refused compare made its folder"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "render animation: names, --frames, one moment, clock per frame, files read once, check, export-pov --frame"
