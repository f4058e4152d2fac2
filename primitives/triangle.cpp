#include "triangle.h"

#include "span.h"
#include "triangle_geometry.h"
#include "watertight.h"

namespace lucent {

Triangle::Triangle(const Vec3& a, const Vec3& b, const Vec3& c,
                   const std::optional<std::array<Vec3, 3>>& normals)
    : p_{a, b, c}, n_(normals), degenerate_(isDegenerateTriangle(a, b, c)) {}

AABB Triangle::bounds() const {
  AABB box;
  for (const Vec3& p : p_) box.expand(p);
  return box;
}

bool Triangle::root(const Ray& ray, double& t, double& b1, double& b2) const {
  if (degenerate_) return false;
  TriangleIntersection ti;
  if (!intersectTriangle(ShearedRay(ray), p_[0], p_[1], p_[2], ti)) return false;
  t = ti.t;
  b1 = ti.b1;
  b2 = ti.b2;
  return true;
}

bool Triangle::intersect(const Ray& ray, Hit& hit) const {
  SurfaceRoot r;
  return root(ray, r.t, r.b1, r.b2) && intersectRoots(&r, 1, ray, this, hit);
}

void Triangle::crossings(const Ray& ray, CrossingList& out) const {
  SurfaceRoot r;
  int n = root(ray, r.t, r.b1, r.b2) ? 1 : 0;
  crossingsOfRoots(&r, n, ray, this, out);
}

SurfaceInfo Triangle::surface(const Ray&, const Hit& hit) const {
  const Vec3* normals = n_ ? n_->data() : nullptr;
  return triangleSurface(p_.data(), normals, nullptr, hit.b1, hit.b2,
                         /*normalFollowsShading=*/true);
}

}  // namespace lucent
