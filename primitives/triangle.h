// <triangle a="0 0 0" b="1 0 0" c="0 1 0" na="..." nb="..." nc="..."/>
//   a, b, c     vectors, the corners (defaults 0 0 0, 1 0 0, 0 1 0)
//   na, nb, nc  optional vertex normals (all three or none), normalised on load
// A single flat triangle: not a solid. The geometric normal is (b − a) × (c − a)
// (counter-clockwise seen from its front), turned to the side of the shading normal when
// vertex normals are given (as pbrt does: for a loose triangle only the user's normals say
// which side is the front). The shading normal interpolates the vertex normals with the
// barycentric coordinates and is normalised again (POV-Ray's smooth_triangle). No (u,v).
// A triangle of zero area (its area lost in rounding) is never hit.
// Hit::b1, Hit::b2 are the barycentric weights of b and c.
#pragma once

#include "shape.h"

#include <array>
#include <optional>

namespace lucent {

class Triangle final : public Shape {
 public:
  Triangle(const Vec3& a, const Vec3& b, const Vec3& c,
           const std::optional<std::array<Vec3, 3>>& normals = std::nullopt);

  const char* kind() const override { return "triangle"; }
  AABB bounds() const override;
  bool isSolid() const override { return false; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3&) const override { return false; }
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  size_t triangleCount() const override { return 1; }

 private:
  bool root(const Ray& ray, double& t, double& b1, double& b2) const;

  std::array<Vec3, 3> p_;
  std::optional<std::array<Vec3, 3>> n_;
  bool degenerate_;
};

}  // namespace lucent
