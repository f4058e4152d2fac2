#!/usr/bin/env bash
# Measures Lucent's performance on this machine, every target of docs/performance.md in one
# run: installs the benchmark dependencies (Embree 3, gnuplot), builds the benchmarks
# (Release) in build-bench/, runs them (the programs of bench/, then bench/gallery_speed.sh
# on the gallery and on the showcase, bench/speed_vs_error.sh, bench/startup.sh,
# bench/pov_samples_speed.sh on the POV-Ray sample scenes that import), profiles
# with bench/profile.sh the scenes of the targets not met (and always the sphere field and
# the showcase; the ten sample scenes of the lowest ratios), prints the targets table and writes the plots (docs/images/perf-*.png,
# docs/images/speed-vs-error*.png), the raw figures (docs/performance-data/*.tsv,
# docs/speed-vs-error.csv), every table of the run with the programs' raw outputs
# (docs/performance-data/latest-run.md) and the section of docs/performance.md between its
# two "bench/run.sh" markers (the targets, each with this run's figure and the command
# that measured it, and where the time goes). The rest of that page is written by hand and
# is left as it is; dated measurements go to docs/performance-history.md.
#
#   bash bench/run.sh           # the full run (about half an hour on two shared cores)
#   bash bench/run.sh --quick   # small sizes: checks the pipeline; figures not meaningful,
#                               # so it writes into a temporary folder, never into docs/
# LUCENT_BENCH_BUILD names another build folder (default build-bench).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${LUCENT_BENCH_BUILD:-build-bench}

quick=0
[ "${1:-}" = "--quick" ] && quick=1
# The gallery and the showcase: size, repeats (the run of best wall time counts, with its
# CPU time). Speed against error: the three scenes of docs/speed-vs-error.md.
sveScenes=(examples/gallery/glass.xml examples/gallery/mirrors.xml examples/gallery/light-area.xml)
if [ $quick -eq 1 ]; then
  tris=20000; size=256; scaleMax=10000; scaleSize=64; peakSize=128; povRepeat=1
  gallerySize=160x120; galleryReps=1; showSize=320x240; showReps=1; startupRuns=5
  galleryScenes=(examples/gallery/checker.xml examples/gallery/glass.xml examples/gallery/torus.xml)
  sveArgs=(--quick --size 160x120)
  samplesOnly='^advanced/(bwstripe|crater/crater)\.pov$'
