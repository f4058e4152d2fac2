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
#                                [--size WxH] [--bits 8|16] [--out DIR] [--repeat-below S]
#                                [--ref-samples N] [--pov-ref FLAGS]
#                                [--setting 'FAMILY|LABEL|ARGS']... [--plot-only] SCENE.xml...
#
# --plot-only redraws the plots and the summary from the existing CSV without rendering.
# --size renders every scene (references included) at W x H instead of its own size.
# --bits: what each timed run writes: 8, an 8-bit sRGB PNG from both renderers (what users
# write; Lucent's built-in writer, POV-Ray's +FN with its sRGB file gamma), or 16 (the
# default), Lucent a 16-bit TIFF and POV-Ray a 16-bit linear PNG. The references are 16-bit.
# --setting adds a Lucent setting to the sweep (see lucentSettings below for the form).
#
# Writes DIR/speed-vs-error.csv (one row per run), DIR/images/speed-vs-error.png and
# -cpu.png (log-log, one panel per scene), DIR/speed-vs-error-data/summary.md (who dominates
# whom) and DIR/speed-vs-error-data/targets.tsv (the two conditions of the CPU-time target,
# per scene); DIR is docs unless --out says otherwise. Keeps the images in
# $LUCENT_SPEED_KEEP if that is set. Needs lucent, povray, oiiotool, gnuplot.
#
# The error: RMSE over the R, G, B values of all pixels, both images clamped to [0, 1] (what
# POV-Ray's PNG can hold) and then sRGB-encoded, i.e. measured on the values a viewer
# sees; the linear-value RMSE is in the CSV too. Each run is timed as a user would time it:
# the whole process, parsing and file output included. Runs shorter than S seconds (5 unless
# --repeat-below says otherwise; 0: never) are repeated once and the faster one is kept (the
# machine is shared; the faster run is the less disturbed).
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
threads=2
quick=0
plotOnly=0
builtFrom=""
size=""
bits=16
out=docs
repeatBelow=5
refSamples=""
povRef=""
extraSettings=()
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --built-from) builtFrom=$2; shift 2 ;;
    --plot-only) plotOnly=1; shift ;;
    --size) size=$2; shift 2 ;;
    --bits) bits=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --repeat-below) repeatBelow=$2; shift 2 ;;
    --ref-samples) refSamples=$2; shift 2 ;;
    --pov-ref) povRef=$2; shift 2 ;;
    --setting) extraSettings+=("$2"); shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || { echo "usage: $0 [--lucent PATH] [--threads N] [--quick] SCENE.xml..." >&2; exit 1; }
lucent=$(realpath -m "$lucent")
if [ -n "$size" ] && ! [[ $size =~ ^[0-9]+x[0-9]+$ ]]; then
  echo "speed_vs_error: --size takes WxH, not $size" >&2; exit 2
fi
case "$bits" in 8|16) ;; *) echo "speed_vs_error: --bits takes 8 or 16, not $bits" >&2; exit 2 ;; esac

csv=$out/speed-vs-error.csv
plot=$out/images/speed-vs-error.png
data=$out/speed-vs-error-data
mkdir -p "$out/images" "$data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Sampling levels. Lucent: a list of settings "FAMILY|LABEL|ARGS": FAMILY names the series
# in the plots and the summary (a new kind of sampling is a new family), LABEL is the CSV's
# `setting`, and ARGS are words given to `lucent render` (-s N: samples per pixel) except
# those of the form @NAME=VALUE, which set the attribute NAME of the scene's <render>
# element (a scene's own value is replaced). Fixed: N samples per pixel, adaptive off.
# Adaptive (@adaptive=T): a pixel whose centre differs from a neighbour's by more than T,
# largest linear channel, is refined in stages of 6, 12, 24, ... samples until they agree
# within T or all N are taken. Corners (@adaptive-mode=corners): POV-Ray's method 2 with
# shared pixel corners, threshold and depth as +A and +R. More settings come from --setting.
# POV-Ray: -A, then method 1 (+AM1: centre, then an R x R grid where the centre differs
# from the left or upper neighbour by the threshold) and method 2 (+AM2: recursive corner
# subdivision to depth R), with jitter at its default (on), as POV-Ray users render.
# Threshold 0 supersamples every pixel.
if [ $quick -eq 1 ]; then
  lucentSettings=("fixed|1 spp|-s 1" "fixed|4 spp|-s 4"
    "adaptive|adaptive 4 spp threshold 0.05|-s 4 @adaptive=0.05"
    "corners|corners threshold 0.1 depth 3|@samples=1 @adaptive=0.1 @adaptive-mode=corners @adaptive-depth=3")
  povLevels=("-A" "+AM1 +A0.3 +R2")
  : "${refSamples:=16}" "${povRef:=+AM1 +A0.0 +R4}"
