#!/usr/bin/env bash
# Two (or more) lucent binaries side by side on shadow-heavy gallery scenes: each scene is
# rendered by each binary in turn, `reps` rounds, one thread, one sample, and the best
# CPU time (user + system of the whole process, /usr/bin/time) and the best render time
# (--stats "time", the image alone) of each binary are printed as a Markdown table, with
# whether the binaries' images are identical (their pixels: one more render each, to PPM,
# since binaries may compress the same pixels differently). Alternating the binaries
# within each round lets both see the same machine load.
#
# Usage: bash bench/shadow_speed.sh [--reps N] [--size WxH] LUCENT_A LUCENT_B [...] \
#          [-- SCENE.xml ...]
# Default scenes: the gallery's light-area, sphere-box-shadows, glass-shadows, light-spot.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
reps=3
size=""
bins=()
scenes=()
while [ $# -gt 0 ]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --) shift; scenes=("$@"); break ;;
    *) bins+=("$1"); shift ;;
  esac
done
[ ${#bins[@]} -ge 2 ] || { echo "usage: $0 [--reps N] [--size WxH] LUCENT_A LUCENT_B [...] [-- scenes]" >&2; exit 2; }
if [ ${#scenes[@]} -eq 0 ]; then
  for s in light-area sphere-box-shadows glass-shadows light-spot; do
    scenes+=("$here/examples/gallery/$s.xml")
  done
fi
sizeArgs=()
if [ -n "$size" ]; then sizeArgs=(-w "${size%x*}" -h "${size#*x}"); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(b == "" || a < b) }'; }

# The start-up alone, to subtract from the CPU times: `lucent --version`, best of reps.
echo "start-up (lucent --version, CPU s, best of $reps):"
for b in "${bins[@]}"; do
  best=""
  for ((r = 0; r < reps; r++)); do
    /usr/bin/time -o "$work/t" -f '%U %S' "$b" --version > /dev/null
    t=$(awk '{ printf "%.2f", $1 + $2 }' "$work/t")
    if less "$t" "$best"; then best=$t; fi
  done
  echo "  $b: $best"
done
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo

header="| scene |"
rule="|---|"
letters=(A B C D E F)
for i in "${!bins[@]}"; do
  echo "${letters[$i]}: ${bins[$i]}"
  header+=" CPU s ${letters[$i]} | render s ${letters[$i]} |"
  rule+="---|---|"
done
echo
echo "$header images |"
echo "$rule---|"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .xml)
  declare -A cpu=() render=()
  for ((r = 0; r < reps; r++)); do
    for i in "${!bins[@]}"; do
      /usr/bin/time -o "$work/t" -f '%U %S' "${bins[$i]}" render "$scene" -o "$work/$i.png" \
        -s 1 -t 1 -q --stats "${sizeArgs[@]}" --allow-path "$here/examples" > "$work/stats"
      c=$(awk '{ printf "%.2f", $1 + $2 }' "$work/t")
      s=$(awk '/^time:/ { print $2 }' "$work/stats")
      if less "$c" "${cpu[$i]:-}"; then cpu[$i]=$c; fi
      if less "$s" "${render[$i]:-}"; then render[$i]=$s; fi
    done
  done
  # The pixels, not the PNG files: binaries may compress the same pixels differently.
  for i in "${!bins[@]}"; do
    "${bins[$i]}" render "$scene" -o "$work/$i.ppm" -s 1 -t 1 -q "${sizeArgs[@]}" \
      --allow-path "$here/examples" > /dev/null
  done
  same=identical
  for i in "${!bins[@]}"; do cmp -s "$work/0.ppm" "$work/$i.ppm" || same=differ; done
  row="| $name |"
  for i in "${!bins[@]}"; do row+=" ${cpu[$i]} | ${render[$i]} |"; done
  echo "$row $same |"
  unset cpu render
done
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
