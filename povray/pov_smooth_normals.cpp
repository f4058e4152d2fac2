#include "pov_smooth_normals.h"

#include "primitives/triangle_mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

// Why any deviation counts: for a viewer direction v the two rules differ where
// v·ng > 0 > v·ns, and such a v exists for every ns that is not along ng; the directions
// form a wedge beside the triangle's plane, as wide as the angle between ns and ng. The
// interpolated normal is a convex combination of the vertex normals, and the set of
// directions within an angle below 90 degrees of ng is a convex cone, so the largest
// deviation below 90 degrees over the triangle is at a corner. Below this angle the wedge
// is too thin to matter, and rounding (normals written to 6 digits, computed normals of
// flat regions) must not warn.
constexpr double kNegligible = 1e-3;  // radians, about 0.06 degrees

std::string degrees(double radians) { return fmt::format("{:.1f} degrees", radians * 180.0 / kPi); }

}  // namespace

double smoothNormalDeviation(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n) {
  const Vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double area = glm::length(cross);
  if (!(area > 0.0) || !std::isfinite(area)) return 0.0;  // never hit (isDegenerateTriangle)
  const Vec3 ng = cross / area;
  bool front = false, back = false;
  double smallestCos = 1.0;
  for (const Vec3& v : n) {
    const double length = glm::length(v);
    if (!(length > 0.0)) continue;  // no normal there: that corner adds nothing
    const double c = glm::dot(v / length, ng);
    front |= c > 0.0;
    back |= c < 0.0;
    smallestCos = std::min(smallestCos, std::abs(c));
  }
  if (front && back) return kPi / 2;
  return std::acos(std::clamp(smallestCos, 0.0, 1.0));
}

void warnSmoothNormalRule(const Node& node, PovIssues& issues) {
  if (!node.shape) return;
  double worst = 0.0;
  std::string what;
  if (const auto* t = std::get_if<TriangleSpec>(&*node.shape)) {
    if (!t->normals) return;
    worst = smoothNormalDeviation({t->a, t->b, t->c}, *t->normals);
    what = "<triangle>";
  } else if (const auto* m = std::get_if<MeshSpec>(&*node.shape)) {
    if (!m->data || m->smooth == SmoothMode::False) return;
    // The normals the renderer uses (scenegraph/shapes/mesh.cpp).
    const MeshData& data = *m->data;
    const std::vector<Vec3> normals =
        m->smooth == SmoothMode::True ? computeVertexNormals(data) : data.normals;
    if (normals.size() != data.positions.size()) return;
    for (const auto& tri : data.triangles)
      worst = std::max(worst,
                       smoothNormalDeviation(
                           {data.positions[tri[0]], data.positions[tri[1]], data.positions[tri[2]]},
                           {normals[tri[0]], normals[tri[1]], normals[tri[2]]}));
    what = m->src.empty() ? "<mesh>" : fmt::format("<mesh src=\"{}\">", m->src);
  } else {
    return;
  }
  if (worst <= kNegligible) return;
  issues.warning(
      node.loc,
      fmt::format("{}: its vertex normals depart from the faces' normals by {} {}: near "
                  "silhouettes, where an interpolated normal faces away from the viewer "
                  "while its triangle faces it, Lucent shades with the triangle's normal "
                  "and POV-Ray 3.7 turns the interpolated normal towards the viewer, so "
                  "POV-Ray's image can show thin dark slivers there (docs/scene-language.md, "
                  "For POV-Ray users)",
                  what, worst >= kPi / 2 ? "at least" : "up to", degrees(worst)));
}

}  // namespace lucent
