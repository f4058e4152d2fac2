// Constructive solid geometry: union, merge, intersection and difference of solids.
#pragma once

#include "primitives/bvh.h"
#include "primitives/shape.h"

#include <memory>
#include <vector>

namespace lucent {

enum class CsgOp { Union, Merge, Intersection, Difference };

// How a CSG node finds the children a ray may meet. EveryChild exists only so that
// bench/csg_children can measure what the BVH saves; scenes always use Tree.
enum class CsgSearch { Tree, EveryChild };

const char* csgOpName(CsgOp op);

// Children live in world space already (the scene builder composes every transform down
// to the leaves), so a CSG node never transforms rays itself and every hit it returns
// names a leaf Instance in hit.shape. Difference is the first child minus all the others.
// The children with a finite box sit in a BVH: crossings are gathered only from children
// whose box the ray overlaps, and a union's closest hit is a front-to-back BVH search.
class CsgNode final : public Shape {
 public:
  CsgNode(CsgOp op, std::vector<std::unique_ptr<Shape>> children,
          CsgSearch search = CsgSearch::Tree);

  const char* kind() const override { return csgOpName(op_); }
  AABB bounds() const override { return bounds_; }
  // Each child's boundsWithin: a union's joined, an intersection's met (so that a child
  // unbounded alone is bounded by the others), a difference's first child's.
  AABB boundsWithin(const AABB& clip) const override;
  bool isSolid() const override { return solid_; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  // Never called: hits name the leaf in hit.shape, and the leaf answers.
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  size_t triangleCount() const override;

  CsgOp op() const { return op_; }
  const std::vector<std::unique_ptr<Shape>>& children() const { return children_; }

 private:
  CsgOp op_;
  std::vector<std::unique_ptr<Shape>> children_;
  AABB bounds_;
  bool solid_;
  CsgSearch search_;
  Bvh bvh_;                          // over the children with a finite (or empty) box
  std::vector<uint32_t> slotChild_;  // the child index of each BVH leaf slot
  std::vector<uint32_t> unbounded_;  // the other children, tested one by one

  // Calls visit(childIndex) for every child whose box the ray overlaps.
  template <class Visit>
  void forEachCandidate(const Ray& ray, Visit&& visit) const;
  // Closest hit over the children, as a union sees them.
  bool closestChildHit(const Ray& ray, Hit& hit) const;
};

}  // namespace lucent