else
  lucentSettings=()
  for n in 1 2 4 8 16 32 64; do lucentSettings+=("fixed|$n spp|-s $n"); done
  for a in 16:0.3 16:0.1 16:0.03 64:0.03 64:0.01; do
    lucentSettings+=("adaptive|adaptive ${a%%:*} spp threshold ${a##*:}|-s ${a%%:*} @adaptive=${a##*:}")
  done
  # Corner sampling (POV-Ray's +AM2 without jitter; THRESHOLD:DEPTH).
  for c in 0.3:3 0.1:3 0.1:4 0.03:4 0.01:5; do
    lucentSettings+=("corners|corners threshold ${c%%:*} depth ${c##*:}|@samples=1 @adaptive=${c%%:*} @adaptive-mode=corners @adaptive-depth=${c##*:}")
  done
  povLevels=("-A"
    "+AM1 +A0.3 +R3" "+AM1 +A0.1 +R3" "+AM1 +A0.0 +R2" "+AM1 +A0.0 +R3" "+AM1 +A0.0 +R4"
    "+AM2 +A0.3 +R3" "+AM2 +A0.1 +R3" "+AM2 +A0.1 +R4" "+AM2 +A0.03 +R4")
  # The highest setting: +R9 is POV-Ray's largest depth; with method 1 and threshold 0 it
  # traces a 9 x 9 grid plus the centre in every pixel, jittered (82 samples). Method 2 at
  # that depth would trace up to 257 x 257 corners per pixel, beyond any practical time.
  : "${refSamples:=256}" "${povRef:=+AM1 +A0.0 +R9}"
fi
lucentSettings+=("${extraSettings[@]}")
for setting in "${lucentSettings[@]}"; do
  [[ $setting == *"|"*"|"* ]] || { echo "speed_vs_error: a setting reads FAMILY|LABEL|ARGS, not '$setting'" >&2; exit 2; }
done

load() { cut -d' ' -f1 /proc/loadavg; }

# The scene with its <render> element given adaptive="0" (fixed sampling: a scene may set
# its own adaptive threshold), written into the work folder; relative src="..." of the
# top-level file are made absolute and --allow-path lets it read its own folder.
sceneCopy() {  # scene out scene-folder
  local dir=$3
  sed -E -e '/<render[ >]/ s/ adaptive="[^"]*"//' -e 's/<render([ >\/])/<render adaptive="0"\1/' \
    -e "s#src=\"([^/\"][^\"]*)\"#src=\"$dir/\1\"#g" "$1" > "$2"
}
# A copy of `scene` with the attribute NAME of its <render> element set to VALUE.
withRenderAttribute() {  # scene name value out
  sed -E -e "/<render[ >]/ s/ $2=\"[^\"]*\"//" -e "s/<render([ >\/])/<render $2=\"$3\"\1/" "$1" > "$4"
}
sizeArgs=()
[ -n "$size" ] && sizeArgs=(-w "${size%x*}" -h "${size#*x}")

# Each run is timed by /usr/bin/time: wall seconds and CPU seconds (user + system, all
# threads), the latter far less disturbed by other work on a shared machine.
timed() {  # log command...
  local log=$1; shift
  /usr/bin/time -o "$work/time.txt" -f '%e %U %S' "$@" > "$log" 2>&1 || { tail -20 "$log" >&2; exit 3; }
  awk '{ printf "%.2f %.2f", $1, $2 + $3 }' "$work/time.txt"
}

# Lucent's render of `scene` (a copy from sceneCopy) into `out` (its extension decides the
# format); prints "wall cpu render" (render: the renderer's own wall time for the image,
# from --stats).
lucentRun() {  # scene out scene-folder render-args...
  local t render scene=$1 out=$2 dir=$3
  shift 3
  t=$(timed "$work/lucent.log" "$lucent" render "$scene" -o "$out" "$@" "${sizeArgs[@]}" \
    -t "$threads" -q --stats --allow-path "$dir")
  render=$(sed -nE 's/^time: +([0-9.]+).*/\1/p' "$work/lucent.log")
  echo "$t $render"
}

