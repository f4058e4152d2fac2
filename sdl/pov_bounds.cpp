#include "pov_bounds.h"

#include "pov_space.h"

#include "scenegraph/shape_registry.h"

#include <algorithm>
#include <cmath>
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

// POV-Ray's box of a disc, in its own space: the square of its outer radius, 0.001 thick
// (SMALL_TOLERANCE), turned from z onto the normal by POV-Ray's rotation (about
// (-n.y, n.x, 0) by acos n.z, in POV-Ray's space: Lucent's with z negated), so corners of
// a tilted disc's box lie where POV-Ray's do.
AABB povDiscBox(const DiscSpec& d) {
  const Vec3 n = lucentFromPov(d.normal);  // its own inverse
  Vec3 axis(1.0, 0.0, 0.0);
  double angle = 0.0;
  if (std::abs(n.z) > 1.0 - 1e-10) {
    angle = n.z < 0.0 ? kPi : 0.0;
  } else {
    axis = glm::normalize(Vec3(-n.y, n.x, 0.0));
    angle = std::acos(n.z);
  }
  const double c = std::cos(angle), s = std::sin(angle);
  const auto turned = [&](const Vec3& v) {  // Rodrigues' rotation of v about axis
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
  };
  constexpr double kThickness = 0.001;
  const Vec3 centre = lucentFromPov(d.center);
  AABB box;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? d.radius : -d.radius, (i & 2) ? d.radius : -d.radius,
                      (i & 4) ? kThickness : -kThickness);
    box.expand(lucentFromPov(centre + turned(corner)));
  }
  return box;
}

}  // namespace

AABB nodeBox(const Node& node, const Mat4& parent, const KnownBox& known) {
  if (known)
    if (const AABB* b = known(node)) return transformed(*b, parent);
  const Mat4 m = parent * node.parentFromNode;
  if (node.inverse) return AABB::everything();
  AABB box;
  switch (node.kind) {
    case NodeKind::Shape:
      try {
        const auto* disc = std::get_if<DiscSpec>(&*node.shape);
        box = transformed(disc ? povDiscBox(*disc) : makeShape(*node.shape)->bounds(), m);
      } catch (const std::exception&) {
        box = AABB::everything();  // a shape that cannot be built is refused when rendered
      }
      break;
    case NodeKind::Use:
      if (node.target) box = nodeBox(*node.target, m, known);
      break;
    case NodeKind::Light:
      break;
    case NodeKind::Group:
    case NodeKind::Union:
    case NodeKind::Merge:
      for (const auto& c : node.children) box.expand(nodeBox(*c, m, known));
      break;
    case NodeKind::Intersection:
      box = AABB::everything();
      for (const auto& c : node.children) box = AABB::meet(box, nodeBox(*c, m, known));
      break;
    case NodeKind::Difference:
      if (!node.children.empty()) box = nodeBox(*node.children.front(), m, known);
      break;
  }
  for (const auto& c : node.clip) box = AABB::meet(box, nodeBox(*c, m, known));
  return box;
}

double boxVolume(const AABB& box) {
  if (box.empty()) return 0.0;
  double v = 1.0;
  for (int i = 0; i < 3; ++i) v *= std::min(box.hi[i] - box.lo[i], kBoundHuge);
  return v;
}

}  // namespace lucent::sdl
