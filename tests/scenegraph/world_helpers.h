// Helpers for testing a World against brute force: a shape node, and the closest hit found
// by asking every top-level object in turn (no BVH).
#pragma once

#include "scenegraph/shape_registry.h"
#include "scenegraph/world.h"

#include <memory>

namespace lucent::testing {

inline std::unique_ptr<Node> shapeNode(ShapeSpec spec, const Mat4& parentFromNode = Mat4(1.0)) {
  auto n = std::make_unique<Node>();
  n->kind = NodeKind::Shape;
  n->element = shapeElementName(spec);
  n->shape = std::move(spec);
  n->parentFromNode = parentFromNode;
  return n;
}

// Each object's own intersect (an Instance carries the ray into object space and tests its
// shape there), the nearest kept.
inline Hit bruteForce(const World& world, const Ray& ray) {
  Hit best;
  Ray r = ray;
  for (const auto& o : world.objects()) {
    Hit h;
    if (o.shape->intersect(r, h)) {
      r.tmax = h.t;
      best = h;
    }
  }
  return best;
}

}  // namespace lucent::testing
