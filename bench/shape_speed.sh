#!/usr/bin/env bash
# Each shape alone against POV-Ray 3.7 (docs/performance.md, "Each shape against POV-Ray"):
# for every bench/shapes/NAME.xml (one kind of shape, about half the frame, one light),
#   - Lucent's cost per ray of the world's closest-hit and any-hit searches over the
#     camera's primary rays (bench/shape_rays, one thread, best of 5 passes), and
#   - the whole process and the render alone, Lucent against POV-Ray on the export, one
#     thread each (bench/gallery_speed.sh on these scenes).
# Writes docs/performance-data/shape-speed.md (and .tsv files beside it).
#
#   bash bench/shape_speed.sh [--lucent PATH] [--shape-rays PATH] [--reps N] [SCENE.xml...]
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
shapeRays=build/bench/shape_rays
reps=3
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --shape-rays) shapeRays=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || scenes=(bench/shapes/*.xml)
out=docs/performance-data
mkdir -p "$out"

"$shapeRays" "${scenes[@]}" > "$out/shape-rays.tsv"
bash bench/gallery_speed.sh --lucent "$lucent" --threads 1 --reps "$reps" --no-doc \
  --out "$out/shape-processes" "${scenes[@]}"

{
  echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), one thread each, Lucent at commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), POV-Ray $(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9.]*[0-9]).*/\1/p' | head -1), best of $reps runs."
  echo
  echo '```sh'
  echo "bash bench/shape_speed.sh --reps $reps"
  echo '```'
  echo
  echo "Per ray: Lucent's closest-hit and any-hit searches of the scene's world over its primary rays (one per pixel, 400 × 300), in nanoseconds, with the fraction of rays that hit. Whole process and render: \`lucent render\` against \`povray\` on the export at one sample per pixel; each ratio is POV-Ray's time over Lucent's (above 1, Lucent is faster)."
  echo
  echo "| shape | hit | closest ns/ray | any-hit ns/ray | render Lucent s | trace POV-Ray s | render ratio | process Lucent s | process POV-Ray s | process ratio |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  join -t $'\t' <(tail -n +2 "$out/shape-rays.tsv" | sort) <(tail -n +2 "$out/shape-processes.tsv" | sort) |
    awk -F'\t' '{ printf "| %s | %.0f %% | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, 100 * $3, $4, $5, $14, $15, $16, $8, $9, $10 }'
} > "$out/shape-speed.md"
cat "$out/shape-speed.md"
