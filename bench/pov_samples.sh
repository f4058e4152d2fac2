#!/usr/bin/env bash
# POV-Ray's own sample scenes as a measurement of the POV-Ray importer: every .pov file of
# Debian's povray-examples (scripts/install-bench-deps installs it) through `lucent check`,
# and each one that imports through `lucent render` and `lucent compare` (POV-Ray on the
# same file), at 320x240, one sample, one thread, with the scene's .ini file where it has
# one (an animation at its middle frame). Writes docs/pov-samples.md: a row per scene
# (imported, refused with the first unsupported feature and its place, crashed, hung), its
# PSNR against POV-Ray, the CPU ratio, and a summary. Scenes below 35 dB take their reason
# from bench/pov_samples_notes.txt ("path/of/scene.pov: why"). Not a CI test.
#
#   bash bench/pov_samples.sh [--lucent PATH] [--examples DIR] [--out FILE] [--only REGEX]
#                             [--update] [--import-only] [--speed-only]
# --update measures only the scenes --only selects and keeps every other row of the page
# already in --out (the summary is computed again over all of them): after a change that
# concerns a few scenes, without the hour of the whole run. --import-only (implies --update)
# measures again only the import against POV-Ray's parse of the imported scenes --only
# selects, keeping every other column: in ten minutes on a machine at rest, which a
# comparison of millisecond parses needs. --speed-only (implies --update) measures again only
# the CPU times of Lucent's and POV-Ray's renders and their ratio.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD

lucent=build/cli/lucent
examples=/usr/share/doc/povray/examples
out=docs/pov-samples.md
only=.
update=0
importOnly=0
speedOnly=0
while [ $# -gt 0 ]; do
  case "$1" in
    --update) update=1; shift ;;
    --import-only) update=1; importOnly=1; shift ;;
    --speed-only) update=1; speedOnly=1; shift ;;
    --lucent) lucent=$2; shift 2 ;;
    --examples) examples=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    *) echo "usage: $0 [--lucent PATH] [--examples DIR] [--out FILE] [--only REGEX] [--update] [--import-only] [--speed-only]" >&2; exit 2 ;;
  esac
