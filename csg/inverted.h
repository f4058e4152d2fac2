// inverse="true" (POV-Ray's inverse): a solid with inside and outside swapped. The surface
// is the same; every crossing changes direction (entering becomes leaving), a ray starts
// inside where it started outside, and the normal (Hit::flip, applied by the leaf Instance)
// points into the original solid, which is now the outside. So an intersection with an
// inverted solid is a difference, and a difference with one is an intersection.
#pragma once

#include "primitives/shape.h"

#include <memory>

namespace lucent {

class Inverted final : public Shape {
 public:
  explicit Inverted(std::unique_ptr<Shape> solid);

  const char* kind() const override { return solid_->kind(); }
  // Everything but the original solid: unbounded (a CSG node tests such a child for every
  // ray, so a ray that misses the original is inside the inverse all along).
  AABB bounds() const override { return AABB::everything(); }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override { return solid_->occluded(ray); }
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return !solid_->inside(p); }
  // Never called: hits name the leaf in hit.shape, and the leaf answers.
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    return solid_->surface(ray, hit);
  }
  size_t triangleCount() const override { return solid_->triangleCount(); }

  const Shape& solid() const { return *solid_; }

 private:
  std::unique_ptr<Shape> solid_;
};

}  // namespace lucent
