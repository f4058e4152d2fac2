#!/usr/bin/env bash
# The fixed cost of a render (docs/startup.md): the CPU time of a whole `lucent render` of a
# 64x48 one-sphere scene to PNG, start-up, parsing, rendering and writing included.
#
#   bash bench/startup.sh [--lucent PATH] [--runs N] [--tsv FILE]
#
# Measured by `perf stat -r N` (the mean over N processes of task-clock, user and system
# time; /usr/bin/time's 10 ms resolution cannot see a few milliseconds), and likewise for
# `lucent --version` (the process start alone). Prints a markdown table; --tsv also writes
# "run, cpu_ms, user_ms, sys_ms" rows.
set -euo pipefail
cd "$(dirname "$0")/.."

lucent=build/cli/lucent
runs=20
tsv=""
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    *) echo "usage: $0 [--lucent PATH] [--runs N] [--tsv FILE]" >&2; exit 2 ;;
  esac
done
lucent=$(realpath -m "$lucent")
command -v perf > /dev/null || { echo "startup: perf is not installed (apt-get install linux-perf)" >&2; exit 3; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat > "$work/sphere.xml" <<'EOF'
<scene version="1">
  <render width="64" height="48"/>
  <camera position="0 0 5" look-at="0 0 0"/>
  <light position="3 3 3"/>
  <sphere radius="1"/>
</scene>
EOF

# "cpu user sys" in milliseconds, the means of `runs` processes.
measure() {
  perf stat -x, -r "$runs" -e task-clock,user_time,system_time -o "$work/stat.csv" "$@" > /dev/null 2>&1 ||
    { echo "startup: '$*' failed" >&2; exit 3; }
  awk -F, '$3 == "task-clock" { c = $1 } $3 == "user_time" { u = $1 / 1e6 } $3 == "system_time" { s = $1 / 1e6 }
    END { printf "%.1f %.1f %.1f\n", c, u, s }' "$work/stat.csv"
}
read -r rc ru rs < <(measure "$lucent" render "$work/sphere.xml" -o "$work/t.png" -q)
read -r vc vu vs < <(measure "$lucent" --version)

echo "# startup: lucent render of a 64x48 one-sphere scene to PNG, mean of $runs processes (perf stat); load $(cut -d' ' -f1 /proc/loadavg)"
echo
echo "| run | CPU ms | user ms | system ms |"
echo "|---|---|---|---|"
echo "| \`lucent render sphere.xml -o t.png -q\` (64×48, one sphere) | $rc | $ru | $rs |"
echo "| \`lucent --version\` (the process start alone) | $vc | $vu | $vs |"
if [ -n "$tsv" ]; then
  printf 'run\tcpu_ms\tuser_ms\tsys_ms\nrender\t%s\t%s\t%s\nversion\t%s\t%s\t%s\n' \
    "$rc" "$ru" "$rs" "$vc" "$vu" "$vs" > "$tsv"
fi
