// What `lucent check` prints about a valid scene: nodes by element, lights by type,
// cameras, materials, leaf instances and triangles (counting what <use> instantiates),
// and the deepest nesting of CSG operations. Computed from the scene graph alone, so
// checking a scene needs no primitives.
#pragma once

#include "scene.h"

#include <map>
#include <string>

namespace lucent {

struct SceneCounts {
  std::map<std::string, int> nodes;    // element name -> count, as written (defs included)
  int defs = 0;                        // top-level nodes inside <defs>
  std::map<std::string, int> lights;   // "point", "spot", ...
  std::map<std::string, int> cameras;  // "pinhole", ...
  int materials = 0;                   // declared (named and inline), without the default
  long long instances = 0;             // leaf shapes in the world, each <use> expanded
  long long triangles = 0;             // of <triangle>s and meshes, each <use> expanded
  int csgDepth = 0;                    // deepest nesting of union/merge/intersection/difference
};

SceneCounts countScene(const Scene& scene);

// Multi-line text, one "label: value" per line.
std::string sceneSummary(const Scene& scene);

}  // namespace lucent
