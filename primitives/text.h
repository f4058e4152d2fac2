// <text>: POV-Ray 3.7's text object, glyph outlines (primitives/text_outline.h) on the
// xy-plane extruded from z = 0 to z = thickness. Each glyph is a linear Prism (prism.h:
// exact per segment, holes by the even-odd rule as POV-Ray's Inside_Glyph counts crossings)
// whose y-extrusion is mapped to z by swapping y and z, which is exact. The glyphs' boxes
// sit in a BVH, so a ray tests only the glyphs whose box it enters; within a glyph the
// Prism examines every segment (it skips the ones wholly on one side of the ray's plane).
// Glyphs that overlap (a negative offset, a strong kerning) are a union: crossings are
// merged by counting how many glyphs the ray is inside.
#pragma once

#include "bvh.h"
#include "prism.h"

#include <memory>
#include <vector>

namespace lucent {

class Text final : public Shape {
 public:
  // One outline per glyph (x, y in the glyph plane); blank glyphs (no contours) are
  // skipped, except that their origins (`blanks`) still extend the box from z = 0 to
  // thickness, as POV-Ray's box of a space does (a trailing space counts in min_extent and
  // max_extent, which shapes.inc's Text_Width measures). Throws std::invalid_argument for a
  // bad outline or a thickness <= 0.
  Text(const std::vector<std::vector<PrismContour>>& glyphs, double thickness,
       const std::vector<Vec2>& blanks = {});

  const char* kind() const override { return "text"; }
  AABB bounds() const override { return bounds_; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;

  size_t glyphCount() const { return glyphs_.size(); }
  size_t segmentCount() const;

 private:
  std::vector<std::unique_ptr<Prism>> glyphs_;
  std::vector<AABB> boxes_;  // in the prisms' space (x, extrusion, y)
  Bvh bvh_;
  AABB bounds_;
};

}  // namespace lucent
