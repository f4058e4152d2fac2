#!/usr/bin/env bash
# lucent render's output contract: exit status 3 when the image cannot be written (a full
# device, a missing folder, an unknown extension, a file size limit hit while writing,
# Ctrl-C), and an existing image is only ever replaced by a complete one.
# Usage: bash render_output.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

cat > "$tmp/scene.xml" <<'XML'
<scene version="1">
  <render width="64" height="48"/>
  <camera position="0 1 5" look-at="0 0 0"/>
  <light position="5 5 5"/>
  <material id="red" diffuse="1 0.2 0.1" specular="0.5" shininess="40"/>
  <plane normal="0 1 0" offset="-1">
    <material diffuse="1"><checker color1="1" color2="0.2"/></material>
  </plane>
  <sphere radius="1" material="red"/>
</scene>
XML

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

# A first image to protect.
expect 0 "first render" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q
[ -s "$tmp/out.png" ] || fail "first render wrote no image"
cp "$tmp/out.png" "$tmp/reference.png"

expect 3 "-o /dev/full" -- "$lucent" render "$tmp/scene.xml" -o /dev/full -q
[ -c /dev/full ] || fail "/dev/full is no longer a character device"
grep -q "cannot write '/dev/full'" "$tmp/stderr" || fail "/dev/full: message: $(cat "$tmp/stderr")"

expect 3 "missing folder" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/no/such/folder/out.png" -q
grep -q "does not exist" "$tmp/stderr" || fail "missing folder: message: $(cat "$tmp/stderr")"

expect 3 "unknown extension" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.xyz" -q
grep -q "unknown image format '.xyz'" "$tmp/stderr" || fail "unknown extension: message: $(cat "$tmp/stderr")"

expect 3 "output is a folder" -- "$lucent" render "$tmp/scene.xml" -o "$tmp" -q

# A folder that cannot be written. We may run as root, whom permission bits do not stop,
# so use places no one can write into: a regular file standing where a folder should be,
# and /proc (the kernel refuses to create files there).
echo "a file, not a folder" > "$tmp/afile"
expect 3 "a file where a folder should be" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/afile/out.png" -q
grep -q "cannot write '$tmp/afile/out.png'" "$tmp/stderr" || fail "file as folder: message: $(cat "$tmp/stderr")"
expect 3 "an unwritable folder (/proc)" -- "$lucent" render "$tmp/scene.xml" -o /proc/lucent-test-out.png -q
grep -q "cannot write '/proc/lucent-test-out.png'" "$tmp/stderr" || fail "/proc: message: $(cat "$tmp/stderr")"
[ -e /proc/lucent-test-out.png ] && fail "/proc/lucent-test-out.png exists"

# A write that fails half way: a 1 KiB file size limit (SIGXFSZ ignored, so write()
# fails with EFBIG instead of killing the process). The PNG of this image is larger.
( ulimit -f 1; trap '' XFSZ; exec "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q \
    -w 200 -h 150 ) >"$tmp/stdout" 2>"$tmp/stderr"
status=$?
[ "$status" -eq 3 ] || fail "file size limit: exit status $status, expected 3; stderr: $(cat "$tmp/stderr")"

cmp -s "$tmp/out.png" "$tmp/reference.png" || fail "the old image was changed by a failed render"
leftovers=$(find "$tmp" -name '.*lucent-*' | wc -l)
[ "$leftovers" -eq 0 ] || fail "temporary files left behind: $(find "$tmp" -name '.*lucent-*')"

# Ctrl-C and SIGTERM: a render too long to finish is interrupted; exit status 3, old image
# intact, nothing else written.
expect 0 "render to be interrupted later" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/big.png" -q -w 16 -h 16
cp "$tmp/big.png" "$tmp/big-reference.png"
# interrupt SIGNAL MASK NAME: a long render stopped by SIGNAL (MASK: its bit in SigCgt).
interrupt() {
  local signal=$1 bit=$2 name=$3
  "$lucent" render "$tmp/scene.xml" -o "$tmp/big.png" -q -w 320 -h 240 -s 2000 >"$tmp/stdout" 2>"$tmp/stderr" &
  pid=$!
  # Wait until lucent catches the signal (its bit of SigCgt in /proc): before that SIGINT
  # would be lost, since a shell starts background jobs with SIGINT ignored.
  caught() { local mask; mask=$(awk '/^SigCgt/ {print $2}' /proc/"$pid"/status 2>/dev/null) &&
    [ -n "$mask" ] && [ $((0x$mask & bit)) -ne 0 ]; }
  for _ in $(seq 1200); do
    caught && break
    sleep 0.1
  done
  kill -"$signal" "$pid"
  # The renderer polls the flag every row; allow a loaded machine two minutes to stop.
  for _ in $(seq 1200); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid"
    fail "$name did not stop the render"
  fi
  wait "$pid"
  status=$?
  [ "$status" -eq 3 ] || fail "$name: exit status $status, expected 3; stderr: $(cat "$tmp/stderr")"
  grep -q "interrupted; '$tmp/big.png' left unchanged" "$tmp/stderr" || fail "$name: message: $(cat "$tmp/stderr")"
  cmp -s "$tmp/big.png" "$tmp/big-reference.png" || fail "$name changed the old image"
  # Nothing else is written but the checkpoint (its tiles for --resume: render_checkpoint.sh):
  # no partial image, no temporary file.
  extra=$(find "$tmp" -newer "$tmp/big-reference.png" -type f ! -name stdout ! -name stderr ! -name big.png.checkpoint)
  [ -z "$extra" ] || fail "$name left files behind: $extra"
  head -c 20 "$tmp/big.png.checkpoint" | grep -q "^lucent checkpoint 1" || fail "$name left no checkpoint"
  grep -q "the checkpoint '$tmp/big.png.checkpoint' keeps the finished tiles" "$tmp/stderr" ||
    fail "$name: no word of the checkpoint: $(cat "$tmp/stderr")"
  rm -f "$tmp/big.png.checkpoint"
}
interrupt INT 2 "Ctrl-C"
interrupt TERM $((1 << 14)) "SIGTERM"

# And a successful render replaces the image.
expect 0 "replacing render" -- "$lucent" render "$tmp/scene.xml" -o "$tmp/out.png" -q -w 32 -h 24
cmp -s "$tmp/out.png" "$tmp/reference.png" && fail "a successful render did not replace the image"

[ "$failures" -eq 0 ] && echo "render_output: all checks passed"
exit $((failures > 0))
