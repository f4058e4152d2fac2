// <box min="-1 -1 -1" max="1 1 1"/>
//   min, max  vectors (opposite corners), defaults -1 -1 -1 and 1 1 1; as in POV-Ray the
//             corners may be given in any order (the box spans their component-wise
//             minimum and maximum).
// A solid axis-aligned box. (u,v): every face has its own [0,1]² square, oriented as the
// face is seen from outside with +y up (for the ±y faces: −z up seen from above, +z up
// seen from below): u grows to the viewer's right, v upwards.
// Hit::part is the face: 2·axis + (1 for the max side, 0 for the min side).
#pragma once

#include "shape.h"
#include "span.h"

namespace lucent {

class Box final : public Shape {
 public:
  // Throws std::invalid_argument for non-finite corners; a flat box is allowed.
  Box(const Vec3& a, const Vec3& b);

  const char* kind() const override { return "box"; }
  AABB bounds() const override { return {lo_, hi_}; }
  bool isSolid() const override { return true; }
  bool intersect(const Ray& ray, Hit& hit) const override;
  void crossings(const Ray& ray, CrossingList& out) const override;
  bool inside(const Vec3& p) const override;
  SurfaceInfo surface(const Ray& ray, const Hit& hit) const override;
  bool povUV(const SurfaceInfo& s, const Hit& hit, Vec2& uv) const override;

  // Count the faces inside, as POV-Ray's Box::Inside does (outside only strictly beyond a
  // face): the rule of an object pattern's boxes. Lucent's own, for CSG, leaves them out.
  void closeFaces() { closedFaces_ = true; }

 private:
  // Where the whole line enters and leaves the box, and through which faces.
  bool span(const Ray& ray, Span& out) const;

  Vec3 lo_, hi_;
  bool closedFaces_ = false;
};

}  // namespace lucent