done
lucent=$(realpath -m "$lucent")
out=$(realpath -m "$out")
notes=$root/bench/pov_samples_notes.txt
[ -x "$lucent" ] || { echo "no lucent at $lucent (build it first)" >&2; exit 2; }
[ -d "$examples" ] || { echo "no $examples: run scripts/install-bench-deps (povray-examples)" >&2; exit 2; }
command -v povray >/dev/null || { echo "povray is not installed (scripts/install-deps)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rows=$work/rows.tsv  # scene, outcome, detail, psnr, lucent cpu, povray s, ratio, import s, parse s
: >"$rows"
# --update: the rows of the page already written, except those measured again.
if [ $update = 1 ]; then
  [ -f "$out" ] || { echo "--update: no $out to update" >&2; exit 2; }
  # A kept scene's reason for being below 35 dB is read again from the notes.
  sed -n '/^## Every scene/,$p' "$out" | grep '^| ' | tail -n +3 |
    awk -v only="$only" -v keepAll=$((importOnly + speedOnly)) 'FNR == NR { i = index($0, ": "); if (i > 1 && $0 !~ /^#/) note[substr($0, 1, i - 1)] = substr($0, i + 2); next }
    {
      line = $0; gsub(/\\\|/, "\001", line); n = split(line, f, "|");
      for (i = 2; i < n; i++) { gsub(/^ +| +$/, "", f[i]); gsub("\001", "|", f[i]) }
      if (f[2] ~ only && !keepAll) next;
      if (f[3] == "imported" && f[4] != "") f[10] = note[f[2]];
      printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", f[2], f[3], f[10], f[4], f[5], f[6], f[7], f[8], f[9] }' "$notes" - >"$rows"
fi

# The scene's .ini, its first and middle frames, a command timed in CPU seconds.
# shellcheck source=bench/pov_samples_lib.sh
source "$root/bench/pov_samples_lib.sh"

# Importing against POV-Ray's parse, wall time against wall time: lucent check's "read in"
# against POV-Ray's own "Parse Time" of the same frame at 8x8 (both: a scene may build by
# image_width, as the mesh cameras do), no output, neither with its process's start.
# POV-Ray's figure is the difference of two millisecond clock readings, each cut to the
# millisecond: a parse of d ms reads as floor(d) or floor(d)+1 ms, d on average. So each
# figure is a mean over seven runs of the five lowest: a run the machine interrupted (a
# figure several times the others) would otherwise decide it. Each program's runs follow
# one another, after an untimed run of the same command: a run right after the other
# program's, or after the machine idled, reads 1.5 to 2 times slower for both (caches the
# other process or the host emptied; docs/povray-import.md, Speed of importing), and taking
# turns made that the figure of every run.
# Sets importS and parseS (seconds, empty where no run gave a figure).
measureImport() {
  local run wall p povArgs walls=() parses=() importArgs=() skip=0 a
  importS="" parseS=""
  for a in "${args[@]}"; do
    if [ $skip = 1 ]; then skip=0; continue; fi
    case "$a" in -w | -h) skip=1 ;; *) importArgs+=("$a") ;; esac
  done
  importArgs+=(-w 8 -h 8)
  povArgs=(+I"$name" +W8 +H8 -D -F +GS -V)
  [ -n "$ini" ] && povArgs=("$ini" "${povArgs[@]}")
  [ ${#frameArgs[@]} -gt 0 ] && povArgs+=(+SF"$(( $(iniFirst "$ini") + frame - 1 ))" +EF"$(( $(iniFirst "$ini") + frame - 1 ))")
  for run in 0 1 2 3 4 5 6 7; do
    wall=$("$lucent" check --stats "${importArgs[@]}" "${checkFrame[@]}" "$name" 2>/dev/null |
      sed -n 's/^read in: .* s of CPU time, \([0-9.]*\) s of wall time.*/\1/p')
    [ -n "$wall" ] && [ $run -gt 0 ] && walls+=("$wall")
  done
  for run in 0 1 2 3 4 5 6 7; do
    p=$(povray "${povArgs[@]}" 2>&1 | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' | tail -1)
    [ -n "$p" ] && [ $run -gt 0 ] && parses+=("$p")
  done
  importS=$(lowMean "${walls[@]}")
  parseS=$(lowMean "${parses[@]}")
  return 0
}

# The mean of the five lowest of the figures given (of all, when there are fewer); empty for none.
lowMean() {
  [ $# -gt 0 ] || return 0
  printf '%s\n' "$@" | sort -g | head -5 | awk '{ s += $1; n++ } END { printf "%.4f", s / n }'
}

count=0
while IFS= read -r pov; do
  rel=${pov#"$examples"/}
  [[ "$rel" =~ $only ]] || continue
  count=$((count + 1))
  dir=$(dirname "$pov")
  sceneArgs "$pov"
  # In a copy of the scene's folder, where the scene may write (its #fopen ... write, as
  # POV-Ray's own run writes there too): the installed examples stay as they are.
  rm -rf "$work/scene"
  cp -r "$dir" "$work/scene"
  cd "$work/scene"
  args+=(--allow-write "$work/scene")
  if [ $importOnly = 1 ]; then
    # Only the import columns of a scene already measured as imported, the rest kept.
    if awk -F'\t' -v r="$rel" '$1 == r && $2 == "imported" && $4 != "" { found = 1 } END { exit !found }' "$rows"; then
      measureImport
      awk -F'\t' -v OFS='\t' -v r="$rel" -v i="$importS" -v p="$parseS" '$1 == r { $8 = i; $9 = p } { print }' \
        "$rows" >"$rows.new" && mv "$rows.new" "$rows"
      echo "$rel: import $importS s, POV-Ray parse $parseS s" >&2
    fi
    cd "$root"
    continue
  fi
  if [ $speedOnly = 1 ]; then
    # Only the CPU columns of a scene already measured as imported, the rest kept.
    if awk -F'\t' -v r="$rel" '$1 == r && $2 == "imported" && $4 != "" { found = 1 } END { exit !found }' "$rows"; then
      timeRenders
      awk -F'\t' -v OFS='\t' -v r="$rel" -v l="$lucentCpu" -v p="$povCpu" -v q="$ratio" \
        '$1 == r { $5 = l; $6 = p; $7 = q } { print }' "$rows" >"$rows.new" && mv "$rows.new" "$rows"
      echo "$rel: Lucent $lucentCpu s, POV-Ray $povCpu s (CPU), ratio $ratio" >&2
    fi
    cd "$root"
    continue
  fi
  timeout 120 "$lucent" check "${args[@]}" "$name" >/dev/null 2>"$work/check.err"
  status=$?
  if [ $status -eq 124 ]; then
    printf '%s\thung\tcheck did not end in 120 s\t\t\t\t\n' "$rel" >>"$rows"
  elif [ $status -ge 128 ] || { [ $status -ne 0 ] && [ $status -ne 2 ] && [ $status -ne 1 ]; }; then
    printf '%s\tcrashed\tcheck exit status %s\t\t\t\t\n' "$rel" "$status" >>"$rows"
  elif [ $status -ne 0 ]; then
    first=$(grep -m1 ': error: ' "$work/check.err" | sed "s#^$work/scene/##; s#^$examples/##; s#^/usr/share/povray-3.7/include/##")
    printf '%s\trefused\t%s\t\t\t\t\n' "$rel" "${first:-exit status $status}" >>"$rows"
  else
    : >"$work/err"
    timed timeout 600 "$lucent" render "${args[@]}" "${frameArgs[@]/--frame/--frames}" -s 1 -t 1 -q \
      -o "$work/lucent.png" "$name"
    status=$?
    lucentCpu=$cpu
    if [ $status -ne 0 ]; then
      printf '%s\t%s\trender exit status %s\t\t\t\t\n' "$rel" \
        "$([ $status -eq 124 ] && echo hung || echo crashed)" "$status" >>"$rows"
    else
      rm -rf "$work/cmp"
      timeout 1200 "$lucent" compare "${args[@]}" "${frameArgs[@]}" -t 1 -o "$work/cmp" "$name" \
        >/dev/null 2>"$work/cmp.err"
      status=$?
      if [ $status -ne 0 ] || [ ! -f "$work/cmp/report.json" ]; then
        why=$(grep -m1 -iE 'error|failed' "$work/cmp.err" | cut -c1-120)
        printf '%s\timported\tcompare failed: %s\t\t%s\t\t\n' "$rel" "${why:-exit $status}" "$lucentCpu" >>"$rows"
      else
        psnr=$(sed -n 's/^ *"psnr_db": \(.*\),$/\1/p' "$work/cmp/report.json")
        if [ "$psnr" = null ]; then psnr=inf; else psnr=$(printf '%.2f' "$psnr"); fi
        # POV-Ray's CPU time, one thread, as Lucent's (compare times its wall clock, which
        # holds about a second of POV-Ray waiting on its own front end).
        povSeconds="" ratio=""
        timed timeout 1200 povray "${povArgs[@]}" && povSeconds=$cpu
        [ -n "$povSeconds" ] && ratio=$(awk -v p="$povSeconds" -v l="$lucentCpu" 'BEGIN{ if (l > 0) printf "%.2f", p / l; }')
        note=""
        [ -f "$notes" ] && note=$(grep -F "$rel:" "$notes" | head -1 | sed "s#^$rel: *##")
        measureImport
        printf '%s\timported\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$note" "$psnr" "$lucentCpu" \
          "$povSeconds" "$ratio" "$importS" "$parseS" >>"$rows"
      fi
    fi
  fi
  cd "$root"
  echo "$rel: $(tail -1 "$rows" | cut -f2,4,7)" >&2
done < <(find "$examples" -name '*.pov' | sort)
if [ $update = 1 ]; then  # the kept rows and the new ones, in the order of the scenes
  sort -t"$(printf '\t')" -k1,1 "$rows" -o "$rows"
  count=$(wc -l <"$rows")
fi

# The page.
{
  echo "# POV-Ray's sample scenes through Lucent's importer"
  echo
  echo "Written by \`bash bench/pov_samples.sh\` ($(date -u +%Y-%m-%d), $count scenes of"
  echo "Debian's \`povray-examples\`, $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*')): each scene through"
  echo "\`lucent check\`, and each one that imports through \`lucent render\` and \`lucent compare\`"
  echo "(POV-Ray 3.7 on the same file) at 320x240, one sample, one thread, with its \`.ini\`"
  echo "file where it has one (an animation at its middle frame). PSNR is compare's (sRGB"
  echo "values); the CPU ratio is POV-Ray's CPU seconds (user + system of the whole process, one"
  echo "thread, no antialiasing, the same size and frame: parse, render, PNG) over Lucent's for"
  echo "\`lucent render\` (import, render, PNG), one sample, one thread."
  echo
  echo "## Summary"
  echo
  echo "| outcome | scenes |"
  echo "| --- | --- |"
  for o in imported refused crashed hung; do
    echo "| $o | $(awk -F'\t' -v o="$o" '$2 == o' "$rows" | wc -l) |"
  done
  echo
  echo "PSNR of the imported scenes:"
  echo
  awk -F'\t' '$2 == "imported" && $4 != "" {
      if ($4 == "inf" || $4 + 0 >= 50) a++; else if ($4 + 0 >= 40) b++;
      else if ($4 + 0 >= 35) c++; else d++; total++ }
    END { printf "| PSNR | scenes |\n| --- | --- |\n| identical or 50 dB and above | %d |\n", a;
      printf "| 40 to 50 dB | %d |\n| 35 to 40 dB | %d |\n| below 35 dB | %d |\n", b, c, d;
      if (total) printf "\nAt 35 dB or more: %d of %d (%.0f %%).\n", a + b + c, total, 100 * (a + b + c) / total }' "$rows"
  echo
  ratios=$(awk -F'\t' '$2 == "imported" && $7 != "" { print $7 }' "$rows" | sort -g)
  n=$(echo "$ratios" | grep -c . || true)
  if [ "$n" -gt 0 ]; then
    median=$(echo "$ratios" | awk -v n="$n" 'NR == int((n + 1) / 2) { print }')
    echo "Median CPU ratio (POV-Ray / Lucent) over $n compared scenes: **${median}x**."
  fi
  echo
  awk -F'\t' '$2 == "imported" && $8 != "" && $9 != "" { n++; if ($8 + 0 <= $9 + 0) f++ }
    END { if (n) printf "Importing (lucent check'"'"'s \"read in\": reading, evaluating, building and checking the scene) against POV-Ray'"'"'s own parse of the same scene (its Parse Time), wall time at 8x8, of seven runs after an untimed one, each program'"'"'s in a row, the mean of the five lowest (POV-Ray'"'"'s clock counts whole milliseconds, so only a mean tells a parse under one), neither with its process'"'"'s start: Lucent faster or equal for %d of %d scenes.\n\n", f, n }' "$rows"
  echo "Refusals by feature (the first unsupported feature of each refused scene):"
  echo
  echo "| feature | scenes |"
  echo "| --- | --- |"
  awk -F'\t' '$2 == "refused" { d = $3; if (match(d, /\x27[^\x27 ]*\x27/)) f = substr(d, RSTART, RLENGTH);
      else { sub(/^[^ ]* error: /, "", d); f = substr(d, 1, 60) } n[f]++ }
    END { for (f in n) printf "| %s | %d |\n", f, n[f] }' "$rows" | sort -t'|' -k3 -rn
  echo
  echo "Imported scenes below 35 dB, and why (bench/pov_samples_notes.txt):"
  echo
  awk -F'\t' '$2 == "imported" && $4 != "" && $4 != "inf" && $4 + 0 < 35 {
      printf "- %s (%.1f dB): %s\n", $1, $4, ($3 == "" ? "**no reason written yet**" : $3) }' "$rows"
  echo
  echo "## Every scene"
  echo
  echo "| scene | outcome | PSNR (dB) | Lucent CPU (s) | POV-Ray CPU (s) | ratio | import (s) | POV-Ray parse (s) | detail |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  awk -F'\t' '{ d = $3; gsub(/\|/, "\\|", d); printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $4, $5, $6, $7, $8, $9, d }' "$rows"
} >"$out"
echo "wrote $out" >&2
