#include "pov_bounds.h"

#include "scenegraph/shape_registry.h"

#include <algorithm>
#include <stdexcept>

namespace lucent::sdl {

namespace {

// POV-Ray's BOUND_HUGE: sides longer count as this long.
constexpr double kBoundHuge = 2.0e10;

AABB transformed(const AABB& box, const Mat4& m) {
  if (box.empty()) return box;
  if (!box.isBounded()) return AABB::everything();
  AABB out;
  for (int i = 0; i < 8; ++i) {
    const Vec3 c((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                 (i & 4) ? box.hi.z : box.lo.z);
    out.expand(Vec3(m * Vec4(c, 1.0)));
  }
  return out;
}

}  // namespace

AABB nodeBox(const Node& node, const Mat4& parent) {
  const Mat4 m = parent * node.parentFromNode;
  if (node.inverse) return AABB::everything();
  AABB box;
  switch (node.kind) {
    case NodeKind::Shape:
      try {
        box = transformed(makeShape(*node.shape)->bounds(), m);
      } catch (const std::exception&) {
        box = AABB::everything();  // a shape that cannot be built is refused when rendered
      }
      break;
    case NodeKind::Use:
      if (node.target) box = nodeBox(*node.target, m);
      break;
    case NodeKind::Light:
      break;
    case NodeKind::Group:
    case NodeKind::Union:
    case NodeKind::Merge:
      for (const auto& c : node.children) box.expand(nodeBox(*c, m));
      break;
    case NodeKind::Intersection:
      box = AABB::everything();
      for (const auto& c : node.children) box = AABB::meet(box, nodeBox(*c, m));
      break;
    case NodeKind::Difference:
      if (!node.children.empty()) box = nodeBox(*node.children.front(), m);
      break;
  }
  for (const auto& c : node.clip) box = AABB::meet(box, nodeBox(*c, m));
  return box;
}

double boxVolume(const AABB& box) {
  if (box.empty()) return 0.0;
  double v = 1.0;
  for (int i = 0; i < 3; ++i) v *= std::min(box.hi[i] - box.lo[i], kBoundHuge);
  return v;
}

}  // namespace lucent::sdl
