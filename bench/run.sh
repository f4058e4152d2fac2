#!/usr/bin/env bash
# Measures Lucent's performance on this machine: installs the benchmark dependencies
# (Embree 3, gnuplot), builds the benchmarks (Release) in build-bench/, runs them and
# writes the plots (docs/images/perf-*.png), the raw figures (docs/performance-data/*.tsv),
# every table of the run with the programs' raw outputs (docs/performance-data/latest-run.md)
# and the section of docs/performance.md between its two "bench/run.sh" markers (the
# targets with the latest figures, one table). The rest of that page is written by hand
# and is left as it is; dated measurements go to docs/performance-history.md.
#
#   bash bench/run.sh           # the full run (about ten minutes on two cores)
#   bash bench/run.sh --quick   # small sizes: checks the pipeline; figures not meaningful,
#                               # so it writes into a temporary folder, never into docs/
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

# The commit measured, told before this script writes anything of its own.
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if ! git diff --quiet HEAD -- . 2>/dev/null; then commit="$commit with uncommitted changes"; fi
work=$(mktemp -d)
page=docs/performance.md
if [ $quick -eq 1 ]; then
  # Nothing in docs/ changes: the page, plots and figures go to a folder that is kept.
  out=$(mktemp -d)
  data=$out/performance-data img=$out/images
  cp "$page" "$out/performance.md"
  page=$out/performance.md
else
  data=docs/performance-data img=docs/images
fi
mkdir -p "$data" "$img"
trap 'rm -rf "$work"' EXIT
begin='<!-- bench/run.sh: begin -->'
end='<!-- bench/run.sh: end -->'
if ! grep -qxF "$begin" "$page" || ! grep -qxF "$end" "$page"; then
  echo "bench/run.sh: error: $page lacks the lines '$begin' and '$end' that mark the section it writes" >&2
  exit 1
fi

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
{
cat <<EOF
## Latest figures

Written by \`bash bench/run.sh\` (this section only). Measured on ${cpu}, $(nproc) hardware
threads, $(date -u +"%Y-%m-%d %H:%M") UTC, commit ${commit}. Every time is the best of three
runs (${povRepeat} for POV-Ray); comparisons with Embree and POV-Ray are ratios measured in
the same run on the same rays, and the one-thread figures of \`bvh_scaling\` are CPU time.
Every table of the run, with the load average at each program's start:
[performance-data/latest-run.md](performance-data/latest-run.md).

| target | measured | |
|---|---|---|
| single-thread primary rays on the 1M-triangle mesh: at least half of Embree's rays/s | ${ratio1}× Embree | $(met "$ratio1" ">=" 0.5) |
| time per ray at 10^6 primitives at most 3× the time at 10^3 (triangles; spheres) | ${growth}×; ${growthS}× | $(met "$growth" "<=" 3) (triangles); $(met "$growthS" "<=" 3) (spheres) |
| BVH build on one thread: at least 3 M triangles/s | ${build1} M/s | $(met "$build1" ">=" 3) |
| BVH build on ${threads} threads: at least 5 M triangles/s (target stated for two) | ${buildN} M/s | $(met "$buildN" ">=" 5) |
| memory per triangle (vertices, indices, BVH): at most 64 bytes | ${bytes} B | $(met "$bytes" "<=" 64) |
| peak memory rendering a 1M-triangle scene: under 150 MB | ${peak} MB (the process alone: ${peakBase} MB) | $(met "$peak" "<" 150) |
| whole process on the 1M-triangle scene, one thread: at least 4× faster than POV-Ray | ${povMesh:-n/a}× wall (${povMeshCpu:-n/a}× CPU time) | $(met "${povMesh:-n/a}" ">=" 4) |
| whole process on a thousand spheres, one thread: at least 2× faster than POV-Ray | ${povSpheres:-n/a}× wall (${povSpheresCpu:-n/a}× CPU time) | $(met "${povSpheres:-n/a}" ">=" 2) |
EOF
} > "$work/section.md"

{
cat <<EOF
# Latest full run of bench/run.sh

Written by \`bash bench/run.sh\` (the whole file); its targets are summed up in
[docs/performance.md](../performance.md). Measured on ${cpu}, $(nproc) hardware threads,
$(date -u +"%Y-%m-%d %H:%M") UTC, commit ${commit}; each program prints the load average at
its start (raw outputs at the end). Every time is the best of three runs (${povRepeat} for
POV-Ray; for Lucent against Embree, five passes over the rays and three builds, Lucent's
and Embree's in turn, so that a slow spell of the machine falls on both). A high load
lowers every figure, Lucent's and Embree's alike, which is why the comparisons are ratios
measured in the same run on the same rays; the one-thread figures of \`bvh_scaling\` are
CPU time.

## Lucent and Embree 3 (${tris} triangles, ${size}×${size} camera rays)

$(tables "$work/embree.md")

$(grep -E '^agreement' "$work/embree.md")

## Time per ray as the primitive count grows (${scaleSize}×${scaleSize} rays, one thread)

$(tables "$work/scaling.md")

## Thread scaling (${tris} triangles)

$(tables "$work/threads.md")

## Peak memory of a whole render (${peakSize}×${peakSize})

$(tables "$work/peak.md")

## Whole process against POV-Ray (one thread, best of ${povRepeat})

\`\`\`sh
build-bench/bench/vs_povray build-bench/cli/lucent /tmp/work --triangles ${tris} --size ${peakSize} --repeat ${povRepeat}
\`\`\`

$(tables "$work/povray.md")

## Raw outputs

\`\`\`
$(grep -hE '^#' "$work/embree.md" "$work/scaling.md" "$work/threads.md" "$work/peak.md" "$work/povray.md")
\`\`\`

The tab-separated figures behind the plots are in this folder (\`*.tsv\`).
EOF
} > "$data/latest-run.md"

# The page with the lines between the markers replaced by the new section.
awk -v section="$work/section.md" -v begin="$begin" -v end="$end" '
  $0 == begin { print; while ((getline line < section) > 0) print line; skipping = 1; next }
  $0 == end { skipping = 0 }
  !skipping { print }' "$page" > "$work/page.md"
cp "$work/page.md" "$page"
if [ $quick -eq 1 ]; then
  echo "bench/run.sh: --quick: wrote $out (performance.md, images/, performance-data/); docs/ is unchanged" >&2
else
  echo "bench/run.sh: wrote the marked section of $page, $img/perf-*.png, $data/*.tsv, $data/latest-run.md" >&2
fi
