#!/usr/bin/env bash
# Two Lucent builds side by side on the same scenes: is a change free for scenes that do not
# use it? Each scene is rendered by BEFORE and AFTER in turn (alternating, so a change in the
# machine's load hits both), REPS times each on one thread; the least CPU time (user +
# system) of each is kept (at 640×480, so that the render dominates start-up) and the ratio AFTER/BEFORE printed. Scenes that the BEFORE build
# cannot read (they use new features) are skipped. The results go to docs/performance.md by
# hand, with the commits of both builds.
#
#   bash bench/before_after.sh BEFORE-LUCENT AFTER-LUCENT [--reps N] [SCENE.xml...]
# (default scenes: examples/gallery/*.xml)
set -euo pipefail
cd "$(dirname "$0")/.."
before=$1
after=$2
shift 2
reps=5
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --reps) reps=$2; shift 2 ;;
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
