#!/usr/bin/env bash
# Ctrl-C (SIGINT) and SIGTERM while an animation renders: the frames finished before stay
# complete images, the frame being rendered is not written (its file, here an old one, is
# left as it was), the frames after it are not started, nothing temporary is left, and the
# exit status is 3. The signal is sent once the first frame's file is a new image: no
# timing is assumed beyond a frame taking longer than the poll (0.1 s) that notices it.
# Usage: bash render_animation_interrupt.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

frames=40
cat > "$tmp/scene.xml" <<XML
<scene version="1">
  <animation frames="$frames"/>
  <render width="320" height="240" samples="64"/>
  <camera position="0 1 5" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <plane normal="0 1 0" offset="-1">
    <material diffuse="1"><checker color1="1" color2="0.2"/></material>
  </plane>
  <sphere radius="1" transform="translate(\${2*clock - 1} 0 0)"/>
</scene>
XML

# is_png FILE: a complete PNG (its signature first, its IEND chunk last).
is_png() {
  [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] &&
    [ "$(tail -c 8 "$1" | head -c 4)" = "IEND" ]
}
name() { printf '%s/out%04d.png' "$tmp/$1" "$2"; }

# interrupt SIGNAL BIT: renders into $tmp/SIGNAL, where every frame's file already holds an
# old text, and stops the render with SIGNAL once frame 1 is written (BIT: its SigCgt bit).
interrupt() {
  local signal=$1 bit=$2 dir="$tmp/$1"
  mkdir "$dir"
  for f in $(seq "$frames"); do echo "old frame $f" >"$(name "$signal" "$f")"; done
  "$lucent" render "$tmp/scene.xml" -o "$dir/out.png" -q >"$tmp/stdout" 2>"$tmp/stderr" &
  local pid=$!
  # Until lucent catches the signal (its bit in SigCgt) a SIGINT would be lost: a shell
  # starts background jobs with SIGINT ignored.
  caught() { local mask; mask=$(awk '/^SigCgt/ {print $2}' /proc/"$pid"/status 2>/dev/null) &&
    [ -n "$mask" ] && [ $((0x$mask & bit)) -ne 0 ]; }
  for _ in $(seq 1200); do
    caught && is_png "$(name "$signal" 1)" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  for _ in $(seq 1200); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid"
    fail "$signal did not stop the render"
  fi
  wait "$pid"
  local status=$?
  [ "$status" -eq 3 ] || fail "$signal: exit status $status, expected 3; stderr: $(cat "$tmp/stderr")"

  # Frames 1..k are complete images, k+1..N the old texts, untouched.
  local written=0 f
  for f in $(seq "$frames"); do
    is_png "$(name "$signal" "$f")" || break
    written=$f
  done
  [ "$written" -ge 1 ] || fail "$signal: frame 1 is not a complete image"
  [ "$written" -lt "$frames" ] || fail "$signal: every frame was rendered; the signal came too late to test"
  for f in $(seq $((written + 1)) "$frames"); do
    [ "$(cat "$(name "$signal" "$f")")" = "old frame $f" ] ||
      fail "$signal: frame $f, after the last written ($written), was changed"
  done
  local leftovers
  leftovers=$(find "$dir" -name '.*' -type f | wc -l)
  [ "$leftovers" -eq 0 ] || fail "$signal: temporary files left: $(find "$dir" -name '.*' -type f)"
  grep -q "^lucent: interrupted.* $written of $frames frames written" "$tmp/stderr" ||
    fail "$signal: message: $(cat "$tmp/stderr") (frames written: $written)"
}

interrupt INT 2    # SIGINT is signal 2: bit 1 << 1
interrupt TERM 16384  # SIGTERM is signal 15: bit 1 << 14

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "render animation interrupt: finished frames complete, the current and later ones untouched, status 3"
