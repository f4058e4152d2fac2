#!/usr/bin/env bash
# lucent-mpi in real mpirun jobs on this machine (docs/distributed.md): the image is the
# same bytes as a single process writes, for 1 to 4 ranks, every sampling mode, several
# tile sizes and thread counts, a region and an animation's frames; the workers render from
# the files rank 0 sent them, with the scene's folder hidden from them (a mount namespace
# of their own); a killed rank ends the job naming it, and --resume completes the image;
# an animation stopped after a frame resumes over the ranks; a bad scene or option is said
# once, with the usual exit status.
# Usage: bash mpi_render.sh <path-to-lucent> <source-dir> <path-to-lucent-mpi>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/lib/script_test.sh"
mpi=${3:?usage: bash mpi_render.sh <lucent> <source-dir> <lucent-mpi>}
command -v mpirun >/dev/null || skip "mpirun (openmpi-bin) is not installed"
command -v oiiotool >/dev/null || skip "oiiotool (openimageio-tools) is not installed"
# The workers' copies go into a folder of this run's own (a worker makes its folder in
# TMPDIR, and mpirun passes the environment to the ranks it starts here), so that runs side
# by side (two clones, two builds on one machine) neither see nor remove each other's.
workers="$tmp/workers"
mkdir -p "$workers"
export TMPDIR=$workers
# Open MPI's own allocations are not ours to report (a sanitizer build).
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
run_mpi() {  # run_mpi N ARGS...: lucent-mpi on N ranks
  local n=$1
  shift
  mpirun --allow-run-as-root --oversubscribe -np "$n" "$mpi" "$@"
}
expect() {  # expect STATUS WHAT -- COMMAND...
  local want=$1 what=$2
  shift 3
  "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  [ "$got" -eq "$want" ] || fail "$what: exit status $got, expected $want; stderr: $(cat "$tmp/stderr")"
}

# A scene that reads an include, a mesh and a texture (made by lucent itself).
mkdir -p "$tmp/scene/parts" "$tmp/scene/meshes" "$tmp/scene/tex"
cp "$src/examples/gallery/meshes/icosahedron.off" "$tmp/scene/meshes/"
cat > "$tmp/make.xml" <<'XML'
<scene version="1">
  <render width="32" height="32"/>
  <camera position="0 0 4" look-at="0 0 0"/>
  <light position="3 3 5"/>
  <sphere radius="1.2"><material diffuse="1 0.4 0.1"/></sphere>
</scene>
XML
"$lucent" render "$tmp/make.xml" -o "$tmp/scene/tex/wood.png" -q || fail "making the texture"
cat > "$tmp/scene/parts/floor.xml" <<'XML'
<scene version="1">
  <plane normal="0 1 0"><material diffuse="1"><image src="../tex/wood.png" scale="2 2"/></material></plane>
</scene>
XML
scene() {  # scene MODE: the <render> attributes of a sampling mode
  cat > "$tmp/scene/scene.xml" <<XML
<scene version="1">
  <render width="90" height="60" $1/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light type="area" position="3 5 4" u="1 0 0" v="0 0 1" samples="3 3" jitter="true"/>
  <include src="parts/floor.xml"/>
  <sphere center="0.6 0.7 0" radius="0.7"><material transmissive="0.8" ior="1.5" reflective="0.1"/></sphere>
  <mesh src="meshes/icosahedron.off" transform="scale(0.6) translate(-1.2 0.6 0)"><material diffuse="0.3 0.5 1" reflective="0.3"/></mesh>
</scene>
XML
}

