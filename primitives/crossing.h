// All the places where a ray crosses a surface, in order, for CSG and shadow filtering.
#pragma once

#include "hit.h"

#include <vector>

namespace lucent {

struct Crossing {
  Hit hit;        // distance, leaf and payload, as a closest-hit search would give them
  bool entering;  // true where the ray passes from outside to inside the solid
  // A crossing that changes membership but shows no surface: where a clipped solid
  // (csg/clipped.h) is cut by its clip, which POV-Ray does not draw. A search for the
  // closest hit passes through it.
  bool hidden = false;
};

struct CrossingList {
  bool startsInside = false;    // is the point at ray.tmin inside the solid?
  std::vector<Crossing> items;  // sorted by hit.t, all within [ray.tmin, ray.tmax]

  void clear() {
    startsInside = false;
    items.clear();
  }
};

}  // namespace lucent
