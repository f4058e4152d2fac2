#!/usr/bin/env bash
# Two Lucent builds side by side on the same scenes: is a change free for scenes that do not
# use it? Each scene is rendered by BEFORE and AFTER in turn (alternating, so a change in the
# machine's load hits both), REPS times each on one thread; the least CPU time (user +
# system) of each is kept (at 640×480, so that the render dominates start-up) and the ratio AFTER/BEFORE printed. Scenes that the BEFORE build
# cannot read (they use new features) are skipped. The results go to docs/performance.md by
# hand, with the commits of both builds.
#
#   bash bench/before_after.sh BEFORE-LUCENT AFTER-LUCENT [--reps N] [--instructions] [SCENE.xml...]
# (default scenes: examples/gallery/*.xml)
#
# --instructions: instead of CPU time, the instructions executed inside the renderer
# (Renderer::render and all it calls, counted by valgrind's callgrind, one run each at
# 320×240): a count that does not depend on the machine's load, for a machine that is
# never quiet. It measures work, not time: a change in cache behaviour or code layout does
# not show in it. Both builds must be configured with -DLUCENT_NATIVE=OFF: Debian 12's
# valgrind (3.19) stops at the AVX-512 instructions -march=native gives on such machines.
set -euo pipefail
cd "$(dirname "$0")/.."
before=$1
after=$2
shift 2
reps=5
instructions=0
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --reps) reps=$2; shift 2 ;;
    --instructions) instructions=1; shift ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -eq 0 ] && scenes=(examples/gallery/*.xml)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# cpu BINARY SCENE: the CPU seconds of one whole render to PPM (no image-library start-up).
cpu() {
  TIMEFORMAT='%U %S'
  { time "$1" render "$2" -o "$tmp/out.ppm" -w 640 -h 480 --threads 1 --quiet >/dev/null 2>&1; } 2>"$tmp/time"
  awk '{printf "%.3f", $1 + $2}' "$tmp/time"
}

# instructions BINARY SCENE: millions of instructions executed inside Renderer::render.
instructions() {
  rm -f "$tmp"/callgrind.out
  valgrind --tool=callgrind --callgrind-out-file="$tmp/callgrind.out" \
    --toggle-collect='lucent::Renderer::render(*' \
    "$1" render "$2" -o "$tmp/out.ppm" -w 320 -h 240 --threads 1 --quiet >/dev/null 2>&1
  awk '/^summary:/ {printf "%.3f", $2 / 1e6}' "$tmp/callgrind.out"
}

if [ "$instructions" = 1 ]; then
  printf '%-28s %12s %12s %8s\n' scene before_Mi after_Mi ratio
  sumB=0
  sumA=0
  for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .xml)
    "$before" check "$scene" >/dev/null 2>&1 || continue
    grep -q "<animation" "$scene" && continue
    b=$(instructions "$before" "$scene")
    a=$(instructions "$after" "$scene")
    sumB=$(awk -v x="$sumB" -v y="$b" 'BEGIN{print x + y}')
    sumA=$(awk -v x="$sumA" -v y="$a" 'BEGIN{print x + y}')
    printf '%-28s %12.3f %12.3f %8.4f\n' "$name" "$b" "$a" "$(awk -v a="$a" -v b="$b" 'BEGIN{print (b > 0) ? a / b : 1}')"
  done
  printf '%-28s %12.3f %12.3f %8.4f\n' "total" "$sumB" "$sumA" "$(awk -v a="$sumA" -v b="$sumB" 'BEGIN{print (b > 0) ? a / b : 1}')"
  exit 0
fi

printf '%-28s %10s %10s %8s\n' scene before_s after_s ratio
sumB=0
sumA=0
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .xml)
  # Animated scenes and scenes the old build refuses are left out.
  "$before" check "$scene" >/dev/null 2>&1 || continue
  grep -q "<animation" "$scene" && continue
  bestB=1e9
  bestA=1e9
  for ((i = 0; i < reps; i++)); do
    b=$(cpu "$before" "$scene")
    a=$(cpu "$after" "$scene")
    bestB=$(awk -v x="$b" -v y="$bestB" 'BEGIN{print (x < y) ? x : y}')
    bestA=$(awk -v x="$a" -v y="$bestA" 'BEGIN{print (x < y) ? x : y}')
  done
  sumB=$(awk -v x="$sumB" -v y="$bestB" 'BEGIN{print x + y}')
  sumA=$(awk -v x="$sumA" -v y="$bestA" 'BEGIN{print x + y}')
  printf '%-28s %10.3f %10.3f %8.3f\n' "$name" "$bestB" "$bestA" "$(awk -v a="$bestA" -v b="$bestB" 'BEGIN{print (b > 0) ? a / b : 1}')"
done
printf '%-28s %10.3f %10.3f %8.3f\n' "total" "$sumB" "$sumA" "$(awk -v a="$sumA" -v b="$sumB" 'BEGIN{print (b > 0) ? a / b : 1}')"
