// clipped_by (POV-Ray's clip): a shape whose surface is kept only where it lies inside
// every clipping solid. The result is an open shell: the cut is not closed by the clip's
// surface, so a ray entering through it sees the inside of the shape. As in POV-Ray, a
// point is inside a clipped solid when it is inside the clips and inside the shape, so in
// CSG the clipped solid counts as the shape cut by its clips; its crossings where a clip
// cuts it are marked hidden (Crossing::hidden): they bound the result but show nothing.
#pragma once

#include "primitives/shape.h"

#include <memory>
#include <vector>

namespace lucent {

class Clipped final : public Shape {
 public:
  // `shape` and `clips` in world space, as a CSG node's children; every clip is a solid.
  // `within`: a world box known to hold the clips' common part (found where their boxes
  // are tighter than in the world's frame: scenegraph/flatten.cpp).
  Clipped(std::unique_ptr<Shape> shape, std::vector<std::unique_ptr<Shape>> clips,
          const AABB& within = AABB::everything());

  const char* kind() const override { return shape_->kind(); }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return shape_->isSolid(); }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override { return inClips(p) && shape_->inside(p); }
  // Never called: hits name the leaf in hit.shape, and the leaf answers.
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override {
    return shape_->surface(ray, hit);
  }
  size_t triangleCount() const override { return shape_->triangleCount(); }

  const Shape& shape() const { return *shape_; }

 private:
  std::unique_ptr<Shape> shape_;
  std::vector<std::unique_ptr<Shape>> clips_;
  AABB bounds_;

  bool inClips(const Vec3& p) const;
  // The shape's first hit in the ray's range whose point is inside the clips.
  bool firstKept(const Ray& ray, Hit& hit) const;
};

}  // namespace lucent
