#!/usr/bin/env bash
# Runs bench/tile_schedule (the simulated efficiency of a distributed render) and plots its
# rows with gnuplot: efficiency against rank count, one line per tile size. Prints the
# program's table; the figure goes to docs/images/distributed-efficiency.png unless --png
# says otherwise. Arguments after the options go to tile_schedule (default: the synthetic
# 3840x2160 map of docs/distributed.md).
#
#   bash bench/tile_schedule.sh                                   # the synthetic figure
#   bash bench/tile_schedule.sh -- costs.txt --threads-per-rank 16  # a recorded trace
#   bash bench/tile_schedule.sh --png /tmp/e.png --tsv /tmp/e.tsv -- --synthetic 1920 1080
# Options: --binary PATH (default build/bench/tile_schedule), --png PATH, --tsv PATH (keep
# the rows), --title TEXT. Needs gnuplot (scripts/install-bench-deps installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
binary=build/bench/tile_schedule
png=docs/images/distributed-efficiency.png
tsv=""
title=""
while [ $# -gt 0 ]; do
  case "$1" in
    --binary) binary=$2; shift 2 ;;
    --png) png=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    --title) title=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "tile_schedule.sh: unknown option '$1' (program arguments go after --)" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] || set -- --synthetic 3840 2160
[ -x "$binary" ] || { echo "tile_schedule.sh: no $binary (cmake --build build --target tile_schedule)" >&2; exit 2; }
command -v gnuplot >/dev/null || { echo "tile_schedule.sh: gnuplot is missing (bash scripts/install-bench-deps)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -n "$tsv" ] || tsv=$work/rows.tsv
"$binary" "$@" --tsv "$tsv" | tee "$work/table.md"
source=$(sed -n 's/^# tile_schedule: //p' "$work/table.md")
[ -n "$title" ] || title="Simulated efficiency of a distributed render"
setup=$(sed -n "s/^# start: //p" "$work/table.md")
network=$(sed -n "s/^# network: //p" "$work/table.md")
tiles=$(grep -v '^#' "$tsv" | cut -f2 | sort -nu | tr '\n' ' ')
# Quotes would end gnuplot's strings.
esc() { printf '%s' "${1//\"/\'}"; }

gnuplot <<GP
set terminal pngcairo size 900,560 font "sans,11"
set output "$png"
set title "$(esc "$title")\n$(esc "$source")\n$(esc "$network")\n$(esc "$setup")" noenhanced font "sans,9"
set datafile separator "\t"
set logscale x 2
set xrange [*:*]
set yrange [0:1.05]
set xlabel "ranks"
set ylabel "efficiency (ideal / predicted makespan)"
set grid
set key bottom left title "tile size" box opaque
plot for [t in "$tiles"] "$tsv" using 1:(\$2 == t + 0 ? \$4 : NaN) with linespoints title t." px"
GP
echo "tile_schedule.sh: wrote $png" >&2
