#!/usr/bin/env bash
# Expansion speed: a scene of N×N spheres made by two nested <repeat>s with expression-valued
# positions and random radii, against the same scene written out literally (the same
# numbers, written by this script). Each is loaded, expanded, built into a world and
# rendered at 32×24 by one process on one core (taskset -c 0, -t 1); prints wall and CPU
# time and peak memory of each, and the ratios; and the same spheres made by POV-Ray #for
# loops read by the POV-Ray importer, against the repeats. The aims: the repeat scene of 10^6 spheres
# in under 2 s, and its peak memory within 1.5× of the literal one's.
#   bash bench/expansion_speed.sh [--lucent PATH] [--n 1000] [--runs 3] [--tsv FILE]
# --tsv writes "scene<TAB>wall s<TAB>CPU s<TAB>peak MB" for each (bench/run.sh reads it).
set -euo pipefail
cd "$(dirname "$0")/.."
lucent=build/cli/lucent
n=1000
runs=3
tsv=""
while [ $# -gt 0 ]; do
  case "$1" in
    --lucent) lucent=$2; shift 2 ;;
    --n) n=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --tsv) tsv=$2; shift 2 ;;
    *) echo "expansion_speed: unknown option $1" >&2; exit 1 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat > "$work/repeat.xml" <<XML
<scene version="1">
  <camera position="0 50 120" look-at="0 0 0"/>
  <light position="100 200 100"/>
  <repeat var="i" count="$n">
    <repeat var="j" count="$n">
      <sphere center="\${i*0.2-100} 0 \${j*0.2-100}" radius="\${0.05+0.04*random(1, i*$n+j)}"/>
    </repeat>
  </repeat>
</scene>
XML

# The literal twin: the same numbers, computed as Lucent does (random() is SplitMix64's
# finaliser over the arguments' bits; Python's repr of a float is its shortest form, as
# Lucent writes substituted numbers).
python3 - "$n" > "$work/literal.xml" <<'PY'
import struct, sys
n = int(sys.argv[1])
M = (1 << 64) - 1
def bits(v):
    if v == 0.0: v = 0.0
    return struct.unpack('<Q', struct.pack('<d', v))[0]
def mix(z):
    z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & M
    z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & M
    return z ^ (z >> 31)
def rnd(seed, i):
    h = mix((bits(seed) + 0x9e3779b97f4a7c15) & M)
    h = mix(h ^ ((bits(i) + 0x632be59bd9b4e019) & M))
    return (h >> 11) * 2.0**-53
out = ['<scene version="1">', '  <camera position="0 50 120" look-at="0 0 0"/>', '  <light position="100 200 100"/>']
for i in range(n):
    for j in range(n):
        out.append('  <sphere center="%r 0 %r" radius="%r"/>' % (i*0.2-100, j*0.2-100, 0.05+0.04*rnd(1.0, float(i*n+j))))
out.append('</scene>')
print('\n'.join(out))
PY

# The POV-Ray twin: two nested #for loops, radii from POV-Ray's rand() (other numbers than
# random()'s, the same work), read by Lucent's POV-Ray importer.
cat > "$work/loops.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 50, -120> look_at 0 }
light_source { <100, 200, -100> color rgb 1 }
#declare R = seed(1);
#for (I, 0, $n - 1)
  #for (J, 0, $n - 1)
    sphere { <I*0.2-100, 0, J*0.2-100>, 0.05+0.04*rand(R) }
  #end
#end
POV

measure() {  # scene -> "wall cpu peakKB" (best of $runs by wall time)
  local best=""
  for _ in $(seq "$runs"); do
    local line
    line=$( { taskset -c 0 /usr/bin/time -f "%e %U %S %M" "$lucent" render "$1" -o "$work/out.ppm" \
              -w 32 -h 24 -t 1 -q; } 2>&1 | tail -1)
    if [ -z "$best" ] || awk -v a="$line" -v b="$best" 'BEGIN{split(a,x," ");split(b,y," ");exit !(x[1]<y[1])}'; then
      best=$line
    fi
  done
  echo "$best"
}
rep=$(measure "$work/repeat.xml")
lit=$(measure "$work/literal.xml")
pov=$(measure "$work/loops.pov")
cmp -s <("$lucent" check "$work/repeat.xml" | grep '^nodes') <("$lucent" check "$work/literal.xml" | grep '^nodes') \
  || { echo "expansion_speed: the two scenes differ in their node counts" >&2; exit 1; }
spheres=$((n * n))
echo "| scene ($spheres spheres, one core) | wall s | CPU s | peak MB |"
echo "| --- | --- | --- | --- |"
for pair in "repeats:$rep" "literal:$lit" "POV-Ray #for loops:$pov"; do
  name=${pair%%:*}; set -- ${pair#*:}
  awk -v n="$name" -v w="$1" -v u="$2" -v s="$3" -v m="$4" 'BEGIN{printf "| %s | %.2f | %.2f | %.0f |\n", n, w, u+s, m/1024}'
done
if [ -n "$tsv" ]; then
  { printf 'scene\twall_s\tcpu_s\tpeak_mb\n'
    for pair in "repeats:$rep" "literal:$lit"; do
      name=${pair%%:*}; set -- ${pair#*:}
      awk -v n="$name" -v w="$1" -v u="$2" -v s="$3" -v m="$4" 'BEGIN{printf "%s\t%.3f\t%.3f\t%.1f\n", n, w, u+s, m/1024}'
    done; } > "$tsv"
fi
set -- $rep; rw=$1; rm=$4
set -- $lit; lw=$1; lm=$4
awk -v rw="$rw" -v lw="$lw" -v rm="$rm" -v lm="$lm" \
  'BEGIN{printf "\nrepeats / literal: time %.2f×, peak memory %.2f×\n", rw/lw, rm/lm}'
set -- $pov; pw=$1; pm=$4
awk -v rw="$rw" -v pw="$pw" -v rm="$rm" -v pm="$pm" \
  'BEGIN{printf "POV-Ray loops / repeats: time %.2f×, peak memory %.2f×\n", pw/rw, pm/rm}'
