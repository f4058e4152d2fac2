// bounded_by as POV-Ray applies it: not a cut of the surface but a test of the ray. An
// object with bounding objects is searched only along rays that meet every one of them
// (anywhere ahead of the ray's start) or start inside it; other rays miss the object
// altogether. When the bounding objects enclose the object this only saves time; when they
// do not, the parts of the object that such rays would meet vanish (POV-Ray 3.7's
// Ray_In_Bound, its top-level bounding box works the same way).
#pragma once

#include "primitives/shape.h"

#include <memory>
#include <vector>

namespace lucent {

class Bounded final : public Shape {
 public:
  // `shape` and `bounds` in world space, as a CSG node's children; every bound is a solid.
  Bounded(std::unique_ptr<Shape> shape, std::vector<std::unique_ptr<Shape>> bounds);

  const char* kind() const override { return shape_->kind(); }
  AABB bounds() const override { return shape_->bounds(); }
  bool isSolid() const override { return shape_->isSolid(); }
  bool intersect(const Ray& ray, Hit& hit) const override {
    return admits(ray) && shape_->intersect(ray, hit);
  }
  bool occluded(const Ray& ray) const override { return admits(ray) && shape_->occluded(ray); }
  // A ray the bounds turn away crosses the solid unseen: its crossings are hidden, so that
  // in CSG the object still counts where it is (POV-Ray's inside test ignores bounds).
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return shape_->inside(p); }
  // Never called: hits name the leaf in hit.shape, and the leaf answers.
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    return shape_->surface(ray, hit);
  }
  size_t triangleCount() const override { return shape_->triangleCount(); }

  // Does the ray meet (or start inside) every bounding object?
  bool admits(const Ray& ray) const;

 private:
  std::unique_ptr<Shape> shape_;
  std::vector<std::unique_ptr<Shape>> bounds_;
};

}  // namespace lucent
