#!/usr/bin/env bash
# Regenerates docs/performance.md and its plots on this machine: installs the benchmark
# dependencies (Embree 3, gnuplot), builds the benchmarks (Release) in build-bench/, runs
# them and writes the tables, the plots (docs/images/perf-*.png) and the raw figures
# (docs/performance-data/*.tsv).
#
#   bash bench/run.sh           # the full run (about ten minutes on two cores)
#   bash bench/run.sh --quick   # small sizes: checks the pipeline, figures not meaningful
# LUCENT_BENCH_BUILD names another build folder (default build-bench).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${LUCENT_BENCH_BUILD:-build-bench}

quick=0
[ "${1:-}" = "--quick" ] && quick=1
if [ $quick -eq 1 ]; then
  tris=20000; size=256; scaleMax=10000; scaleSize=64; peakSize=128; povRepeat=1
else
  tris=1000000; size=1024; scaleMax=1000000; scaleSize=256; peakSize=640; povRepeat=3
fi

bash scripts/install-bench-deps
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target lucent mesh_embree bvh_scaling bvh_threads \
  peak_memory vs_povray >/dev/null

data=docs/performance-data
img=docs/images
mkdir -p "$data" "$img"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "bench/run.sh: Lucent against Embree (${tris} triangles)" >&2
"$build"/bench/mesh_embree --triangles "$tris" --size "$size" --tsv "$data/embree.tsv" \
  | tee "$work/embree.md"
echo "bench/run.sh: time per ray against primitive count" >&2
"$build"/bench/bvh_scaling --max "$scaleMax" --size "$scaleSize" --tsv "$data/scaling.tsv" \
  | tee "$work/scaling.md"
echo "bench/run.sh: thread scaling" >&2
"$build"/bench/bvh_threads --triangles "$tris" --size "$size" --tsv "$data/threads.tsv" \
  | tee "$work/threads.md"
echo "bench/run.sh: peak memory of lucent render" >&2
"$build"/bench/peak_memory "$build"/cli/lucent "$work" --triangles "$tris" \
  --size "$peakSize" | tee "$work/peak.md" || true
echo "bench/run.sh: whole-process time against POV-Ray" >&2
if command -v povray >/dev/null; then
  "$build"/bench/vs_povray "$build"/cli/lucent "$work" --triangles "$tris" --size "$peakSize" \
    --repeat "$povRepeat" --povray "$(command -v povray)" --tsv "$data/povray.tsv" \
    | tee "$work/povray.md" || true
else
  echo "# vs_povray: povray is not installed (apt-get install povray)" | tee "$work/povray.md"
fi

# ---- plots ----
gnuplot <<EOF
set terminal pngcairo size 800,480 font "sans,11"
set output "$img/perf-embree.png"
set title "Rays per second on a ${tris}-triangle mesh (same rays, same run)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set ylabel "million rays per second"
set yrange [0:*]
set key top left
set grid ytics
set datafile separator "\t"
plot "< grep -E '^(primary|shadow)' $data/embree.tsv" using 3:xtic(sprintf("%s, %s thr", strcol(1), strcol(2))) title "Lucent", \
     "" using 4 title "Embree 3"

set output "$img/perf-scaling.png"
set title "Time per ray against primitive count (one thread)"
unset style
set style data linespoints
set autoscale y
set logscale xy
set xlabel "primitives"
set ylabel "nanoseconds per ray"
set format x "10^{%L}"
set key top left
plot "$data/scaling.tsv" using 1:2 title "spheres (world BVH over instances)" pt 7, \
     "" using 1:3 title "triangles (mesh BVH)" pt 5

set output "$img/perf-threads.png"
set title "Thread scaling, ${tris}-triangle mesh"
unset logscale
set format x "%g"
set xlabel "threads"
set ylabel "speed-up over one thread"
set xtics 1
set key top left
plot "$data/threads.tsv" using 1:3 title "primary rays" pt 7, \
     "" using 1:5 title "shadow rays" pt 5, \
     x title "ideal" dashtype 2 lc rgb "grey"
EOF

