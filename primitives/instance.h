// A leaf shape placed in the world: the shape, its transform and an opaque tag.
#pragma once

#include "shape.h"
#include "test_counts.h"
#include "transform.h"

#include <cstdint>
#include <memory>

namespace lucent {

// Rays are carried into object space (never the shape into world space); hit distances
// stay in world units because the direction is not renormalised; normals come back with
// the inverse-transpose. Many instances may share one shape (a mesh used many times).
// The tag is the scene's business (scenegraph/'s index of the leaf); primitives never read
// it, but hand it on in every hit (Hit::tag), so the scene finds what it knows of the leaf
// without a cast.
class Instance final : public Shape {
 public:
  // `testSlot`: what --stats counts a test of this instance as (test_counts.h).
  Instance(std::shared_ptr<const Shape> shape, const Transform& worldFromObject, uint32_t tag,
           size_t testSlot = kOtherTestSlot);

  const char* kind() const override { return shape_->kind(); }
  AABB bounds() const override { return bounds_; }
  // The shape's boundsWithin, asked with the clip carried into object space.
  AABB boundsWithin(const AABB& clip) const override;
  bool isSolid() const override { return shape_->isSolid(); }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    return surface(ray, hit, false);
  }
  // With `mappedUV`, also POV-Ray's (u, v) (SurfaceInfo::mappedUV): the shape's povUV, or
  // where it has none the world point's x and y, as POV-Ray's default UVCoord.
  SurfaceInfo surface(const Ray& ray, const Hit& hit, bool mappedUV) const;
  size_t triangleCount() const override { return shape_->triangleCount(); }

  const Shape& shape() const { return *shape_; }
  const std::shared_ptr<const Shape>& sharedShape() const { return shape_; }
  const Transform& transform() const { return placed_ ? placed_->transform : kIdentity; }
  uint32_t tag() const { return tag_; }

  // A world may answer ray tests for this leaf with its own copy of it carried into world
  // space (World does so for spheres under a similarity transform, which stay spheres),
  // instead of carrying each ray into object space. The copy differs from the exact image
  // of the leaf by rounding; `distance` (world units) bounds that difference, and
  // surface() adds it to every component of pError, so that the origins of secondary rays
  // clear the copy as well as the leaf. Only for a transform other than the identity (a
  // copy under the identity is the leaf itself); 0 by default.
  void widenSurfaceError(double distance);

 private:
  Ray toObject(const Ray& ray) const;

  static const Transform kIdentity;

  // A transform other than the identity, with what widenSurfaceError() added.
  struct Placement {
    Transform transform;
    double surfaceError = 0.0;
  };

  // The members a ray test reads come first, in the object's first cache line. The
  // transform is held apart and only when it is not the identity (most instances: spheres
  // are placed by their center), so an instance takes about 90 bytes instead of 420: a
  // field of a million spheres then fits caches and pages far better.
  std::shared_ptr<const Shape> shape_;
  uint32_t tag_;
  uint8_t testSlot_;
  AABB bounds_;
  std::unique_ptr<Placement> placed_;  // null: the identity
};

}  // namespace lucent
