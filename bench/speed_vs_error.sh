#!/usr/bin/env bash
# Speed against error, Lucent and POV-Ray 3.7, on a few scenes (docs/speed-vs-error.md).
#
# For each scene: a reference image (Lucent at 256 samples per pixel), cross-checked against
# POV-Ray at its highest anti-aliasing setting; then every sampling level of both renderers,
# its whole-process wall time and its RMSE against the reference. All runs of a scene happen
# in one go, with the same thread count for both renderers, and each records the 1-minute
# load average just before it starts (the machine may be shared).
#
#   bash bench/speed_vs_error.sh [--lucent PATH] [--threads N] [--quick] [--built-from TEXT]
#                                [--plot-only] SCENE.xml...
#
# --plot-only redraws the plots from the existing CSV without rendering.
#
# Writes docs/speed-vs-error.csv (one row per run), docs/images/speed-vs-error.png (log-log,
# one panel per scene) and docs/speed-vs-error-data/summary.md (who dominates whom), and keeps
# the images in $LUCENT_SPEED_KEEP if that is set. Needs lucent, povray, oiiotool, gnuplot.
#
# The error: RMSE over the R, G, B values of all pixels, both images clamped to [0, 1] (what
# POV-Ray's 16-bit PNG can hold) and then sRGB-encoded, i.e. measured on the values a viewer
# sees; the linear-value RMSE is in the CSV too. Each run is timed as a user would time it:
# the whole process, parsing and file output included. Runs shorter than 5 s are repeated
# once and the faster one is kept (the machine is shared; the faster run is the less disturbed).
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
threads=2
quick=0
plotOnly=0
builtFrom=""
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --built-from) builtFrom=$2; shift 2 ;;
    --plot-only) plotOnly=1; shift ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || { echo "usage: $0 [--lucent PATH] [--threads N] [--quick] SCENE.xml..." >&2; exit 1; }
lucent=$(realpath -m "$lucent")

csv=docs/speed-vs-error.csv
plot=docs/images/speed-vs-error.png
data=docs/speed-vs-error-data
mkdir -p docs/images "$data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Sampling levels. Lucent: fixed samples per pixel, then adaptive "samples:threshold"
# (a pixel whose centre differs from a neighbour's by more than the threshold, largest
# linear channel, is refined in stages of 6, 12, 24, ... samples until they agree within
# the threshold or all are taken). POV-Ray: -A, then method 1 (+AM1: centre, then an
# R x R grid where the centre differs from the left or upper neighbour by the threshold)
# and method 2 (+AM2: recursive corner subdivision to depth R), with jitter at its default
# (on), as POV-Ray users render. Threshold 0 supersamples every pixel.
if [ $quick -eq 1 ]; then
  lucentSamples=(1 4); lucentAdaptive=(4:0.05)
  povLevels=("-A" "+AM1 +A0.3 +R2"); refSamples=16; povRef="+AM1 +A0.0 +R4"
else
  lucentSamples=(1 2 4 8 16 32 64)
  lucentAdaptive=(16:0.3 16:0.1 16:0.03 64:0.03 64:0.01)
  povLevels=("-A"
    "+AM1 +A0.3 +R3" "+AM1 +A0.1 +R3" "+AM1 +A0.0 +R2" "+AM1 +A0.0 +R3" "+AM1 +A0.0 +R4"
    "+AM2 +A0.3 +R3" "+AM2 +A0.1 +R3" "+AM2 +A0.1 +R4" "+AM2 +A0.03 +R4")
  refSamples=256
  # The highest setting: +R9 is POV-Ray's largest depth; with method 1 and threshold 0 it
  # traces a 9 x 9 grid plus the centre in every pixel, jittered (82 samples). Method 2 at
  # that depth would trace up to 257 x 257 corners per pixel, beyond any practical time.
  povRef="+AM1 +A0.0 +R9"
fi

load() { cut -d' ' -f1 /proc/loadavg; }

# The scene with its <render> element given adaptive="T" (0 for fixed sampling: a scene may
# set its own), written into the work folder; relative src="..." of the top-level file are
# made absolute and --allow-path lets it read its own folder.
sceneCopy() {  # scene threshold out scene-folder
  local dir=$4
  sed -E -e '/<render[ >]/ s/ adaptive="[^"]*"//' -e "s/<render([ >\/])/<render adaptive=\"$2\"\1/" \
    -e "s#src=\"([^/\"][^\"]*)\"#src=\"$dir/\1\"#g" "$1" > "$3"
}

