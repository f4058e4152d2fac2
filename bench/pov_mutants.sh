#!/usr/bin/env bash
# Mutated POV-Ray sample scenes through `lucent check` and `lucent render`: each mutant must
# end (within the time limit) with exit status 0, 1, 2 or 3 and, when it is refused, a
# located message; a signal (a crash) or the time limit (a hang) is a finding, kept in the
# output folder with its command. Mutations, chosen with a fixed seed: a line deleted, a line
# repeated, a character deleted, a brace or parenthesis inserted, two lines swapped, the
# file cut short, a number replaced by an extreme one (0, -1, 1e300, 1e-300).
# Not a CI test (it needs povray-examples); run it after changing the importer.
#
#   bash bench/pov_mutants.sh [--lucent PATH] [--examples DIR] [--count N] [--seed S] [--out DIR]
set -uo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
examples=/usr/share/doc/povray/examples
count=400
seed=1
out=$(mktemp -d)
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --examples) examples=$2; shift 2 ;;
    --count) count=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--lucent PATH] [--examples DIR] [--count N] [--seed S] [--out DIR]" >&2; exit 2 ;;
  esac
done
lucent=$(realpath -m "$lucent")
mkdir -p "$out"
[ -x "$lucent" ] || { echo "no lucent at $lucent" >&2; exit 2; }
[ -d "$examples" ] || { echo "no $examples (scripts/install-bench-deps)" >&2; exit 2; }

mapfile -t scenes < <(find "$examples" -name '*.pov' -size -40k | sort)
RANDOM=$seed
crashes=0 hangs=0 unlocated=0 done=0
for ((k = 0; k < count; k++)); do
  src=${scenes[RANDOM % ${#scenes[@]}]}
  dir=$(dirname "$src")
  lines=$(wc -l <"$src")
  [ "$lines" -gt 2 ] || continue
  # The mutant lies beside a copy of the scene's folder, so that its includes resolve and
  # the examples stay untouched.
  copy="$out/tree/${dir#"$examples"/}"
  [ -d "$copy" ] || { mkdir -p "$copy" && cp -r "$dir"/. "$copy"/ 2>/dev/null; }
  dir=$copy
  mutant="$dir/lucent-mutant-$k.pov"
  line=$((RANDOM % lines + 1))
  other=$((RANDOM % lines + 1))
  case $((RANDOM % 7)) in
    0) what="line $line deleted"; sed "${line}d" "$src" >"$mutant" ;;
    1) what="line $line repeated"; sed "${line}p" "$src" >"$mutant" ;;
    2) what="a character of line $line deleted"; sed "${line}s/.//$((RANDOM % 20 + 1))" "$src" >"$mutant" ;;
    3) what="'{' inserted at line $line"; sed "${line}s/^/{ /" "$src" >"$mutant" ;;
    4) what="lines $line and $other swapped"
       awk -v a="$line" -v b="$other" '{l[NR]=$0} END{t=l[a]; l[a]=l[b]; l[b]=t; for(i=1;i<=NR;i++) print l[i]}' "$src" >"$mutant" ;;
    5) what="cut after line $line"; head -n "$line" "$src" >"$mutant" ;;
    6) values=(0 -1 1e300 1e-300); v=${values[RANDOM % 4]}
       what="the numbers of line $line replaced by $v"; sed -E "${line}s/[0-9]+(\.[0-9]+)?/$v/g" "$src" >"$mutant" ;;
  esac
  for cmd in check render; do
    args=("$lucent" "$cmd" "$mutant")
    [ "$cmd" = render ] && args+=(-w 32 -h 24 -t 1 -q -o "$out/mutant.ppm")
    (cd "$dir" && timeout 60 "${args[@]}") >"$out/stdout" 2>"$out/stderr"
    status=$?
    if [ $status -eq 124 ]; then
      hangs=$((hangs + 1)); cp "$mutant" "$out/hang-$k.pov"
      echo "HANG ($cmd): ${src#"$examples"/}, $what: $out/hang-$k.pov"
    elif [ $status -gt 3 ]; then
      crashes=$((crashes + 1)); cp "$mutant" "$out/crash-$k.pov"; cp "$out/stderr" "$out/crash-$k.err"
      echo "CRASH ($cmd, status $status): ${src#"$examples"/}, $what: $out/crash-$k.pov"
    elif [ $status -eq 2 ] && ! grep -qE ':[0-9]+:[0-9]+: error: |: error: ' "$out/stderr"; then
      unlocated=$((unlocated + 1)); cp "$mutant" "$out/unlocated-$k.pov"
      echo "UNLOCATED ($cmd): ${src#"$examples"/}, $what: $(head -2 "$out/stderr")"
    fi
    [ $status -ne 0 ] && break  # render only what check accepts
  done
  rm -f "$mutant"
  done=$((done + 1))
done
echo "pov_mutants: $done mutants of ${#scenes[@]} sample scenes (seed $seed): $crashes crashed, $hangs hung, $unlocated refused without a place"
[ $((crashes + hangs + unlocated)) -eq 0 ]
