#include "pov_coincident.h"

#include "primitives/aabb.h"
#include "scenegraph/shape_registry.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <vector>

namespace lucent {

namespace {

// A leaf of one CSG operand, in the CSG node's space.
struct Leaf {
  const Node* node;
  size_t operand;      // which child of the CSG node it belongs to
  AABB bounds;         // its bounding box
  bool exact;          // the box is its surface (an axis-aligned box) or holds its plane
  int planeAxis = -1;  // an axis-aligned plane: the axis, and its coordinate
  double planeAt = 0.0;
};

// Does m map each axis onto an axis (a scale, a mirror, quarter turns, a translation)?
bool keepsAxes(const Mat4& m) {
  for (int r = 0; r < 3; ++r) {
    int nonzero = 0;
    for (int c = 0; c < 3; ++c) nonzero += m[c][r] != 0.0;
    if (nonzero != 1) return false;
  }
  return true;
}

// Columns orthogonal and of one length s: a turn, a mirror and a uniform scale.
bool isSimilarity(const Mat4& m, double s) {
  const Vec3 a(m[0]), b(m[1]), c(m[2]);
  const double tol = 1e-12 * s * s;
  return std::abs(glm::dot(a, b)) <= tol && std::abs(glm::dot(a, c)) <= tol &&
         std::abs(glm::dot(b, c)) <= tol && std::abs(glm::dot(b, b) - s * s) <= tol &&
         std::abs(glm::dot(c, c) - s * s) <= tol;
}

void collect(const Node& n, const Mat4& m, size_t operand, std::vector<Leaf>& out, int depth) {
  if (depth > 64) return;  // the parser bounds instance depth; this only bounds the walk
  const Mat4 here = m * n.parentFromNode;
  switch (n.kind) {
    case NodeKind::Use:
      if (n.target) collect(*n.target, here, operand, out, depth + 1);
      return;
    case NodeKind::Shape: {
      if (!n.shape) return;
      Leaf leaf{&n, operand, {}, false};
      if (const auto* p = std::get_if<PlaneSpec>(&*n.shape)) {
        for (int k = 0; k < 3; ++k)
          if (std::abs(p->normal[k]) == 1.0 && keepsAxes(here)) {
            // The plane n·x = d with n along axis k, carried by `here`.
            const Vec4 point = here * Vec4(p->normal * p->offset, 1.0);
            int axis = 0;
            for (int r = 0; r < 3; ++r)
              if (here[k][r] != 0.0) axis = r;
            leaf.planeAxis = axis;
            leaf.planeAt = point[axis];
            leaf.exact = true;
          }
        if (!leaf.exact) return;
      } else {
        std::shared_ptr<const Shape> shape;
        try {
          shape = makeShape(*n.shape);
        } catch (const std::exception&) {
          return;  // the world builder reports it
        }
        leaf.bounds = transformBounds(here, shape->bounds());
        // A sphere under a similarity stays a sphere: its own bounds, not a turned box's.
        const double s = glm::length(Vec3(here[0]));
        if (const auto* sp = std::get_if<SphereSpec>(&*n.shape); sp && isSimilarity(here, s)) {
          const Vec3 c(here * Vec4(sp->center, 1.0));
          leaf.bounds = AABB(c - Vec3(sp->radius * s), c + Vec3(sp->radius * s));
        }
        leaf.exact = std::holds_alternative<BoxSpec>(*n.shape) && keepsAxes(here);
      }
      out.push_back(leaf);
      return;
    }
    default:
      for (const auto& c : n.children) collect(*c, here, operand, out, depth + 1);
  }
}

bool same(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

// The plane (axis, coordinate) in which a face of box a and a face of box b overlap with
// area, if any.
std::optional<std::pair<int, double>> sharedFace(const AABB& a, const AABB& b) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const bool overlap = std::min(a.hi[i], b.hi[i]) > std::max(a.lo[i], b.lo[i]) &&
                         std::min(a.hi[j], b.hi[j]) > std::max(a.lo[j], b.lo[j]);
    if (!overlap) continue;
    for (double fa : {a.lo[k], a.hi[k]})
      for (double fb : {b.lo[k], b.hi[k]})
        if (same(fa, fb)) return std::make_pair(k, fa);
  }
  return std::nullopt;
}

std::optional<std::string> coincidence(const Leaf& a, const Leaf& b) {
  const char* axes = "xyz";
  if (a.planeAxis >= 0 && b.planeAxis >= 0) {
    if (a.planeAxis == b.planeAxis && same(a.planeAt, b.planeAt))
      return fmt::format("lie in one plane ({} = {})", axes[a.planeAxis], a.planeAt);
    return std::nullopt;
  }
  if (a.planeAxis >= 0 || b.planeAxis >= 0) {
    const Leaf& plane = a.planeAxis >= 0 ? a : b;
    const Leaf& box = a.planeAxis >= 0 ? b : a;
    if (!box.exact) return std::nullopt;
    const int k = plane.planeAxis;
    if (same(box.bounds.lo[k], plane.planeAt) || same(box.bounds.hi[k], plane.planeAt))
      return fmt::format("lie in one plane ({} = {})", axes[k], plane.planeAt);
    return std::nullopt;
  }
  if (a.exact && b.exact) {
    if (auto f = sharedFace(a.bounds, b.bounds))
      return fmt::format("have faces in one plane ({} = {})", axes[f->first], f->second);
    return std::nullopt;
  }
  // Two shapes of one kind with the same bounds (the same sphere written twice).
  if (a.node->element != b.node->element) return std::nullopt;
  for (int k = 0; k < 3; ++k)
    if (!same(a.bounds.lo[k], b.bounds.lo[k]) || !same(a.bounds.hi[k], b.bounds.hi[k]))
      return std::nullopt;
  return std::string("have the same bounding box and may coincide");
}

}  // namespace

void warnCoincidentSurfaces(const Node& csg, PovIssues& issues) {
  std::vector<Leaf> leaves;
  for (size_t i = 0; i < csg.children.size(); ++i)
    collect(*csg.children[i], Mat4(1.0), i, leaves, 0);
  if (leaves.size() > 2000)
    return;  // pairs grow quadratically; large CSG is rare and slow to check
  for (size_t i = 0; i < leaves.size(); ++i)
    for (size_t j = i + 1; j < leaves.size(); ++j) {
      if (leaves[i].operand == leaves[j].operand) continue;
      if (auto what = coincidence(leaves[i], leaves[j])) {
        issues.warning(
            csg.loc,
            fmt::format(
                "<{}>: its operands <{}> ({}) and <{}> ({}) {}: where surfaces coincide POV-Ray "
                "takes one or the other pixel by pixel (speckles), Lucent decides by its rule "
                "for coincident surfaces (docs/csg.md), so the images differ there",
                csg.element, leaves[i].node->element, leaves[i].node->loc.str(),
                leaves[j].node->element, leaves[j].node->loc.str(), *what));
        return;
      }
    }
}

}  // namespace lucent
