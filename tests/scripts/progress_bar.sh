#!/usr/bin/env bash
# The progress bar: on a terminal, lucent render draws "rendering [###...] NN%
# x.xx Mrays/s ETA m:ss" on stderr; with -q, or when stderr is not a terminal, it prints
# nothing there. script(1) (util-linux, always on Debian) gives the render a terminal.
# Usage: bash progress_bar.sh <path-to-lucent> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"

# The bar is redrawn every 250 ms: the render must last a few redraws. 2 samples of the
# five-shapes scene (the former showcase) at 480x360 take about 2.8 s of CPU (measured:
# 16 samples take 22 s), so at least a second on two cores; longer under load, which only
# means more redraws.
render=("$lucent" render "$src/examples/five-shapes.xml" -w 480 -h 360 -s 2)

# On a terminal: the bar with its four parts. script -e returns the command's status.
script -qec "$(printf '%q ' "${render[@]}" -o "$tmp/tty.png")" "$tmp/tty.log" >/dev/null 2>&1 ||
  fail "render on a terminal exited with $?"
grep -aq 'rendering \[[#.]\{30\}\] \+[0-9]\+%' "$tmp/tty.log" || fail "no bar with a percentage on the terminal"
grep -aq '[0-9]\.[0-9][0-9] Mrays/s' "$tmp/tty.log" || fail "no Mrays/s on the terminal"
grep -aq 'ETA [0-9]\+:[0-9][0-9]' "$tmp/tty.log" || fail "no ETA on the terminal"
[ -s "$tmp/tty.png" ] || fail "no image from the render on a terminal"

# -q on a terminal: silent.
script -qec "$(printf '%q ' "${render[@]}" -q -o "$tmp/quiet.png")" "$tmp/quiet.log" >/dev/null 2>&1 ||
  fail "render -q on a terminal exited with $?"
! grep -aq 'rendering \[' "$tmp/quiet.log" || fail "-q still draws the bar"

# stderr not a terminal (stdout still is): silent.
script -qec "$(printf '%q ' "${render[@]}" -o "$tmp/pipe.png") 2>$tmp/stderr.txt" "$tmp/pipe.log" >/dev/null 2>&1 ||
  fail "render with stderr to a file exited with $?"
! grep -aq 'rendering \[' "$tmp/stderr.txt" "$tmp/pipe.log" || fail "the bar is drawn when stderr is not a terminal"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "progress bar: drawn on a terminal, silent with -q and when stderr is not a terminal"