# Byte identity with a single process: every sampling mode, 1 to 4 ranks, tile sizes and threads.
modes=("samples=\"1\"" "samples=\"4\"" "samples=\"16\" adaptive=\"0.05\"" "adaptive=\"0.2\" adaptive-mode=\"corners\" adaptive-depth=\"3\"")
runs=("1 -t 2" "2 -t 1 --tile-size 8" "3 -t 1 --tile-size 13" "4 -t 1" "2 -t 2 --tile-size 32")
for mode in "${modes[@]}"; do
  scene "$mode"
  "$lucent" render "$tmp/scene/scene.xml" -o "$tmp/one.png" -q || fail "$mode: lucent render"
  for r in "${runs[@]}"; do
    read -r n opts <<<"$r"
    rm -f "$tmp/mpi.png"
    # The rays a single process traces with these tiles (adaptive sampling renders each
    # tile's margin too, so they depend on the tile size, not on the ranks).
    # shellcheck disable=SC2086
    "$lucent" render "$tmp/scene/scene.xml" -o "$tmp/tiles.png" -q --stats $opts >"$tmp/one.stats" || fail "$mode: $opts"
    # shellcheck disable=SC2086
    expect 0 "$mode, $n ranks $opts" -- run_mpi "$n" render "$tmp/scene/scene.xml" -o "$tmp/mpi.png" -q --stats $opts
    cmp -s "$tmp/one.png" "$tmp/mpi.png" || fail "$mode, $n ranks $opts: the image differs from a single process's"
    # The ray counts are the sum of every rank's.
    [ "$(grep '^rays:' "$tmp/stdout")" = "$(grep '^rays:' "$tmp/one.stats")" ] ||
      fail "$mode, $n ranks $opts: ray counts $(grep '^rays:' "$tmp/stdout"), single process $(grep '^rays:' "$tmp/one.stats")"
  done
done
[ -z "$(ls "$workers" | grep '^lucent-mpi-')" ] || fail "a worker left its folder: $(ls "$workers")"

# A region, with adaptive supersampling looking across its edges, in float EXR.
scene "samples=\"16\" adaptive=\"0.05\""
"$lucent" render "$tmp/scene/scene.xml" -o "$tmp/one.exr" -q --region 20,10,77,51 || fail "region"
expect 0 "region over 3 ranks" -- run_mpi 3 render "$tmp/scene/scene.xml" -o "$tmp/mpi.exr" -q -t 1 --region 20,10,77,51 --tile-size 16
# Every bit of every float pixel (the files differ in their time stamps).
oiiotool "$tmp/one.exr" "$tmp/mpi.exr" --diff --fail 0 >"$tmp/diff" 2>&1 || fail "region over 3 ranks: the EXR differs: $(tail -3 "$tmp/diff")"

# An animation: each frame's tiles over the ranks, each frame read again by every rank.
cat > "$tmp/scene/anim.xml" <<'XML'
<scene version="1">
  <animation frames="4"/>
  <render width="60" height="40" samples="4"/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light position="3 5 4"/>
  <include src="parts/floor.xml"/>
  <group transform="rotate-y(${90 * clock})">
    <mesh src="meshes/icosahedron.off" transform="scale(0.6) translate(1 0.6 0)"><material diffuse="0.3 0.5 1"/></mesh>
  </group>
</scene>
XML
"$lucent" render "$tmp/scene/anim.xml" -o "$tmp/one#.png" -q || fail "animation"
expect 0 "animation over 3 ranks" -- run_mpi 3 render "$tmp/scene/anim.xml" -o "$tmp/mpi#.png" -q -t 1 --tile-size 16
for f in 1 2 3 4; do
  cmp -s "$tmp/one$f.png" "$tmp/mpi$f.png" || fail "animation frame $f differs"
done
cmp -s "$tmp/one1.png" "$tmp/one2.png" && fail "the animation's frames 1 and 2 are the same (the test shows nothing)"
expect 0 "frames 2..3 over 2 ranks" -- run_mpi 2 render "$tmp/scene/anim.xml" -o "$tmp/part#.png" -q -t 1 --frames 2..3
cmp -s "$tmp/one2.png" "$tmp/part2.png" && cmp -s "$tmp/one3.png" "$tmp/part3.png" || fail "--frames 2..3 differ"
[ -f "$tmp/part1.png" ] && fail "--frames 2..3 wrote frame 1"

