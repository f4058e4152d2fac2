#!/usr/bin/env bash
# MPI against threads on one machine (docs/distributed.md): the wall time of
# `mpirun -np 2 lucent-mpi render S -t 1` against `lucent render S -t 2` on three scenes of
# different cost profiles, run alternately side by side, RUNS times each (the median is kept).
# Efficiency = threaded time / MPI time (1.0: two ranks as fast as two threads). Each MPI
# image is compared byte for byte with the threaded one.
#
#   bash bench/mpi_efficiency.sh [--runs N] [--build DIR]
#
# The scenes: examples/five-shapes.xml (glass, mirrors, area light: uneven tiles), a displaced
# sphere of 720,000 triangles in a PLY file (mostly parsing: the file streamed to rank 1
# while both parse it, and a BVH built by each rank), and examples/primitives.xml at
# 1600x1200 (many cheap, even tiles). mpirun's own start (`mpirun -np 2 lucent-mpi
# --version`, measured too) is a fixed cost of every job; the last column leaves it out.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=3
build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    *) echo "usage: $0 [--runs N] [--build DIR]" >&2; exit 2 ;;
  esac
done
lucent=$(realpath "$build/cli/lucent")
lucent_mpi=$(realpath "$build/mpi/lucent-mpi")
command -v mpirun > /dev/null || { echo "mpi_efficiency: mpirun is not installed" >&2; exit 3; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun=(mpirun -np 2)
[ "$(id -u)" = 0 ] && mpirun+=(--allow-run-as-root)
mpirun+=(--oversubscribe --bind-to none)

# A displaced sphere: 600 x 600 quads, each two triangles, binary PLY.
python3 - "$work/bumpy.ply" <<'EOF'
import math, struct, sys
n = 600
verts = []
for j in range(n + 1):
    th = math.pi * j / n
    for i in range(n):
        ph = 2 * math.pi * i / n
        r = 1 + 0.05 * math.sin(9 * th) * math.cos(11 * ph)
        verts.append((r * math.sin(th) * math.cos(ph), r * math.cos(th), r * math.sin(th) * math.sin(ph)))
faces = []
for j in range(n):
    for i in range(n):
        a, b = j * n + i, j * n + (i + 1) % n
        c, d = a + n, b + n
        if j > 0: faces.append((a, b, d))
        if j < n - 1: faces.append((a, d, c))
with open(sys.argv[1], "wb") as f:
    f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
             "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
             % (len(verts), len(faces))).encode())
    f.write(b"".join(struct.pack("<3f", *v) for v in verts))
    f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))
EOF
cat > "$work/bumpy.xml" <<'EOF'
<scene version="1">
  <render width="800" height="600"/>
  <camera position="0 0.6 3.2" look-at="0 0 0"/>
  <light position="4 5 6"/>
  <light position="-5 2 3" color="0.4 0.4 0.5"/>
  <mesh src="bumpy.ply" smooth="true">
    <material diffuse="0.8 0.5 0.3" reflective="0.2" specular="0.5" shininess="60"/>
  </mesh>
  <plane normal="0 1 0" offset="-1.1"/>
</scene>
EOF

wall() {  # wall seconds of a command
  local t0 t1
  t0=$(date +%s.%N)
  "$@" > /dev/null 2>&1 || { echo "mpi_efficiency: '$*' failed" >&2; exit 3; }
  t1=$(date +%s.%N)
  echo "$t1 - $t0" | bc -l
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "# mpi_efficiency: wall time, median of $runs side-by-side runs; $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
: > "$work/launch"
for ((r = 0; r < runs; r++)); do wall "${mpirun[@]}" "$lucent_mpi" --version >> "$work/launch"; done
launch=$(median < "$work/launch")
printf '# mpirun -np 2 lucent-mpi --version (the launch of a job): %.2f s\n\n' "$launch"
echo "| scene | 1 process × 2 threads (s) | 2 ranks × 1 thread (s) | efficiency | without the launch | same bytes |"
echo "|---|---|---|---|---|---|"
for spec in "examples/five-shapes.xml" "$work/bumpy.xml" "examples/primitives.xml -w 1600 -h 1200"; do
  read -r -a args <<< "$spec"
  name=$(basename "${args[0]}")
  [ ${#args[@]} -gt 1 ] && name="$name ${args[*]:1}"
  : > "$work/threads" && : > "$work/ranks"
  for ((r = 0; r < runs; r++)); do
    wall "$lucent" render "${args[@]}" -t 2 -q -o "$work/threads.png" >> "$work/threads"
    wall "${mpirun[@]}" "$lucent_mpi" render "${args[@]}" -t 1 -q -o "$work/ranks.png" >> "$work/ranks"
  done
  t=$(median < "$work/threads")
  m=$(median < "$work/ranks")
  same=no
  cmp -s "$work/threads.png" "$work/ranks.png" && same=yes
  printf '| %s | %.2f | %.2f | %.2f | %.2f | %s |\n' "$name" "$t" "$m" "$(echo "$t / $m" | bc -l)" \
    "$(echo "$t / ($m - $launch)" | bc -l)" "$same"
done
