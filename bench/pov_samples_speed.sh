#!/usr/bin/env bash
# The sample scenes as a speed benchmark: every scene of Debian's povray-examples that
# docs/pov-samples.md lists as imported, rendered by `lucent render` and by `povray` at
# 320x240, one sample, one thread, with the scene's .ini where it has one (an animation at
# its middle frame), each timed in CPU seconds of the whole process (user + system): import
# or parse, render, writing the PNG. Writes a TSV (scene, Lucent CPU, POV-Ray CPU, POV-Ray
# over Lucent) and prints a markdown summary: the median ratio, the scenes slower than
# POV-Ray, and the lowest ratios. bench/run.sh runs it and profiles the lowest ten.
#
#   bash bench/pov_samples_speed.sh [--lucent PATH] [--examples DIR] [--list FILE]
#                                   [--only REGEX] --tsv OUT
# --list names the page whose imported rows are measured (default docs/pov-samples.md).
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD

lucent=build/cli/lucent
examples=/usr/share/doc/povray/examples
list=docs/pov-samples.md
only=.
tsv=""
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --examples) examples=$2; shift 2 ;;
    --list) list=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    *) echo "usage: $0 [--lucent PATH] [--examples DIR] [--list FILE] [--only REGEX] --tsv OUT" >&2; exit 2 ;;
  esac
done
[ -n "$tsv" ] || { echo "$0: --tsv OUT is required" >&2; exit 2; }
lucent=$(realpath -m "$lucent")
tsv=$(realpath -m "$tsv")
[ -x "$lucent" ] || { echo "no lucent at $lucent (build it first)" >&2; exit 2; }
[ -d "$examples" ] || { echo "no $examples: run scripts/install-bench-deps (povray-examples)" >&2; exit 2; }
[ -f "$list" ] || { echo "no $list: run bench/pov_samples.sh first" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray is not installed (scripts/install-deps)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=bench/pov_samples_lib.sh
source "$root/bench/pov_samples_lib.sh"

# The scenes the page lists as imported with a PSNR (rendered and compared).
sed -n '/^## Every scene/,$p' "$list" | grep '^| ' | tail -n +3 |
  awk -F'|' '{ gsub(/ /, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $4) }
    $3 == "imported" && $4 != "" { print $2 }' >"$work/scenes"

printf 'scene\tlucent_cpu_s\tpovray_cpu_s\tratio\n' >"$tsv"
while IFS= read -r rel; do
  [[ "$rel" =~ $only ]] || continue
  pov=$examples/$rel
  [ -f "$pov" ] || continue
  sceneArgs "$pov"
  # In a copy of the scene's folder, where the scene may write, as bench/pov_samples.sh.
  rm -rf "$work/scene"
  cp -r "$(dirname "$pov")" "$work/scene"
  cd "$work/scene"
  timeRenders
  cd "$root"
  if [ -n "$ratio" ]; then
    printf '%s\t%s\t%s\t%s\n' "$rel" "$lucentCpu" "$povCpu" "$ratio" >>"$tsv"
    echo "$rel: Lucent $lucentCpu s, POV-Ray $povCpu s, ratio $ratio" >&2
  else
    echo "$rel: not timed (a render failed)" >&2
  fi
done <"$work/scenes"

# The summary.
tail -n +2 "$tsv" | awk -F'\t' '$4 != "n/a"' | sort -t$'\t' -k4,4g >"$work/sorted"
n=$(wc -l <"$work/sorted")
[ "$n" -gt 0 ] || { echo "no scene was timed" >&2; exit 1; }
median=$(cut -f4 "$work/sorted" | awk '{ v[NR] = $1 } END { if (NR % 2) printf "%.2f", v[(NR + 1) / 2]; else printf "%.2f", (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
slower=$(awk -F'\t' '$4 < 1' "$work/sorted" | wc -l)
echo "Sample scenes timed: $n; median CPU ratio (POV-Ray / Lucent) **${median}x**; slower than POV-Ray: $slower."
echo
echo "| scene | Lucent CPU (s) | POV-Ray CPU (s) | ratio |"
echo "| --- | --- | --- | --- |"
head -10 "$work/sorted" | awk -F'\t' '{ printf "| %s | %s | %s | %s |\n", $1, $2, $3, $4 }'