# No shared file system: the workers run with the scene's folder covered by an empty one
# (a mount namespace of their own), so they can only read what rank 0 sent.
if unshare -m sh -c "mount -t tmpfs none '$tmp/scene' && [ ! -e '$tmp/scene/scene.xml' ]" 2>/dev/null; then
  scene "samples=\"4\""
  "$lucent" render "$tmp/scene/scene.xml" -o "$tmp/one.png" -q || fail "the scene for hidden files"
  hidden="mount -t tmpfs none '$tmp/scene' && exec \"\$0\" \"\$@\""
  expect 0 "workers without the scene's files" -- mpirun --allow-run-as-root --oversubscribe \
    -np 1 "$mpi" render "$tmp/scene/scene.xml" -o "$tmp/hidden.png" -q -t 1 --tile-size 8 : \
    -np 2 unshare -m sh -c "$hidden" "$mpi" render "$tmp/scene/scene.xml" -o "$tmp/hidden.png" -q -t 1 --tile-size 8
  cmp -s "$tmp/one.png" "$tmp/hidden.png" || fail "workers without the scene's files: the image differs"
  # The same covering makes a worker that reads the scene itself fail: the test can fail.
  expect 3 "a process without the scene's files" -- unshare -m sh -c "$hidden" "$lucent" render "$tmp/scene/scene.xml" -o "$tmp/x.png" -q
else
  fail "cannot make a mount namespace here (unshare -m, as root) to hide the scene from the workers"
fi

# An animation stopped (SIGTERM to rank 0, as a batch system's cancel sends every process
# of the job) after its first frame, then resumed over the ranks: the written frame is
# skipped (loaded, found written, not rendered: the workers, which parsed it alongside rank
# 0, are told so), the others match a single process.
cat > "$tmp/scene/slow-anim.xml" <<'XML'
<scene version="1">
  <animation frames="4"/>
  <render width="160" height="120" samples="16"/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light type="area" position="3 5 4" u="1 0 0" v="0 0 1" samples="6 6" jitter="true"/>
  <include src="parts/floor.xml"/>
  <sphere center="${clock} 0.7 0" radius="0.7"><material transmissive="0.8" ior="1.5" reflective="0.1"/></sphere>
</scene>
XML
"$lucent" render "$tmp/scene/slow-anim.xml" -o "$tmp/sa-one#.png" -q || fail "the slow animation"
run_mpi 2 render "$tmp/scene/slow-anim.xml" -o "$tmp/sa#.png" -q -t 1 --tile-size 8 --checkpoint-interval 0.05 \
  >"$tmp/term.out" 2>"$tmp/term.err" &
job=$!
for _ in $(seq 600); do
  [ -f "$tmp/sa1.png" ] && break
  sleep 0.01
done
for p in $(pgrep -f "$mpi render $tmp/scene/slow-anim.xml"); do
  tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=0 && kill -TERM "$p"
done
wait "$job"
[ -f "$tmp/sa4.png" ] && fail "the stopped animation wrote every frame (the test shows nothing)"
grep -q "run again with --resume" "$tmp/term.err" || fail "the stopped animation kept no checkpoint: $(cat "$tmp/term.err")"
expect 0 "an animation resumed over 2 ranks" -- run_mpi 2 render "$tmp/scene/slow-anim.xml" -o "$tmp/sa#.png" -t 1 --tile-size 8 --resume
grep -q "frame 1: '$tmp/sa1.png' was written before; skipped" "$tmp/stderr" ||
  fail "the resumed animation did not skip frame 1: $(cat "$tmp/stderr")"
for f in 1 2 3 4; do
  cmp -s "$tmp/sa-one$f.png" "$tmp/sa$f.png" || fail "the resumed animation's frame $f differs"