else
  tris=1000000; size=1024; scaleMax=1000000; scaleSize=256; peakSize=640; povRepeat=3
  gallerySize=640x480; galleryReps=2; showSize=1280x960; showReps=2; startupRuns=20
  galleryScenes=(examples/gallery/*.xml)
  # The POV-Ray reference is only a cross-check of Lucent's (the errors are against
  # Lucent's 256-sample reference): depth 5 (26 samples a pixel) instead of the script's
  # default 9 (82) keeps the run within half an hour.
  sveArgs=(--size 640x480 --pov-ref "+AM1 +A0.0 +R5")
  samplesOnly=.
fi
# Speed against error: each timed run writes an 8-bit PNG, what users write (and what the
# gallery comparison writes), and runs once: the target is on CPU time, which other work
# on the machine disturbs far less than wall time.
sveArgs+=(--bits 8 --repeat-below 0 --threads "$(nproc)")

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
  data=$out/performance-data img=$out/images sve=$out
  cp "$page" "$out/performance.md"
  page=$out/performance.md
else
  data=docs/performance-data img=docs/images sve=docs
fi
started=$(date +%s)
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
lucent=$build/cli/lucent
echo "bash bench/run.sh: start-up (the 64x48 one-sphere scene)" >&2
bash bench/startup.sh --lucent "$lucent" --runs "$startupRuns" --tsv "$data/startup.tsv" \
  | tee "$work/startup.md" || true
echo "bash bench/run.sh: expansion of 10^6 spheres made by repeats, against the scene written out" >&2
expN=1000; [ $quick -eq 1 ] && expN=100
bash bench/expansion_speed.sh --lucent "$lucent" --n "$expN" --runs 3 --tsv "$data/expansion.tsv" \
  | tee "$work/expansion.md" || true
echo "bash bench/run.sh: the per-frame cost of an animation beyond its render" >&2
bash bench/animation_overhead.sh --lucent "$lucent" | tee "$work/animation.md" || true
if command -v povray >/dev/null; then
  echo "bash bench/run.sh: the gallery against POV-Ray ($gallerySize, one thread)" >&2
  bash bench/gallery_speed.sh --lucent "$lucent" --threads 1 --samples 1 --reps "$galleryReps" \
    --size "$gallerySize" --no-doc --out "$data/gallery-speed" "${galleryScenes[@]}" || true
  echo "bash bench/run.sh: the showcase against POV-Ray ($showSize, one sample, one thread)" >&2
  bash bench/gallery_speed.sh --lucent "$lucent" --threads 1 --samples 1 --reps "$showReps" \
    --size "$showSize" --no-doc --out "$data/showcase-speed" examples/five-shapes.xml || true
  echo "bash bench/run.sh: speed against error" >&2
  bash bench/speed_vs_error.sh --lucent "$lucent" --out "$sve" "${sveArgs[@]}" "${sveScenes[@]}" || true
  # POV-Ray's own sample scenes, those docs/pov-samples.md lists as imported (povray-examples,
  # installed by scripts/install-bench-deps): the benchmark users would pick.
  if [ -d /usr/share/doc/povray/examples ]; then
    echo "bash bench/run.sh: the imported POV-Ray sample scenes against POV-Ray (320x240, one thread)" >&2
    bash bench/pov_samples_speed.sh --lucent "$lucent" --only "$samplesOnly" \
      --tsv "$data/pov-samples-speed.tsv" > "$work/samples.md" || true
  fi
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
tables() { [ -f "$1" ] || return 0; awk '/^\|/ {print; t = 1; next} t {print ""; t = 0} END {if (t) print ""}' "$1"; }
round() { awk -v x="$1" 'BEGIN { if (x == "") print "n/a"; else printf "%.2f", x }'; }
val() { awk -F'\t' -v k="$1" -v t="$2" -v c="$3" '$1==k && $2==t {print $c}' "$data/embree.tsv"; }
threads=$(awk -F'\t' '$1=="primary" && $2!="1" {print $2}' "$data/embree.tsv")
primary1=$(round "$(val primary 1 5)")
shadow1=$(round "$(val shadow 1 5)")
build1=$(round "$(val build 1 3)")
buildN=$(round "$(val build "$threads" 3)")
bytes=$(round "$(val memory all 3)")
growth=$(awk -F'\t' '$1==1000 {a=$3} $1==1000000 {b=$3} END {if (a && b) printf "%.2f", b/a; else print "n/a"}' "$data/scaling.tsv")
growthS=$(awk -F'\t' '$1==1000 {a=$2} $1==1000000 {b=$2} END {if (a && b) printf "%.2f", b/a; else print "n/a"}' "$data/scaling.tsv")
peak=$(grep -E '^\| `lucent render`' "$work/peak.md" | awk -F'|' '{gsub(/[ MB]/,"",$5); print $5}')
peakBase=$(grep -E '^\| `lucent --version`' "$work/peak.md" | awk -F'|' '{gsub(/[ MB]/,"",$5); print $5}')
pov() { awk -F'\t' -v s="$1" -v c="$2" '$1==s {printf "%.2f", $c}' "$data/povray.tsv" 2>/dev/null || true; }
povMesh=$(pov bumpy 8); povMeshCpu=$(pov bumpy 9)
povSpheres=$(pov spheres 8); povSpheresCpu=$(pov spheres 9)
# The gallery: the median CPU ratio and the scene of the lowest; the showcase's CPU ratio.
gtsv=$data/gallery-speed.tsv stsv=$data/showcase-speed.tsv
galleryMedian="" galleryCount=0 slowName="" slowRatio="" showCpu="" showTimes=""
if [ -f "$gtsv" ]; then
  galleryMedian=$(tail -n +2 "$gtsv" | cut -f9 | grep -v n/a | sort -g |
    awk '{ v[NR] = $1 } END { if (NR == 0) print "n/a"; else if (NR % 2) printf "%.2f", v[(NR + 1) / 2]; else printf "%.2f", (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  galleryCount=$(($(wc -l < "$gtsv") - 1))
  slowName=$(tail -n +2 "$gtsv" | awk -F'\t' '$9 != "n/a"' | sort -t$'\t' -k9,9g | head -1 | cut -f1)
  slowRatio=$(tail -n +2 "$gtsv" | awk -F'\t' '$9 != "n/a"' | sort -t$'\t' -k9,9g | head -1 | cut -f9)
fi
if [ -f "$stsv" ]; then
  showCpu=$(awk -F'\t' 'NR == 2 {print $9}' "$stsv")
  showTimes=$(awk -F'\t' 'NR == 2 {printf "CPU: Lucent %s s, POV-Ray %s s", $7, $8}' "$stsv")
fi
# Speed against error: the counts of the two conditions over the three scenes.
ttsv=$sve/speed-vs-error-data/targets.tsv
sveBeaten="" sveUnanswered="" sveBeatenN="" sveUnansweredN=""
if [ -f "$ttsv" ]; then
  sveBeaten=$(tail -n +2 "$ttsv" | awk -F'\t' '{ b += $2; n += $3; d = d sep $1 " " $2 " of " $3; sep = ", " } END { if (NR) printf "%d of %d Lucent runs beaten (%s)", b, n, d }')
  sveUnanswered=$(tail -n +2 "$ttsv" | awk -F'\t' '{ b += $4; n += $5; d = d sep $1 " " $4 " of " $5; sep = ", " } END { if (NR) printf "%d of %d POV-Ray runs without such a Lucent run (%s)", b, n, d }')
  sveBeatenN=$(tail -n +2 "$ttsv" | awk -F'\t' '{ b += $2 } END { if (NR) print b }')
  sveUnansweredN=$(tail -n +2 "$ttsv" | awk -F'\t' '{ b += $4 } END { if (NR) print b }')
fi
# The sample scenes: the median CPU ratio, the count slower than POV-Ray, the lowest.
stsvS=$data/pov-samples-speed.tsv
samplesMedian="" samplesCount=0 samplesSlower="" samplesLow="" samplesLowName=""
if [ -f "$stsvS" ] && [ "$(wc -l < "$stsvS")" -gt 1 ]; then
  tail -n +2 "$stsvS" | sort -t$'\t' -k4,4g > "$work/samples-sorted.tsv"
  samplesCount=$(wc -l < "$work/samples-sorted.tsv")
  samplesMedian=$(cut -f4 "$work/samples-sorted.tsv" |
    awk '{ v[NR] = $1 } END { if (NR % 2) printf "%.2f", v[(NR + 1) / 2]; else printf "%.2f", (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  samplesSlower=$(awk -F'\t' '$4 < 1' "$work/samples-sorted.tsv" | wc -l)
  samplesLow=$(head -1 "$work/samples-sorted.tsv" | cut -f4)
  samplesLowName=$(head -1 "$work/samples-sorted.tsv" | cut -f1)
fi
startMs=$(awk -F'\t' '$1 == "render" {print $2}' "$data/startup.tsv" 2>/dev/null || true)
expWall=$(awk -F'\t' '$1 == "repeats" {print $2}' "$data/expansion.tsv" 2>/dev/null || true)
expCpu=$(awk -F'\t' '$1 == "repeats" {print $3}' "$data/expansion.tsv" 2>/dev/null || true)
expMem=$(awk -F'\t' '$1 == "repeats" {r = $4} $1 == "literal" {l = $4} END { if (l > 0) printf "%.2f", r / l }' "$data/expansion.tsv" 2>/dev/null || true)
expMemAbs=$(awk -F'\t' '$1 == "repeats" {r = $4} $1 == "literal" {l = $4} END { if (l > 0) printf "%.0f MB against %.0f MB", r, l }' "$data/expansion.tsv" 2>/dev/null || true)
met() { awk -v x="$1" -v op="$2" -v y="$3" 'BEGIN { if (x == "" || x == "n/a") print "not measured";
  else if ((op == ">=" && x + 0 >= y + 0) || (op == "<=" && x + 0 <= y + 0) || (op == "<" && x + 0 < y + 0)) print "met";
  else print "**not met**" }'; }
# A target with a first bar: met, first bar met, or not met.
bar() { awk -v x="$1" -v y="$2" -v f="$3" 'BEGIN { if (x == "" || x == "n/a") print "not measured";
  else if (x + 0 >= y + 0) print "met"; else if (x + 0 >= f + 0) print "**not met** (first bar met)"; else print "**not met**" }'; }

B=$build
vsCmd="\`$B/bench/vs_povray $B/cli/lucent WORK --triangles $tris --size $peakSize --repeat $povRepeat\`"
embreeCmd="\`$B/bench/mesh_embree --triangles $tris --size $size\`"
galleryCmd="\`bash bench/gallery_speed.sh --lucent $B/cli/lucent --threads 1 --samples 1 --reps $galleryReps --size $gallerySize\`"
showCmd="\`bash bench/gallery_speed.sh --lucent $B/cli/lucent --threads 1 --samples 1 --reps $showReps --size $showSize examples/five-shapes.xml\`"
sveShown=$(for a in "${sveArgs[@]}"; do [[ $a == *" "* ]] && printf " '%s'" "$a" || printf ' %s' "$a"; done)
sveCmd="\`bash bench/speed_vs_error.sh --lucent $B/cli/lucent$sveShown examples/gallery/{glass,mirrors,light-area}.xml\`"
scaleCmd="\`$B/bench/bvh_scaling --max $scaleMax --size $scaleSize\`"
peakCmd="\`$B/bench/peak_memory $B/cli/lucent WORK --triangles $tris --size $peakSize\`"
startCmd="\`bash bench/startup.sh --lucent $B/cli/lucent --runs $startupRuns\`"
animMs=$(awk -F'|' '/^\| (sphere|mesh)/ { v = $3; gsub(/ /, "", v); if (v + 0 > m) m = v + 0; seen = 1 } END { if (seen) printf "%.1f", m }' "$work/animation.md" 2>/dev/null || true)
animCmd="\`bash bench/animation_overhead.sh --lucent $B/cli/lucent\`"
expCmd="\`bash bench/expansion_speed.sh --lucent $B/cli/lucent --n $expN --runs 3\`"

s_spheres=$(bar "${povSpheresCpu:-n/a}" 3 2)
s_mesh=$(met "${povMeshCpu:-n/a}" ">=" 6)
s_show=$(met "${showCpu:-n/a}" ">=" 3)
s_gmed=$(met "${galleryMedian:-n/a}" ">=" 3)
s_gmin=$(met "${slowRatio:-n/a}" ">=" 1)
s_prim=$(met "$primary1" ">=" 0.9)
s_shad=$(met "$shadow1" ">=" 0.8)
s_sve1=$(met "${sveBeatenN:-n/a}" "<=" 0)
s_sve2=$(met "${sveUnansweredN:-n/a}" "<=" 0)
s_start=$(met "${startMs:-n/a}" "<=" 20)
s_smed=$(met "${samplesMedian:-n/a}" ">=" 3)
s_smin=$(met "${samplesLow:-n/a}" ">=" 1)
samplesCmd="\`bash bench/pov_samples_speed.sh --lucent $B/cli/lucent --tsv OUT\`"
showX=${showSize/x/×} galleryX=${gallerySize/x/×}

{
  echo "| target | measured in this run | measured by | |"
  echo "|---|---|---|---|"
  echo "| 1,000-sphere field, whole process, one thread: CPU time at least 3× better than POV-Ray's (first bar: 2×) | ${povSpheresCpu:-n/a}× CPU (${povSpheres:-n/a}× wall) | $vsCmd | $s_spheres |"
  echo "| 1M-triangle mesh, whole process, one thread: CPU time at least 6× better than POV-Ray's | ${povMeshCpu:-n/a}× CPU (${povMesh:-n/a}× wall) | $vsCmd | $s_mesh |"
  echo "| the showcase at $showX, one sample, one thread each: CPU time at least 3× better than POV-Ray's on its export | ${showCpu:-n/a}× (${showTimes:-n/a}) | $showCmd | $s_show |"
  echo "| the gallery at $galleryX, whole process, one thread: median CPU ratio at least 3× | ${galleryMedian:-n/a}× (median of $galleryCount scenes) | $galleryCmd | $s_gmed |"
  echo "| the gallery at $galleryX: no scene slower than POV-Ray (lowest CPU ratio at least 1×) | ${slowRatio:-n/a}× (${slowName:-n/a}) | $galleryCmd | $s_gmin |"
  echo "| the imported POV-Ray sample scenes at 320×240, one sample, whole process, one thread: median CPU ratio at least 3× | ${samplesMedian:-n/a}× (median of $samplesCount scenes) | $samplesCmd | $s_smed |"
  echo "| the imported POV-Ray sample scenes: none slower than POV-Ray (lowest CPU ratio at least 1×) | ${samplesLow:-n/a}× (${samplesLowName:-n/a}; ${samplesSlower:-n/a} of $samplesCount below 1×) | $samplesCmd | $s_smin |"
  echo "| Embree, one thread, same rays: primary rays at least 0.9× | ${primary1}× | $embreeCmd | $s_prim |"
  echo "| Embree, one thread, same rays: shadow rays at least 0.8× | ${shadow1}× | $embreeCmd | $s_shad |"
  echo "| speed against error, CPU time, on glass, mirrors, light-area: no Lucent run beaten by a POV-Ray run both faster and more accurate | ${sveBeaten:-n/a} | $sveCmd | $s_sve1 |"
  echo "| speed against error, CPU time: for every POV-Ray run, a Lucent run at least as accurate in at most half its CPU time | ${sveUnanswered:-n/a} | $sveCmd | $s_sve2 |"
  echo "| start-up: the 64×48 one-sphere scene renders and writes its PNG in at most 20 ms of CPU | ${startMs:-n/a} ms (mean of $startupRuns processes) | $startCmd | $s_start |"
  echo "| nothing slower: time per ray at 10^6 primitives at most 3× the time at 10^3 (triangles; spheres) | ${growth}×; ${growthS}× | $scaleCmd | $(met "$growth" "<=" 3) (triangles); $(met "$growthS" "<=" 3) (spheres) |"
  echo "| nothing slower: BVH build on one thread at least 3 M triangles/s | ${build1} M/s | $embreeCmd | $(met "$build1" ">=" 3) |"
  echo "| nothing slower: BVH build on ${threads} threads at least 5 M triangles/s (stated for two) | ${buildN} M/s | $embreeCmd | $(met "$buildN" ">=" 5) |"
  echo "| nothing slower: memory per triangle (vertices, indices, BVH) at most 64 bytes | ${bytes} B | $embreeCmd | $(met "$bytes" "<=" 64) |"
  echo "| nothing slower: peak memory rendering the 1M-triangle scene under 150 MB | ${peak:-n/a} MB (the process alone: ${peakBase:-n/a} MB) | $peakCmd | $(met "${peak:-n/a}" "<" 150) |"
  echo "| the language: $((expN * expN)) spheres from nested repeats with expression positions and random radii expand and build (with a 32×24 render) in under 2 s on one core | ${expWall:-n/a} s wall (${expCpu:-n/a} s CPU) | $expCmd | $(met "${expWall:-n/a}" "<" 2) |"
  echo "| the language: peak memory of that scene within 1.5× of the same scene written out | ${expMem:-n/a}× (${expMemAbs:-n/a}) | $expCmd | $(met "${expMem:-n/a}" "<=" 1.5) |"
  echo "| the language: an animation's cost per frame beyond its render, after the first (a 24-frame 64×48 animation; the larger of a one-sphere scene and one with a mesh file and a texture) under 20 ms | ${animMs:-n/a} ms | $animCmd | $(met "${animMs:-n/a}" "<" 20) |"
} > "$work/targets.md"

# ---- where the time goes: a profile of the scene of each target not met (the sphere
# field and the showcase always) ----
profiles=$work/profiles.md
: > "$profiles"
profile() {  # title [profile-options] scene render-args...
  local title=$1 a; shift
  for a in "$@"; do [[ $a == *.xml ]] && { [ -f "$a" ] || return 0; break; }; done
  echo "bash bench/run.sh: profile: $title" >&2
  { echo "### $title"; echo; bash bench/profile.sh --lucent "$lucent" "$@" || echo "(perf failed)"; echo; } >> "$profiles"
}
notMet() { [[ $1 == *"not met"* ]]; }
profile "The 1,000-sphere field, one thread (against POV-Ray: $s_spheres)" --repeat 5 "$work/spheres.xml" -t 1
profile "The showcase at $showX, one sample, one thread (against POV-Ray: $s_show)" examples/five-shapes.xml \
  -w "${showSize%x*}" -h "${showSize#*x}" -s 1 -t 1
if notMet "$s_mesh" || notMet "$s_prim" || notMet "$s_shad"; then
  profile "The 1M-triangle mesh, one thread (against POV-Ray: $s_mesh; against Embree, primary: $s_prim, shadow: $s_shad; the render traces the same mesh)" \
    "$work/bumpy.xml" -t 1
fi
if { notMet "$s_gmed" || notMet "$s_gmin"; } && [ -n "$slowName" ]; then
  profile "The gallery's slowest scene against POV-Ray, $slowName at $galleryX, one thread (${slowRatio}×)" \
    "examples/gallery/$slowName.xml" -w "${gallerySize%x*}" -h "${gallerySize#*x}" -s 1 -t 1
fi
sveSize=${sveArgs[*]}; sveSize=${sveSize#*--size }; sveSize=${sveSize%% *}
if { notMet "$s_sve1" || notMet "$s_sve2"; } && [ -f "$ttsv" ]; then
  for sc in $(tail -n +2 "$ttsv" | awk -F'\t' '$2 > 0 || $4 > 0 {print $1}'); do
    profile "Speed against error: $sc at ${sveSize/x/×}, 16 samples, one thread (a condition not met on this scene)" \
      "examples/gallery/$sc.xml" -w "${sveSize%x*}" -h "${sveSize#*x}" -s 16 -t 1
  done
fi
# The ten sample scenes of the lowest CPU ratios, each rendered as it was timed (320x240, its
# .ini, its middle frame, one sample, one thread), from a copy of its folder.
if [ -f "$work/samples-sorted.tsv" ]; then
  ex=/usr/share/doc/povray/examples
  source bench/pov_samples_lib.sh
  head -10 "$work/samples-sorted.tsv" | while IFS=$'\t' read -r rel lcpu pcpu r; do
    sceneArgs "$ex/$rel"
    rm -rf "$work/scene" && cp -r "$(dirname "$ex/$rel")" "$work/scene"
    profile "Sample scene $rel at 320×240, one sample, one thread (${r}× POV-Ray's CPU time)" \
      "$work/scene/$name" "${args[@]}" "${frameArgs[@]/--frame/--frames}" --allow-write "$work/scene" -s 1 -t 1
  done
fi
elapsed=$(( $(date +%s) - started ))
runTime="$((elapsed / 60)) min $((elapsed % 60)) s"

cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
{
  echo "## Latest figures"
  echo
  echo "Written by \`bash bench/run.sh\` (this section only), one run of $runTime. Measured on ${cpu},"
  echo "$(nproc) hardware threads shared with other work, $(date -u +"%Y-%m-%d %H:%M") UTC, commit ${commit}."
  echo "Every comparison is a ratio of two figures measured side by side in this run; each row"
  echo "names the program that measured it (\`WORK\` is the run's temporary folder). The"
  echo "one-thread comparisons are CPU time, user + system of the whole process, which other"
  echo "work on the machine disturbs far less than wall time. Every table of the run, with the"
  echo "load average at each program's start: [performance-data/latest-run.md](performance-data/latest-run.md);"
  echo "the gallery per scene: [performance-data/gallery-speed.md](performance-data/gallery-speed.md);"
  echo "speed against error: [speed-vs-error-data/summary.md](speed-vs-error-data/summary.md)."
  echo
  cat "$work/targets.md"
  echo
  echo "## Where the time goes"
  echo
  echo "Written by the same run: \`bash bench/profile.sh SCENE ARGS\` (a \`perf record\` of one"
  echo "whole \`lucent render\`, then \`perf report --no-children --sort sym\`: each function's own"
  echo "share of the samples) for the scene of each target not met, and always for the sphere"
  echo "field and the showcase."
  echo
  cat "$profiles"
} > "$work/section.md"

{
  echo "# Latest full run of bench/run.sh"
  echo
  echo "Written by \`bash bench/run.sh\` (the whole file); its targets are summed up in"
  echo "[docs/performance.md](../performance.md). Measured on ${cpu}, $(nproc) hardware threads,"
  echo "$(date -u +"%Y-%m-%d %H:%M") UTC, commit ${commit}, one run of $runTime; each program prints the"
  echo "load average at its start (raw outputs at the end). Every time is the best of three runs"
  echo "(${povRepeat} for POV-Ray against the sphere field and the mesh; ${galleryReps} for the gallery;"
  echo "${showReps} for the showcase; one for speed against error; for Lucent against Embree, five"
  echo "passes over the rays and three builds, Lucent's and Embree's in turn, so that a slow spell"
  echo "of the machine falls on both). A high load lowers every figure, Lucent's and Embree's alike,"
  echo "which is why the comparisons are ratios measured in the same run on the same rays; the"
  echo "one-thread figures of \`bvh_scaling\` are CPU time."
  echo
  echo "## Targets"
  echo
  cat "$work/targets.md"
  echo
  echo "## Lucent and Embree 3 (${tris} triangles, ${size}×${size} camera rays)"
  echo
  tables "$work/embree.md"
  grep -E '^agreement' "$work/embree.md" || true
  echo
  echo "## Time per ray as the primitive count grows (${scaleSize}×${scaleSize} rays, one thread)"
  echo
  tables "$work/scaling.md"
  echo "## Thread scaling (${tris} triangles)"
  echo
  tables "$work/threads.md"
  echo "## Peak memory of a whole render (${peakSize}×${peakSize})"
  echo
  tables "$work/peak.md"
  echo "## Whole process against POV-Ray (one thread, best of ${povRepeat})"
  echo
  echo '```sh'
  echo "$B/bench/vs_povray $B/cli/lucent /tmp/work --triangles ${tris} --size ${peakSize} --repeat ${povRepeat}"
  echo '```'
  echo
  tables "$work/povray.md"
  echo "## The showcase against POV-Ray ($showX, one sample, one thread)"
  echo
  cat "$data/showcase-speed.md" 2>/dev/null || echo "(not measured)"
  echo
  echo "## The gallery against POV-Ray ($galleryX, one thread)"
  echo
  cat "$data/gallery-speed.md" 2>/dev/null || echo "(not measured)"
  echo
  echo "## Speed against error"
  echo
  cat "$sve/speed-vs-error-data/summary.md" 2>/dev/null || echo "(not measured)"
  echo
  echo "## The imported POV-Ray sample scenes against POV-Ray (320×240, one sample, one thread)"
  echo
  cat "$work/samples.md" 2>/dev/null || echo "(not measured)"
  echo
  echo "Every scene: [pov-samples-speed.tsv](pov-samples-speed.tsv)."
  echo
  echo "## Start-up"
  echo
  tables "$work/startup.md"
  echo "## Expansion of a scene made by repeats"
  echo
  tables "$work/expansion.md"
  echo "## The cost of an animation's frames"
  echo
  tables "$work/animation.md"
  echo "## Raw outputs"
  echo
  echo '```'
  grep -hE '^#' "$work/embree.md" "$work/scaling.md" "$work/threads.md" "$work/peak.md" \
    "$work/povray.md" "$work/startup.md" 2>/dev/null || true
  echo '```'
  echo
  echo "The tab-separated figures behind the plots are in this folder (\`*.tsv\`)."
} > "$data/latest-run.md"

# The page with the lines between the markers replaced by the new section.
awk -v section="$work/section.md" -v begin="$begin" -v end="$end" '
  $0 == begin { print; while ((getline line < section) > 0) print line; skipping = 1; next }
  $0 == end { skipping = 0 }
  !skipping { print }' "$page" > "$work/page.md"
cp "$work/page.md" "$page"

echo
echo "Targets (bench/run.sh, one run of $runTime):"
cat "$work/targets.md"
if [ $quick -eq 1 ]; then
  echo "bash bench/run.sh: --quick: wrote $out (performance.md, images/, performance-data/, speed-vs-error*); docs/ is unchanged" >&2
else
  echo "bash bench/run.sh: wrote the marked section of $page, $img/perf-*.png, $data/*.tsv, $data/latest-run.md, docs/speed-vs-error*, docs/images/speed-vs-error*.png" >&2
fi
