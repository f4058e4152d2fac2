#!/usr/bin/env bash
# What an animation costs per frame beyond the render itself: parsing the scene again for
# the frame, building its world, writing its image, the frame loop. Renders a 24-frame
# animation of a tiny scene (64x48, one sphere moving with clock; and the same with a mesh
# file and an image texture, which the frames share) with --stats, and takes each frame's
# time minus its render time, frames 2..N (frame 1 also pays for the first reads). Then
# the same frames as one process each (-D frame=F), which pays start-up and the file reads
# every time, for comparison. Prints a markdown table.
#
#   bash bench/animation_overhead.sh [--lucent PATH] [--frames N]
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
frames=24
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    *) echo "usage: $0 [--lucent PATH] [--frames N]" >&2; exit 2 ;;
  esac
done
lucent=$(realpath -m "$lucent")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp examples/meshes/icosahedron.off examples/textures/uvgrid.png "$work/"

cat > "$work/sphere.xml" <<XML
<scene version="1">
  <animation frames="$frames"/>
  <render width="64" height="48"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <sphere radius="1" transform="translate(\${2*clock - 1} 0 0)"/>
</scene>
XML
cat > "$work/files.xml" <<XML
<scene version="1">
  <animation frames="$frames"/>
  <render width="64" height="48"/>
  <camera position="0 1 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <sphere radius="0.7" transform="translate(\${2*clock - 1} 0 0)">
    <material><image src="uvgrid.png"/></material>
  </sphere>
  <mesh src="icosahedron.off" transform="scale(0.5) translate(0 -1 0)"/>
</scene>
XML

now() { date +%s.%N; }
ms() { awk -v a="$1" -v b="$2" -v n="$3" 'BEGIN { printf "%.1f", 1000 * (b - a) / n }'; }

# row NAME SCENE: one process for all frames (--stats), then one process per frame.
row() {
  local name=$1 scene=$2 start end oneProcess processes overhead files
  mkdir -p "$work/$name"
  start=$(now)
  "$lucent" render "$scene" -o "$work/$name/f.png" -q --stats >"$work/$name.stats"
  end=$(now)
  oneProcess=$(ms "$start" "$end" "$frames")
  # "frame     N:      T  s (load L s, render R s, write and the rest W s)"
  overhead=$(awk '/^frame +[0-9]+:/ {
      n = $2 + 0; t = $3; load = $6; r = $9
      if (n > 1) { sum += t - r; loads += load; count++ }
    }
    END { if (count) printf "%.1f %.1f", 1000 * sum / count, 1000 * loads / count; else print "? ?" }' \
    "$work/$name.stats")
  files=$(awk '/^files:/ {print $2 " mesh, " $6 " image"}' "$work/$name.stats")
  start=$(now)
  for f in $(seq "$frames"); do
    "$lucent" render "$scene" -o "$work/$name/p$f.png" -q -D frame="$f"
  done
  end=$(now)
  processes=$(ms "$start" "$end" "$frames")
  read -r perFrame load <<<"$overhead"
  echo "| $name | $perFrame | $load | $oneProcess | $processes | $files |"
}

echo "Per-frame cost of a $frames-frame animation at 64x48, in ms (frames 2..$frames for the first two columns):"
echo
echo "| scene | frame minus its render | of it, loading the scene | wall a frame, one process | wall a frame, a process each | files read by the one process |"
echo "| --- | ---: | ---: | ---: | ---: | --- |"
row sphere "$work/sphere.xml"
row "mesh+texture" "$work/files.xml"