done
# A killed worker: mpirun ends the job naming the rank, rank 0 keeps its checkpoint, and
# --resume (plain lucent) completes the same image.
cat > "$tmp/scene/slow.xml" <<'XML'
<scene version="1">
  <render width="160" height="120" samples="16"/>
  <camera position="0 1.5 5" look-at="0 0.5 0"/>
  <light type="area" position="3 5 4" u="1 0 0" v="0 0 1" samples="6 6" jitter="true"/>
  <include src="parts/floor.xml"/>
  <sphere center="0.6 0.7 0" radius="0.7"><material transmissive="0.8" ior="1.5" reflective="0.1"/></sphere>
  <mesh src="meshes/icosahedron.off" transform="scale(0.6) translate(-1.2 0.6 0)"><material diffuse="0.3 0.5 1" reflective="0.3"/></mesh>
</scene>
XML
"$lucent" render "$tmp/scene/slow.xml" -o "$tmp/slow-one.png" -q || fail "the slow scene"
run_mpi 3 render "$tmp/scene/slow.xml" -o "$tmp/slow.png" -q -t 1 --tile-size 8 --checkpoint-interval 0.05 \
  >"$tmp/kill.out" 2>"$tmp/kill.err" &
job=$!
killed=""
for _ in $(seq 200); do
  sleep 0.05
  [ -s "$tmp/slow.png.checkpoint" ] || continue
  for p in $(pgrep -f "$mpi render $tmp/scene/slow.xml"); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=2; then
      kill -9 "$p" && killed=$p
    fi
  done
  [ -n "$killed" ] && break
done
wait "$job"
status=$?
[ -n "$killed" ] || fail "no worker of rank 2 to kill (did the job end too soon?): $(cat "$tmp/kill.err")"
[ "$status" -ne 0 ] || fail "the job with a killed rank exited 0"
grep -q "process rank 2 .* exited on signal 9" "$tmp/kill.err" || fail "the killed rank is not named: $(cat "$tmp/kill.err")"
grep -q "run again with --resume" "$tmp/kill.err" || fail "rank 0 did not keep its checkpoint: $(cat "$tmp/kill.err")"
[ -f "$tmp/slow.png" ] && fail "the job with a killed rank wrote its image"
expect 0 "resume after a killed rank" -- "$lucent" render "$tmp/scene/slow.xml" -o "$tmp/slow.png" -t 2 --tile-size 8 --resume
grep -q "resuming '$tmp/slow.png': [1-9][0-9]* of 300 tiles from the checkpoint" "$tmp/stderr" ||
  fail "resume after a killed rank: $(cat "$tmp/stderr")"
cmp -s "$tmp/slow.png" "$tmp/slow-one.png" || fail "the image resumed after a killed rank differs"
rm -rf "$workers"/lucent-mpi-*  # the killed worker's copies (SIGKILL leaves no time to remove them)

# Bad input: said once (by rank 0), with the exit statuses of lucent render.
printf '<scene version="1">\n  <sphere radius="-1"/>\n</scene>\n' >"$tmp/scene/bad.xml"
expect 2 "a bad scene over 3 ranks" -- run_mpi 3 render "$tmp/scene/bad.xml" -o "$tmp/bad.png"
[ "$(grep -c "bad.xml:2:[0-9]*: error" "$tmp/stderr")" -eq 1 ] || fail "a bad scene: $(cat "$tmp/stderr")"
expect 1 "a bad option over 2 ranks" -- run_mpi 2 render "$tmp/scene/scene.xml" --tile-sise 8
[ "$(grep -c "did you mean '--tile-size'" "$tmp/stderr")" -eq 1 ] || fail "a bad option: $(cat "$tmp/stderr")"
expect 3 "a missing scene over 2 ranks" -- run_mpi 2 render "$tmp/scene/none.xml" -o "$tmp/none.png"
grep -q "none.xml" "$tmp/stderr" || fail "a missing scene: $(cat "$tmp/stderr")"

[ "$failures" -eq 0 ] || exit 1
echo "lucent-mpi: all checks passed"
