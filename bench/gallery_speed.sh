#!/usr/bin/env bash
# Lucent against POV-Ray 3.7 over the gallery (docs/performance-history.md, "The gallery
# against POV-Ray"): every examples/gallery/*.xml rendered by `lucent render` and by `povray` on
# its export (`lucent export-pov`) at matched settings: the scene's size and depth, the same
# samples per pixel (1 by default: both trace the pixel centres, the same rays), the same
# thread count, the same kind of file (an 8-bit sRGB PNG, what users write: POV-Ray's +FN
# with its default sRGB file gamma, the export having assumed_gamma 1). Each run is repeated
# and the fastest kept; the 1-minute load average is recorded before each scene.
#
#   bash bench/gallery_speed.sh [--lucent PATH] [--threads N] [--samples N] [--reps N]
#                               [--size WxH] [--out PREFIX] [--no-doc | --doc-only]
#                               [--built-from TEXT] [SCENE.xml...]
# (--doc-only puts the last measured table, docs/performance-data/gallery-speed.md, into
# docs/performance-history.md without measuring.) --size renders every scene at W x H
# instead of its own size (Lucent's -w/-h, POV-Ray's +W/+H); --out P writes the table to P
# with .tsv and .md appended instead of docs/performance-data/gallery-speed.{tsv,md}
# (bench/run.sh uses both options).
#
# Three times per renderer: the whole process as a user waits for it (start-up, parsing,
# building, rendering, writing), its CPU time (user + system, all threads), and the
# renderer's own time for the image alone (Lucent's --stats "time", POV-Ray's "Trace Time").
# Writes docs/performance-data/gallery-speed.tsv and docs/performance-data/gallery-speed.md
# (the table, which docs/performance.md links to), and puts the table into its section of
# docs/performance-history.md, beside the reading of the run (unless --no-doc).
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
threads=2
samples=1
reps=3
doc=1
docOnly=0
builtFrom=""
size=""
prefix=docs/performance-data/gallery-speed
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --samples) samples=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --no-doc) doc=0; shift ;;
    --doc-only) docOnly=1; shift ;;
    --built-from) builtFrom=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --out) prefix=$2; shift 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || scenes=(examples/gallery/*.xml)
lucent=$(realpath -m "$lucent")

mkdir -p "$(dirname "$prefix")"
tsv="$prefix".tsv
md="$prefix".md
sizeArgs=()
if [ -n "$size" ]; then
  [[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "gallery_speed: --size takes WxH, not $size" >&2; exit 2; }
  sizeArgs=(-w "${size%x*}" -h "${size#*x}")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# POV-Ray's sampling for `samples` (as `lucent compare` does it): 1 is -A, the pixel centre;
# more is threshold 0 without jitter, an R x R grid plus the centre, R = round(sqrt(samples)).
if [ "$samples" -le 1 ]; then
  povAA="-A"
else
  grid=$(awk -v s="$samples" 'BEGIN { r = int(sqrt(s) + 0.5); print (r < 2 ? 2 : r) }')
  povAA="+A0.0 -J +AM1 +R$grid"
fi

# "wall cpu render" of the fastest (by wall time) of `reps` runs of a command, timed by
# /usr/bin/time (cpu: user + system seconds of all threads, far less disturbed than wall
# time by other work on a shared machine); $1 names the parser of the renderer's own time.
fastest() {  # parser command...
  local parser=$1; shift
  local best="" t
  for ((i = 0; i < reps; i++)); do
    /usr/bin/time -o "$work/time.txt" -f '%e %U %S' "$@" > "$work/run.log" 2>&1 ||
      { tail -20 "$work/run.log" >&2; return 3; }
    t="$(awk '{ printf "%.2f %.2f", $1, $2 + $3 }' "$work/time.txt") $("$parser" "$work/run.log")"
    if [ -z "$best" ] || awk -v a="${t%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
      best=$t
    fi
  done
  echo "$best"
}
lucentTime() { sed -nE 's/^time: +([0-9.]+).*/\1/p' "$1"; }
povTime() { sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$1"; }

if [ $docOnly -eq 0 ]; then
printf 'scene\twidth\theight\tlucent_wall_s\tpovray_wall_s\twall_ratio\tlucent_cpu_s\tpovray_cpu_s\tcpu_ratio\tlucent_render_s\tpovray_trace_s\trender_ratio\tload1\n' > "$tsv"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .xml)
  dir=$(dirname "$(realpath "$scene")")
  tag=$(grep -m1 -oE '<render[^>]*>' "$scene" || true)
  width=$(sed -nE 's/.*[ \t]width="([0-9]+)".*/\1/p' <<< "$tag"); width=${width:-640}
  height=$(sed -nE 's/.*[ \t]height="([0-9]+)".*/\1/p' <<< "$tag"); height=${height:-480}
  if [ -n "$size" ]; then width=${size%x*}; height=${size#*x}; fi
  if ! "$lucent" export-pov "$scene" -o "$work/$name.pov" > "$work/export.log" 2>&1; then
    echo "gallery_speed: $name: not exportable, skipped: $(grep -m1 error "$work/export.log")" >&2
    continue
  fi
  load=$(cut -d' ' -f1 /proc/loadavg)
  lw="" pw=""
  read -r lw lc lr < <(fastest lucentTime "$lucent" render "$scene" -o "$work/lucent.png" \
    -s "$samples" -t "$threads" "${sizeArgs[@]}" -q --stats)
  # shellcheck disable=SC2086
  read -r pw pc pr < <(cd "$work" && fastest povTime povray +I"$name.pov" +Opov.png +W"$width" \
    +H"$height" -D -V -GR +FN +WT"$threads" $povAA)
  if [ -z "${lw:-}" ] || [ -z "${pw:-}" ]; then
    echo "gallery_speed: $name: a render failed, skipped" >&2
    continue
  fi
  ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }'; }
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$width" "$height" \
    "$lw" "$pw" "$(ratio "$pw" "$lw")" "$lc" "$pc" "$(ratio "$pc" "$lc")" \
    "$lr" "$pr" "$(ratio "$pr" "$lr")" "$load" >> "$tsv"
  echo "gallery_speed: $(tail -1 "$tsv")" >&2
done

# The fixed cost of starting each program: CPU seconds of `--version`, best of reps.
startCpu() {
  local best="" t
  for ((i = 0; i < reps; i++)); do
    /usr/bin/time -o "$work/time.txt" -f '%U %S' "$@" > /dev/null 2>&1 || true
    t=$(awk '{ printf "%.2f", $1 + $2 }' "$work/time.txt")
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  echo "$best"
}
startL=$(startCpu "$lucent" --version)
startP=$(startCpu povray --version)

median() {  # column of the tsv
  tail -n +2 "$tsv" | cut -f"$1" | grep -v n/a | sort -g |
    awk '{ v[NR] = $1 } END { if (NR == 0) print "n/a"; else if (NR % 2) print v[(NR + 1) / 2]; else printf "%.2f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
count=$(($(wc -l < "$tsv") - 1))
loads=$(tail -n +2 "$tsv" | cut -f13 | sort -g | awk 'NR == 1 { lo = $1 } { hi = $1 } END { print lo " to " hi }')
[ -n "$builtFrom" ] || builtFrom="the working tree at commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
{
  echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads, both renderers on $threads threads, $samples sample(s) per pixel (POV-Ray \`$povAA\`), best of $reps runs each; Lucent built from $builtFrom; POV-Ray $(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9.]*[0-9]).*/\1/p' | head -1). The 1-minute load average before each scene was $loads (the machine is shared with other work; 2 would mean both cores already busy)."
  echo
  echo "\`\`\`sh"
  echo "bash bench/gallery_speed.sh --lucent build/cli/lucent --threads $threads --samples $samples --reps $reps${size:+ --size $size}"
  echo "\`\`\`"
  echo
  echo 'Wall: the whole process, as a user waits for it. CPU: user + system seconds of all threads of the whole process. Render: the renderer'\''s own wall time for the image alone (Lucent'\''s `--stats` time, POV-Ray'\''s Trace Time). Each ratio is POV-Ray'\''s time over Lucent'\''s: above 1, Lucent is faster.'
  echo
  echo "Start-up alone (the program loads its libraries, prints its version and exits; CPU seconds, best of $reps): \`lucent --version\` $startL, \`povray --version\` $startP."
  echo
  echo "| scene | size | wall Lucent s | wall POV-Ray s | wall ratio | CPU Lucent s | CPU POV-Ray s | CPU ratio | render Lucent s | trace POV-Ray s | render ratio | load |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  tail -n +2 "$tsv" | awk -F'\t' '{ printf "| %s | %sx%s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13 }'
  echo "| **median of $count** | | $(median 4) | $(median 5) | **$(median 6)** | $(median 7) | $(median 8) | **$(median 9)** | $(median 10) | $(median 11) | **$(median 12)** | |"
} > "$md"
fi

# docs/performance-history.md: the table goes between the markers of the section "The gallery
# against POV-Ray" (the section with its markers is added before "## Raw outputs" the
# first time); the rest of the page, the reading below the table included, is left alone.
if [ $doc -eq 1 ]; then
  page=${LUCENT_PERF_PAGE:-docs/performance-history.md}
  begin='<!-- gallery-speed: begin (bench/gallery_speed.sh writes what is between these markers) -->'
  end='<!-- gallery-speed: end -->'
  if ! grep -qF "$begin" "$page"; then
    awk -v b="$begin" -v e="$end" '
      /^## Raw outputs/ && !done { print "## The gallery against POV-Ray"; print ""; print b; print e; print ""; done = 1 }
      { print }
      END { if (!done) { print ""; print "## The gallery against POV-Ray"; print ""; print b; print e } }' \
      "$page" > "$work/page.md"
    cp "$work/page.md" "$page"
  fi
  awk -v b="$begin" -v e="$end" -v md="$md" '
    $0 == b { print; while ((getline line < md) > 0) print line; skip = 1; next }
    $0 == e { skip = 0 }
    !skip { print }' "$page" > "$work/page.md"
  cp "$work/page.md" "$page"
fi
echo "gallery_speed: wrote $tsv and $md" >&2