# Each run is timed by /usr/bin/time: wall seconds and CPU seconds (user + system, all
# threads), the latter far less disturbed by other work on a shared machine.
timed() {  # log command...
  local log=$1; shift
  /usr/bin/time -o "$work/time.txt" -f '%e %U %S' "$@" > "$log" 2>&1 || { tail -20 "$log" >&2; exit 3; }
  awk '{ printf "%.2f %.2f", $1, $2 + $3 }' "$work/time.txt"
}

# Lucent's render of `scene` (a copy from sceneCopy) into a 16-bit TIFF; prints
# "wall cpu render" (render: the renderer's own wall time for the image, from --stats).
lucentRun() {  # scene out samples scene-folder
  local t render
  t=$(timed "$work/lucent.log" "$lucent" render "$1" -o "$2" -s "$3" -t "$threads" -q --stats --allow-path "$4")
  render=$(sed -nE 's/^time: +([0-9.]+).*/\1/p' "$work/lucent.log")
  echo "$t $render"
}

# POV-Ray's render of `pov` into a 16-bit linear PNG; prints "wall cpu render" (render: its
# own "Trace Time" from its statistics).
povRun() {  # pov out width height "flags"
  local t render
  # shellcheck disable=SC2086
  t=$(cd "$(dirname "$1")" && timed "$work/pov.log" povray +I"$1" +O"$2" +W"$3" +H"$4" -D -V -GR \
    +FN16 File_Gamma=1.0 +WT"$threads" $5)
  render=$(sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$work/pov.log")
  echo "$t $render"
}

# Runs a timer function (whose second argument is its output image); repeats it once when
# it took less than 5 s and keeps the faster run.
best() {
  local first second out=$3
  first=$("$@")
  awk -v w="${first%% *}" 'BEGIN { exit !(w < 5) }' || { echo "$first"; return; }
  cp "$out" "$work/first.${out##*.}"
  second=$("$@")
  if awk -v a="${first%% *}" -v b="${second%% *}" 'BEGIN { exit !(a <= b) }'; then
    cp "$work/first.${out##*.}" "$out"; echo "$first"
  else
    echo "$second"
  fi
}

# RMSE of an image against the reference, on sRGB-encoded and on linear values. Lucent
# writes 16-bit TIFF (sRGB-encoded, deflate) and POV-Ray 16-bit PNG (linear, deflate): two
# outputs of the same precision and about the same cost; both are brought to clamped linear
# RGB and to sRGB floats.
prepared() {  # image out-prefix
  if [ "${1##*.}" = tif ]; then
    oiiotool "$1" --ch R,G,B -d float -o "$2-srgb.exr"
    oiiotool "$2-srgb.exr" --colorconvert sRGB linear --clamp:min=0:max=1 -d float -o "$2-lin.exr"
  else
    oiiotool "$1" --ch R,G,B --clamp:min=0:max=1 -d float -o "$2-lin.exr"
    oiiotool "$2-lin.exr" --colorconvert linear sRGB -d float -o "$2-srgb.exr"
  fi
}
rmse() {  # ref-prefix image
  prepared "$2" "$work/cur"
  local s l
  # (--diff exits with a failure status whenever the images differ at all)
  s=$({ oiiotool "$1-srgb.exr" "$work/cur-srgb.exr" --diff 2>&1 || true; } | awk '/RMS error/ {print $4}')
  l=$({ oiiotool "$1-lin.exr" "$work/cur-lin.exr" --diff 2>&1 || true; } | awk '/RMS error/ {print $4}')
  echo "$s $l"
}

host="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads"
if [ $plotOnly -eq 0 ]; then
echo "scene,renderer,setting,samples,wall_s,cpu_s,render_s,rmse_srgb,rmse_linear,rmse_srgb_own_ref,load1" > "$csv"
: > "$data/summary.md"

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .xml)
  echo "speed_vs_error: $name" >&2
  pov="$work/$name.pov"

  dir=$(dirname "$(realpath "$scene")")
  # Every variant is made from one snapshot, so an edit of the scene during the run cannot
  # mix two versions.
  sceneCopy "$scene" 0 "$work/fixed.xml" "$dir"
  "$lucent" export-pov "$work/fixed.xml" -o "$pov" --allow-path "$dir" > "$work/export.log" 2>&1 ||
    { cat "$work/export.log" >&2; exit 3; }
  # The image size: the <render> element's, else the contract's defaults.
  tag=$(grep -m1 -oE '<render[^>]*>' "$work/fixed.xml" || true)
  width=$(sed -nE 's/.*[ \t]width="([0-9]+)".*/\1/p' <<< "$tag"); width=${width:-640}
  height=$(sed -nE 's/.*[ \t]height="([0-9]+)".*/\1/p' <<< "$tag"); height=${height:-480}

  # The references: Lucent at refSamples, POV-Ray at its highest setting.
  l=$(load); read -r w c r < <(lucentRun "$work/fixed.xml" "$work/ref.tif" "$refSamples" "$dir")
  prepared "$work/ref.tif" "$work/ref"
  echo "$name,lucent,reference $refSamples spp,$refSamples,$w,$c,$r,0,0,0,$l" >> "$csv"
  l=$(load); read -r w c r < <(povRun "$pov" "$work/povref.png" "$width" "$height" "$povRef")
  prepared "$work/povref.png" "$work/povref"
  read -r s lin < <(rmse "$work/ref" "$work/povref.png")
  echo "$name,povray,reference $povRef,,$w,$c,$r,$s,$lin,0,$l" >> "$csv"
  [ -n "${LUCENT_SPEED_KEEP:-}" ] && mkdir -p "$LUCENT_SPEED_KEEP" &&
    cp "$work/ref.tif" "$LUCENT_SPEED_KEEP/$name-lucent-ref.tif" &&
    cp "$work/povref.png" "$LUCENT_SPEED_KEEP/$name-povray-ref.png"

  for n in "${lucentSamples[@]}"; do
    l=$(load); read -r w c r < <(best lucentRun "$work/fixed.xml" "$work/img.tif" "$n" "$dir")
    read -r s lin < <(rmse "$work/ref" "$work/img.tif")
    echo "$name,lucent,$n spp,$n,$w,$c,$r,$s,$lin,$s,$l" >> "$csv"
    [ -n "${LUCENT_SPEED_KEEP:-}" ] && cp "$work/img.tif" "$LUCENT_SPEED_KEEP/$name-lucent-$n.tif"
  done
  for a in "${lucentAdaptive[@]}"; do
    n=${a%%:*}; t=${a##*:}
    sceneCopy "$work/fixed.xml" "$t" "$work/adaptive.xml" "$dir"
    l=$(load); read -r w c r < <(best lucentRun "$work/adaptive.xml" "$work/img.tif" "$n" "$dir")
    read -r s lin < <(rmse "$work/ref" "$work/img.tif")
    echo "$name,lucent,adaptive $n spp threshold $t,$n,$w,$c,$r,$s,$lin,$s,$l" >> "$csv"
  done
  for level in "${povLevels[@]}"; do
    l=$(load); read -r w c r < <(best povRun "$pov" "$work/img.png" "$width" "$height" "$level")
    read -r s lin < <(rmse "$work/ref" "$work/img.png")
    read -r so _ < <(rmse "$work/povref" "$work/img.png")
    echo "$name,povray,$level,,$w,$c,$r,$s,$lin,$so,$l" >> "$csv"
    [ -n "${LUCENT_SPEED_KEEP:-}" ] && cp "$work/img.png" "$LUCENT_SPEED_KEEP/$name-povray-${level// /}.png"
  done
done
[ -n "$builtFrom" ] || builtFrom="the working tree at commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $host, $threads threads for each renderer; Lucent built from $builtFrom; POV-Ray $(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9.]*[0-9]).*/\1/p' | head -1). The 1-minute load average before the runs went from $(tail -n +2 "$csv" | cut -d, -f11 | sort -g | head -1) to $(tail -n +2 "$csv" | cut -d, -f11 | sort -g | tail -1)." > "$data/measured.md"
fi

# ---- who dominates whom, per scene ----
# A run dominates another when it is at least as fast and at least as accurate. For every
# POV-Ray run: is some Lucent run (references excluded) both faster and more accurate? And
# the converse. Once with wall time, once with CPU time.
dominance() {  # time column
  awk -F, -v tc="$1" '
    NR > 1 && $3 !~ /^reference/ { n[$1]++; r[$1, n[$1]] = $2; w[$1, n[$1]] = $tc; e[$1, n[$1]] = $8; if (!($1 in seen)) { seen[$1] = 1; order[++k] = $1 } }
    NR > 1 && $3 ~ /^reference/ && $2 == "povray" { cross[$1] = $8 }
    END {
      for (q = 1; q <= k; q++) {
        sc = order[q]; pb = 0; pt = 0; lb = 0; lt = 0
        for (i = 1; i <= n[sc]; i++) {
          beaten = 0
          for (j = 1; j <= n[sc]; j++)
            if (r[sc, j] != r[sc, i] && w[sc, j] <= w[sc, i] && e[sc, j] <= e[sc, i]) beaten = 1
          if (r[sc, i] == "povray") { pt++; pb += beaten } else { lt++; lb += beaten }
        }
        printf "%s|%d of %d|%d of %d|%s\n", sc, pb, pt, lb, lt, cross[sc]
      }
    }' "$csv"
}
{
  cat "$data/measured.md"
  echo
  echo "| scene | POV-Ray runs beaten by a faster (wall; CPU) and more accurate Lucent run | Lucent runs beaten by a faster (wall; CPU) and more accurate POV-Ray run | RMSE of the two references (sRGB) |"
  echo "|---|---|---|---|"
  paste -d'|' <(dominance 5) <(dominance 6) |
    awk -F'|' '{ printf "| %s | %s; %s | %s; %s | %s |\n", $1, $2, $6, $3, $7, $4 }'
} > "$data/summary.md"

# ---- the plots: one log-log panel per scene, against wall time and against CPU time ----
count=${#scenes[@]}
cols=$(( count < 3 ? count : 3 )); rows=$(( (count + cols - 1) / cols ))
plotFile() {  # output time-column label
  echo "set terminal pngcairo size $((cols * 520)),$((rows * 420)) font 'sans,10'"
  echo "set output '$1'"
  echo "set datafile separator ','"
  echo "set logscale xy; set grid; set key bottom left font ',8'"
  echo "set xlabel '$3'; set ylabel 'RMSE against the reference (sRGB)'"
  echo "set multiplot layout $rows,$cols title 'Speed against error: Lucent and POV-Ray 3.7 ($host, $threads threads each)'"
  for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .xml)
    sel="\$1==\\\"$name\\\""
    echo "set title '$name'"
    echo "plot \"< awk -F, '$sel && \$2==\\\"lucent\\\" && \$3 ~ /spp\$/ && \$3 !~ /^(reference|adaptive)/' $csv\" using $2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'Lucent, 1-64 spp', \\"
    echo "  \"< awk -F, '$sel && \$3 ~ /^adaptive/' $csv\" using $2:8 with points pt 5 ps 1.2 lc rgb '#17becf' title 'Lucent adaptive', \\"
    echo "  \"< awk -F, '$sel && \$2==\\\"povray\\\" && (\$3 ~ /AM1/ || \$3 == \\\"-A\\\") && \$3 !~ /^reference/' $csv\" using $2:8 with points pt 9 ps 1.3 lc rgb '#d62728' title 'POV-Ray -A and +AM1', \\"
    echo "  \"< awk -F, '$sel && \$2==\\\"povray\\\" && \$3 ~ /AM2/ && \$3 !~ /^reference/' $csv\" using $2:8 with points pt 11 ps 1.3 lc rgb '#ff7f0e' title 'POV-Ray +AM2'"
  done
  echo "unset multiplot"
}
plotFile "$plot" 5 "wall time (s), whole process" > "$work/plot.gp"
plotFile "${plot%.png}-cpu.png" 6 "CPU time (s, user + system, all threads), whole process" > "$work/plot-cpu.gp"
gnuplot "$work/plot.gp"
gnuplot "$work/plot-cpu.gp"
echo "speed_vs_error: wrote $csv, $plot, ${plot%.png}-cpu.png, $data/summary.md" >&2
