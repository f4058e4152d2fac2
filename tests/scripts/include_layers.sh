#!/usr/bin/env bash
# The layers of docs/architecture.md are kept: scripts/check-layers passes on the tree, and
# fails, naming the file, line and layers, on copies of it with a deliberate upward include
# (render/ including lang/, primitives/ including scenegraph/) or an include that climbs
# out of its folder with "../".
# Run by CTest as: bash include_layers.sh <lucent-binary> <source-dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_test.sh"
work=$tmp

if ! python3 "$src/scripts/check-layers" "$src" >"$work/out" 2>&1; then
  cat "$work/out"; fail "the tree breaks its own layers"
fi

# A copy of the libraries and the document that holds the graph.
copy() {
  rm -rf "$work/tree"; mkdir -p "$work/tree/docs"
  cp "$src/docs/architecture.md" "$work/tree/docs/"
  for lib in memory primitives meshes csg scenegraph images povray lang render app cli mpi; do
    cp -r "$src/$lib" "$work/tree/"
  done
}

# expect_failure FILE LINE-TO-ADD EXPECTED-MESSAGE
expect_failure() {
  copy
  printf '%s\n' "$2" >>"$work/tree/$1"
  local lines; lines=$(wc -l <"$work/tree/$1")
  if python3 "$src/scripts/check-layers" "$work/tree" >"$work/out" 2>&1; then
    fail "an include of '$2' in $1 passed the layer check"
  elif ! grep -qF "$1:$lines: error: $3" "$work/out"; then
    cat "$work/out"; fail "the layer check did not say '$1:$lines: error: $3'"
  fi
}
expect_failure render/tracer.cpp '#include "lang/parser.h"' 'render/ may not include lang/'
expect_failure primitives/sphere.h '#include "scenegraph/scene.h"' 'primitives/ may not include scenegraph/'
expect_failure csg/csg_node.h '#include "../render/tracer.h"' 'csg/ may not include render/'
expect_failure images/image_plugin.h '#include "povray/pov_export.h"' 'images/ may not include povray/'
expect_failure render/renderer.cpp '#include "app/checkpoint.h"' 'render/ may not include app/'
expect_failure app/render_job.h '#include "cli/render_run.h"' 'app/ may not include cli/'

# Allowed includes, some across several layers, pass.
copy
printf '%s\n' '#include "primitives/math.h"' '#include "memory/system_memory.h"' >>"$work/tree/cli/main.cpp"
python3 "$src/scripts/check-layers" "$work/tree" >"$work/out" 2>&1 || { cat "$work/out"; fail "allowed includes refused"; }

[ "$failures" -eq 0 ] && echo "include layers: all checks passed"
exit $((failures > 0))
