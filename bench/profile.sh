#!/usr/bin/env bash
# Where the time of a render goes: a `perf record` of one whole `lucent render` of SCENE
# (the extra words go to `lucent render`: size, samples, threads) and its per-function
# shares of the samples, `perf report --no-children --sort sym` (the time spent in each
# function itself, not in what it calls), as a markdown table of the functions above
# --min percent (default 1), then the shares by library. Template arguments and parameter
# lists are cut from the names.
#
#   bash bench/profile.sh [--lucent PATH] [--min PERCENT] [--top N] [--repeat R]
#                         SCENE.xml [RENDER-ARGS...]
#
# --repeat R records R renders one after the other (more samples of a short render).
#
# Needs perf (Debian's linux-perf) and a kernel.perf_event_paranoid of 2 or less (it samples
# its own process in user space only).
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
min=1
top=25
repeat=1
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --min) min=$2; shift 2 ;;
    --top) top=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { echo "usage: $0 [--lucent PATH] [--min PERCENT] [--top N] SCENE.xml [RENDER-ARGS...]" >&2; exit 2; }
scene=$1; shift
lucent=$(realpath -m "$lucent")
command -v perf > /dev/null || { echo "profile: perf is not installed (apt-get install linux-perf)" >&2; exit 3; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 999 Hz, not a round number, so the sampling does not lock onto a periodic part of the work.
perf record -F 999 -o "$work/perf.data" -- bash -c \
  'for ((i = 0; i < $1; i++)); do "${@:2}" || exit; done' renders "$repeat" \
  "$lucent" render "$scene" -o "$work/out.png" -q "$@" \
  > "$work/record.log" 2>&1 || { tail -5 "$work/record.log" >&2; exit 3; }
samples=$(perf report -i "$work/perf.data" --stdio --no-children --sort sym 2>/dev/null |
  sed -nE 's/^# Samples: ([0-9]+[KM]?).*/\1/p' | head -1)
echo "| share of samples | function |"
echo "|---|---|"
perf report -i "$work/perf.data" --stdio --no-children --sort sym --percent-limit "$min" 2>/dev/null |
  grep -E '^ +[0-9.]+%' | head -n "$top" |
  perl -ne '
    my ($share, $kind, $sym) = /^\s+([0-9.]+%)\s+\[(.)\]\s+(.*)$/ or next;
    # A BVH walk is named after what it walks for (closest, all, any...) and its caller.
    my $walk = "";
    if ($sym =~ /^lucent::Bvh::candidatesWith<(.*)$/) {
      my $inner = $1;
      $walk = " ($1, for $2)" if $inner =~ /lucent::Bvh::(\w+)<.*?((?:lucent::)?\w+::\w+)\(/;
    }
    $sym =~ s/\(anonymous namespace\)/{anon}/g;
    1 while $sym =~ s/<[^<>]*>//g;
    1 while $sym =~ s/\([^()]*\)//g;
    $sym =~ s/\s+const$//;
    $sym .= $walk;
    $sym .= " (kernel)" if $kind eq "k";
    $sym =~ s/\|/\\|/g;
    print "| $share | `$sym` |\n";'
echo
echo
# Where the unnamed addresses and the rest belong: the shares by library.
echo "By library (\`perf report --no-children --sort dso\`): $(perf report -i "$work/perf.data" --stdio --no-children --sort dso 2>/dev/null |
  awk '/^ +[0-9.]+%/ && n < 6 { printf "%s%s %s", (n ? ", " : ""), $2, $1; n++ }')."
runs=""
[ "$repeat" -gt 1 ] && runs=", $repeat runs"
echo "($samples samples of \`lucent render $(basename "$scene") $*\`$runs, \`perf record -F 999\`, \`perf report --no-children --sort sym\`.)"
