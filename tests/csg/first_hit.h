// What a ray meets first in a world: whether it meets anything, where, and the geometric
// normal there (the leaf applies Hit::flip), for the CSG tests.
#pragma once

#include "scenegraph/world.h"

namespace lucent::test {

struct Seen {
  bool found = false;
  double t = 0;
  Vec3 ng{0.0};
};

inline Seen look(const World& world, const Ray& ray) {
  Seen s;
  Hit h;
  if (!world.intersect(ray, h)) return s;
  s.found = true;
  s.t = h.t;
  s.ng = h.shape->surface(ray, h).ng;
  return s;
}

}  // namespace lucent::test