# POV-Ray's render of `pov` into a PNG: 16-bit linear, or with bits 8 an 8-bit sRGB one;
# prints "wall cpu render" (render: its own "Trace Time" from its statistics).
povRun() {  # pov out width height "flags" bits
  local t render format="+FN16 File_Gamma=1.0"
  [ "$6" = 8 ] && format="+FN"
  # shellcheck disable=SC2086
  t=$(cd "$(dirname "$1")" && timed "$work/pov.log" povray +I"$1" +O"$2" +W"$3" +H"$4" -D -V -GR \
    $format +WT"$threads" $5)
  render=$(sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$work/pov.log")
  echo "$t $render"
}

# Runs a timer function (whose second argument is its output image); repeats it once when
# it took less than 5 s and keeps the faster run.
best() {
  local first second out=$3
  first=$("$@")
  awk -v w="${first%% *}" -v s="$repeatBelow" 'BEGIN { exit !(w < s) }' || { echo "$first"; return; }
  cp "$out" "$work/first.${out##*.}"
  second=$("$@")
  if awk -v a="${first%% *}" -v b="${second%% *}" 'BEGIN { exit !(a <= b) }'; then
    cp "$work/first.${out##*.}" "$out"; echo "$first"
  else
    echo "$second"
  fi
}

# RMSE of an image against the reference, on sRGB-encoded and on linear values. At 16 bits
# Lucent writes TIFF (sRGB-encoded, deflate) and POV-Ray PNG (linear, deflate): two outputs
# of the same precision and about the same cost; at 8 bits both write sRGB-encoded PNG.
# Every image is brought to clamped linear RGB and to sRGB floats; `encoding` says what the
# file holds (srgb or linear).
prepared() {  # image out-prefix encoding
  if [ "$3" = srgb ]; then
    oiiotool "$1" --ch R,G,B -d float -o "$2-srgb.exr"
    oiiotool "$2-srgb.exr" --colorconvert sRGB linear --clamp:min=0:max=1 -d float -o "$2-lin.exr"
  else
    oiiotool "$1" --ch R,G,B --clamp:min=0:max=1 -d float -o "$2-lin.exr"
    oiiotool "$2-lin.exr" --colorconvert linear sRGB -d float -o "$2-srgb.exr"
  fi
}
rmse() {  # ref-prefix image encoding
  prepared "$2" "$work/cur" "$3"
  rmseOfPrepared "$1"
}
# The same for the image last prepared by rmse, against another reference.
rmseOfPrepared() {  # ref-prefix
  local s l
  # (--diff exits with a failure status whenever the images differ at all)
  s=$({ oiiotool "$1-srgb.exr" "$work/cur-srgb.exr" --diff 2>&1 || true; } | awk '/RMS error/ {print $4}')
  l=$({ oiiotool "$1-lin.exr" "$work/cur-lin.exr" --diff 2>&1 || true; } | awk '/RMS error/ {print $4}')
  echo "$s $l"
}

host="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads"
if [ $plotOnly -eq 0 ]; then
echo "scene,renderer,setting,samples,wall_s,cpu_s,render_s,rmse_srgb,rmse_linear,rmse_srgb_own_ref,load1,family" > "$csv"
: > "$data/summary.md"
: > "$work/floors.txt"
if [ "$bits" = 8 ]; then lext=png povEnc=srgb; else lext=tif povEnc=linear; fi

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .xml)
  echo "speed_vs_error: $name" >&2
  pov="$work/$name.pov"

  dir=$(dirname "$(realpath "$scene")")
  # Every variant is made from one snapshot, so an edit of the scene during the run cannot
  # mix two versions.
  sceneCopy "$scene" "$work/fixed.xml" "$dir"
  "$lucent" export-pov "$work/fixed.xml" -o "$pov" --allow-path "$dir" > "$work/export.log" 2>&1 ||
    { cat "$work/export.log" >&2; exit 3; }
  # The image size: --size, else the <render> element's, else the contract's defaults.
  tag=$(grep -m1 -oE '<render[^>]*>' "$work/fixed.xml" || true)
  width=$(sed -nE 's/.*[ \t]width="([0-9]+)".*/\1/p' <<< "$tag"); width=${width:-640}
  height=$(sed -nE 's/.*[ \t]height="([0-9]+)".*/\1/p' <<< "$tag"); height=${height:-480}
  if [ -n "$size" ]; then width=${size%x*}; height=${size#*x}; fi

  # The references: Lucent at refSamples, POV-Ray at its highest setting, both 16-bit.
  l=$(load); read -r w c r < <(lucentRun "$work/fixed.xml" "$work/ref.tif" "$dir" -s "$refSamples")
  prepared "$work/ref.tif" "$work/ref" srgb
  echo "$name,lucent,reference $refSamples spp,$refSamples,$w,$c,$r,0,0,0,$l,reference" >> "$csv"
  l=$(load); read -r w c r < <(povRun "$pov" "$work/povref.png" "$width" "$height" "$povRef" 16)
  prepared "$work/povref.png" "$work/povref" linear
  read -r s lin < <(rmse "$work/ref" "$work/povref.png" linear)
  echo "$name,povray,reference $povRef,,$w,$c,$r,$s,$lin,0,$l,reference" >> "$csv"
  # The error an 8-bit file adds by itself: the reference rounded to 8 bits against itself.
  if [ "$bits" = 8 ]; then
    oiiotool "$work/ref-srgb.exr" -d uint8 -o "$work/ref8.png"
    read -r s _ < <(rmse "$work/ref" "$work/ref8.png" srgb)
    echo "$name $s" >> "$work/floors.txt"
  fi
  [ -n "${LUCENT_SPEED_KEEP:-}" ] && mkdir -p "$LUCENT_SPEED_KEEP" &&
    cp "$work/ref.tif" "$LUCENT_SPEED_KEEP/$name-lucent-ref.tif" &&
    cp "$work/povref.png" "$LUCENT_SPEED_KEEP/$name-povray-ref.png"

  for setting in "${lucentSettings[@]}"; do
    family=${setting%%|*}; rest=${setting#*|}; label=${rest%%|*}; words=${rest#*|}
    cp "$work/fixed.xml" "$work/variant.xml"
    args=() samples=""
    read -ra tokens <<< "$words"
    for ((i = 0; i < ${#tokens[@]}; i++)); do
      tok=${tokens[i]}
      if [[ $tok == @*=* ]]; then
        kv=${tok#@}
        withRenderAttribute "$work/variant.xml" "${kv%%=*}" "${kv#*=}" "$work/variant2.xml"
        mv "$work/variant2.xml" "$work/variant.xml"
      else
        args+=("$tok")
        if [ "$tok" = -s ] || [ "$tok" = --samples ]; then samples=${tokens[i + 1]:-}; fi
      fi
    done
    l=$(load); read -r w c r < <(best lucentRun "$work/variant.xml" "$work/img.$lext" "$dir" "${args[@]}")
    read -r s lin < <(rmse "$work/ref" "$work/img.$lext" srgb)
    echo "$name,lucent,$label,$samples,$w,$c,$r,$s,$lin,$s,$l,$family" >> "$csv"
    [ -n "${LUCENT_SPEED_KEEP:-}" ] && [ "$family" = fixed ] &&
      cp "$work/img.$lext" "$LUCENT_SPEED_KEEP/$name-lucent-$samples.$lext"
  done
  for level in "${povLevels[@]}"; do
    l=$(load); read -r w c r < <(best povRun "$pov" "$work/img.png" "$width" "$height" "$level" "$bits")
    read -r s lin < <(rmse "$work/ref" "$work/img.png" "$povEnc")
    read -r so _ < <(rmseOfPrepared "$work/povref")
    case "$level" in *AM2*) family=AM2 ;; *) family=AM1 ;; esac
    echo "$name,povray,$level,,$w,$c,$r,$s,$lin,$so,$l,$family" >> "$csv"
    [ -n "${LUCENT_SPEED_KEEP:-}" ] && cp "$work/img.png" "$LUCENT_SPEED_KEEP/$name-povray-${level// /}.png"
  done
done
[ -n "$builtFrom" ] || builtFrom="the working tree at commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
sizeText="each scene at its own size"
[ -n "$size" ] && sizeText="every scene at ${size/x/×}"
{
  echo -n "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $host, $threads threads for each renderer, $sizeText, "
  if [ "$bits" = 8 ]; then
    echo -n "each timed run writing an 8-bit sRGB PNG (the error that rounding to 8 bits adds by itself, the reference against itself rounded: $(awk '{ printf "%s%s %s", (NR > 1 ? ", " : ""), $1, $2 }' "$work/floors.txt"))"
  else
    echo -n "each timed run writing a 16-bit file"
  fi
  echo "; Lucent built from $builtFrom; POV-Ray $(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9.]*[0-9]).*/\1/p' | head -1). The 1-minute load average before the runs went from $(tail -n +2 "$csv" | cut -d, -f11 | sort -g | head -1) to $(tail -n +2 "$csv" | cut -d, -f11 | sort -g | tail -1)."
} > "$data/measured.md"
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
# The two conditions of the CPU-time target (docs/performance.md), per scene:
#   beaten: Lucent runs for which some POV-Ray run is both faster (less CPU time) and more
#     accurate (lower sRGB RMSE), both strictly; the condition holds when there are none;
#   unanswered: POV-Ray runs for which no Lucent run is at least as accurate in at most half
#     their CPU time; the condition holds when there are none.
# Writes scene, beaten, Lucent runs, unanswered, POV-Ray runs, tab-separated.
targets() {
  awk -F, '
    NR > 1 && $3 !~ /^reference/ { n[$1]++; r[$1, n[$1]] = $2; c[$1, n[$1]] = $6; e[$1, n[$1]] = $8; if (!($1 in seen)) { seen[$1] = 1; order[++k] = $1 } }
    END {
      print "scene\tlucent_beaten\tlucent_runs\tpovray_unanswered\tpovray_runs"
      for (q = 1; q <= k; q++) {
        sc = order[q]; lb = 0; lt = 0; pu = 0; pt = 0
        for (i = 1; i <= n[sc]; i++) {
          if (r[sc, i] == "lucent") {
            lt++; beaten = 0
            for (j = 1; j <= n[sc]; j++)
              if (r[sc, j] == "povray" && c[sc, j] < c[sc, i] && e[sc, j] < e[sc, i]) beaten = 1
            lb += beaten
          } else {
            pt++; answered = 0
            for (j = 1; j <= n[sc]; j++)
              if (r[sc, j] == "lucent" && e[sc, j] <= e[sc, i] && c[sc, j] <= 0.5 * c[sc, i]) answered = 1
            pu += !answered
          }
        }
        printf "%s\t%d\t%d\t%d\t%d\n", sc, lb, lt, pu, pt
      }
    }' "$csv"
}
targets > "$data/targets.tsv"
{
  cat "$data/measured.md"
  echo
  echo "| scene | POV-Ray runs beaten by a faster (wall; CPU) and more accurate Lucent run | Lucent runs beaten by a faster (wall; CPU) and more accurate POV-Ray run | RMSE of the two references (sRGB) |"
  echo "|---|---|---|---|"
  paste -d'|' <(dominance 5) <(dominance 6) |
    awk -F'|' '{ printf "| %s | %s; %s | %s; %s | %s |\n", $1, $2, $6, $3, $7, $4 }'
  echo
  echo "The CPU-time target (docs/performance.md): no Lucent run beaten by a POV-Ray run both faster and more accurate; for every POV-Ray run, a Lucent run at least as accurate in at most half its CPU time."
  echo
  echo "| scene | Lucent runs beaten by a POV-Ray run faster and more accurate (CPU) | POV-Ray runs without a Lucent run as accurate in half the CPU time |"
  echo "|---|---|---|"
  tail -n +2 "$data/targets.tsv" | awk -F'\t' '{ printf "| %s | %d of %d | %d of %d |\n", $1, $2, $3, $4, $5 }'
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
    first=1
    line="plot "
    colours=('#1f77b4' '#17becf' '#2ca02c' '#9467bd' '#8c564b')
    k=0
    for family in $(tail -n +2 "$csv" | awk -F, -v s="$name" '$1 == s && $2 == "lucent" && $12 != "reference" && !seen[$12]++ { print $12 }'); do
      style="points pt 5 ps 1.2"
      [ "$family" = fixed ] && style="linespoints pt 7"
      [ $first -eq 1 ] || line+=", \\"$'\n'"  "
      line+="\"< awk -F, '$sel && \$2==\\\"lucent\\\" && \$12==\\\"$family\\\"' $csv\" using $2:8 with $style lc rgb '${colours[k % 5]}' title 'Lucent, $family'"
      first=0; k=$((k + 1))
    done
    [ $first -eq 1 ] || line+=", \\"$'\n'"  "
    line+="\"< awk -F, '$sel && \$2==\\\"povray\\\" && \$12==\\\"AM1\\\"' $csv\" using $2:8 with points pt 9 ps 1.3 lc rgb '#d62728' title 'POV-Ray -A and +AM1', \\"$'\n'
    line+="  \"< awk -F, '$sel && \$2==\\\"povray\\\" && \$12==\\\"AM2\\\"' $csv\" using $2:8 with points pt 11 ps 1.3 lc rgb '#ff7f0e' title 'POV-Ray +AM2'"
    echo "$line"
  done
  echo "unset multiplot"
}
plotFile "$plot" 5 "wall time (s), whole process" > "$work/plot.gp"
plotFile "${plot%.png}-cpu.png" 6 "CPU time (s, user + system, all threads), whole process" > "$work/plot-cpu.gp"
gnuplot "$work/plot.gp"
gnuplot "$work/plot-cpu.gp"
echo "speed_vs_error: wrote $csv, $plot, ${plot%.png}-cpu.png, $data/summary.md" >&2