# ---- targets, from the raw figures ----
# The markdown tables of a program's output, a blank line after each.
tables() { awk '/^\|/ {print; t = 1; next} t {print ""; t = 0} END {if (t) print ""}' "$1"; }
round() { awk -v x="$1" 'BEGIN { if (x == "") print "n/a"; else printf "%.2f", x }'; }
val() { awk -F'\t' -v k="$1" -v t="$2" -v c="$3" '$1==k && $2==t {print $c}' "$data/embree.tsv"; }
threads=$(awk -F'\t' '$1=="primary" && $2!="1" {print $2}' "$data/embree.tsv")
ratio1=$(round "$(val primary 1 5)")
build1=$(round "$(val build 1 3)")
buildN=$(round "$(val build "$threads" 3)")
bytes=$(round "$(val memory all 3)")
growth=$(awk -F'\t' '$1==1000 {a=$3} $1==1000000 {b=$3} END {if (a && b) printf "%.2f", b/a; else print "n/a"}' "$data/scaling.tsv")
growthS=$(awk -F'\t' '$1==1000 {a=$2} $1==1000000 {b=$2} END {if (a && b) printf "%.2f", b/a; else print "n/a"}' "$data/scaling.tsv")
peak=$(grep -E '^\| `lucent render`' "$work/peak.md" | awk -F'|' '{gsub(/[ MB]/,"",$5); print $5}')
povMesh=$(awk -F'\t' '$1=="bumpy" {printf "%.2f", $8}' "$data/povray.tsv" 2>/dev/null)
povMeshCpu=$(awk -F'\t' '$1=="bumpy" {printf "%.2f", $9}' "$data/povray.tsv" 2>/dev/null)
povSpheres=$(awk -F'\t' '$1=="spheres" {printf "%.2f", $8}' "$data/povray.tsv" 2>/dev/null)
povSpheresCpu=$(awk -F'\t' '$1=="spheres" {printf "%.2f", $9}' "$data/povray.tsv" 2>/dev/null)
peakBase=$(grep -E '^\| `lucent --version`' "$work/peak.md" | awk -F'|' '{gsub(/[ MB]/,"",$5); print $5}')
met() { awk -v x="$1" -v op="$2" -v y="$3" 'BEGIN { if (x == "" || x == "n/a") print "not measured";
  else if ((op == ">=" && x + 0 >= y + 0) || (op == "<=" && x + 0 <= y + 0) || (op == "<" && x + 0 < y + 0)) print "met";
  else print "**not met**" }'; }

cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
# The section written by bench/gallery_speed.sh (its table and the reading below it) is
# kept as it is: this script does not measure the gallery.
gallerySection=$(sed -n '/^## The gallery against POV-Ray/,/^## Raw outputs/{/^## Raw outputs/!p}' docs/performance.md 2>/dev/null || true)
{
cat <<EOF
# Performance

Lucent finds ray hits with a bounding volume hierarchy at every level that has many
children: the scene's top level (one entry per shape instance), inside each mesh (its
triangles) and inside each CSG node (its children). This page gives the figures measured
by \`bench/\`, side by side with Embree 3 where a comparison makes sense.

Regenerate everything on this page (tables, plots, raw figures) with:

\`\`\`sh
bash bench/run.sh
\`\`\`

It installs what the benchmarks alone need (\`scripts/install-bench-deps\`: Debian's
\`libembree-dev\` and \`gnuplot-nox\`; Lucent itself never links Embree), builds the
programs of \`bench/\` in Release mode in \`build-bench/\` and runs them. The meshes are made
by the programs (a tessellated sphere displaced by a sum of sines), never downloaded.

Measured on: ${cpu}, $(nproc) hardware threads, $(date -u +%Y-%m-%d).
Every time is the best of three runs. The machine is shared: each program prints the load
average at its start (in the raw outputs below); a high load lowers every figure,
Lucent's and Embree's alike, which is why the comparisons are ratios measured in the same
run on the same rays.

## Targets

| target | measured | |
|---|---|---|
| single-thread primary rays on the 1M-triangle mesh: at least half of Embree's rays/s | ${ratio1}× Embree | $(met "$ratio1" ">=" 0.5) |
| time per ray at 10^6 primitives at most 3× the time at 10^3 (triangles; spheres) | ${growth}×; ${growthS}× | $(met "$growth" "<=" 3) |
| BVH build on one thread: at least 3 M triangles/s | ${build1} M/s | $(met "$build1" ">=" 3) |
| BVH build on ${threads} threads: at least 5 M triangles/s (target stated for two) | ${buildN} M/s | $(met "$buildN" ">=" 5) |
| memory per triangle (vertices, indices, BVH): at most 64 bytes | ${bytes} B | $(met "$bytes" "<=" 64) |
| peak memory rendering a 1M-triangle scene: under 150 MB | ${peak} MB (the process alone: ${peakBase} MB) | $(met "$peak" "<" 150) |
| whole process on the 1M-triangle scene, one thread: at least 4× faster than POV-Ray | ${povMesh:-n/a}× wall (${povMeshCpu:-n/a}× CPU time) | $(met "${povMesh:-n/a}" ">=" 4) |
| whole process on a thousand spheres, one thread: at least 2× faster than POV-Ray | ${povSpheres:-n/a}× wall (${povSpheresCpu:-n/a}× CPU time) | $(met "${povSpheres:-n/a}" ">=" 2) |

## Lucent and Embree 3 on one million triangles

![Rays per second, Lucent and Embree](images/perf-embree.png)

The same double-precision rays go to both (Embree's rounded to float): camera rays through
a ${size}×${size} image in 8×8 tiles, then shadow rays from Lucent's hit points to a point
light. Lucent answers through its \`World\` (an instance of the mesh shape, exactly what
the renderer calls, watertight double-precision triangle tests); Embree through
\`rtcIntersect1\` and \`rtcOccluded1\`, its one-ray interface (its packet and stream
interfaces are faster still and have no counterpart in Lucent). "All threads" spreads the
rays over TBB's threads in chunks of 1024 for both.

$(tables "$work/embree.md")

$(grep -E '^agreement' "$work/embree.md")

Build speed counts Lucent's whole mesh shape construction (bounds of every triangle, the
BVH build, the leaf order) against Embree's \`rtcCommitScene\` at its default (medium)
quality, with Embree's device limited to one thread and then given all of them. Memory
counts what each keeps per triangle: Lucent its double-precision positions, its indices
and its BVH (4-wide nodes, 32 bytes per child entry, plus a 4-byte leaf order), Embree
its float copy of the buffers plus everything its device allocates for the BVH.

## Time per ray as the primitive count grows

![Time per ray against primitive count](images/perf-scaling.png)

One thread, ${scaleSize}×${scaleSize} camera rays, timed on the thread's CPU clock (best
of three), so time spent waiting for a core on a shared machine is not counted. Spheres: n spheres scattered over the unit
sphere with radius 2/√n (they cover it about once at every n), each its own instance in
the world's top-level BVH. Triangles: the displaced sphere tessellated into about n
triangles, one mesh with its own BVH. Both keep the same picture as n grows, so the
growth is the hierarchy's (ideally logarithmic) and the caches'.

$(tables "$work/scaling.md")

## Thread scaling

![Thread scaling](images/perf-threads.png)

$(tables "$work/threads.md")

## Peak memory of a whole render

\`lucent render\` of a scene holding the mesh (binary PLY file, flat shading, one point
light, ${peakSize}×${peakSize} pixels, one sample), its peak resident memory as the kernel
counts it (getrusage of the child process): parsing, loading and repairing the mesh file,
the BVH, the image. Beside it \`lucent --version\`, which loads the same program and
its shared libraries (OpenImageIO and its own dependencies are most of them) and does
nothing else: that much is spent before any scene.

$(tables "$work/peak.md")

## Whole-process comparison with POV-Ray

The same scenes rendered by \`lucent render --threads 1\` and by POV-Ray 3.7
(\`povray +WT1\`), each the whole process from start to exit: parsing, loading, building
the acceleration structures, rendering, writing the PNG. The POV-Ray scenes are the
exports of Lucent's (\`lucent export-pov\`): the mesh becomes an inline \`mesh2\` (POV-Ray
reads no PLY file), which POV-Ray parses as text, the way its users hold large meshes.
The sphere field is a thousand spheres of three materials, one of them a mirror, on a
checkered plane under two point lights. One sample per pixel, no anti-aliasing in either.
Every time is the best of ${povRepeat} runs; the peak memory is the largest of them.
Measured by \`bench/vs_povray\` (run by \`bench/run.sh\`):

\`\`\`sh
build-bench/bench/vs_povray build-bench/cli/lucent /tmp/work --triangles ${tris} --size ${peakSize} --repeat ${povRepeat}
\`\`\`

$(tables "$work/povray.md")

${gallerySection}

## Raw outputs

\`\`\`
$(grep -E '^#' "$work/embree.md" "$work/scaling.md" "$work/threads.md" "$work/peak.md" "$work/povray.md" | sed 's/^[^:]*://')
\`\`\`

The tab-separated figures behind the plots are in \`docs/performance-data/\`.
EOF
} > docs/performance.md
echo "bench/run.sh: wrote docs/performance.md, $img/perf-*.png, $data/*.tsv" >&2
