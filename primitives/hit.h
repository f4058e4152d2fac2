// What a ray search returns (small, found per candidate) and the surface geometry that is
// computed once, for the winning hit only (pbrt's two phases).
#pragma once

#include "math.h"

#include <cstdint>

namespace lucent {

class Shape;

// Found during the search: only the distance and a small shape-specific payload.
struct Hit {
  double t = kInf;
  const Shape* shape = nullptr;  // the leaf that was hit: its surface() gives the geometry
  uint32_t part = 0;             // shape-specific: face, cap or side, triangle index, ...
  // The tag of the Instance hit (Instance::tag), set by it. Beside `part`, in what was
  // padding: a Hit is no larger, and a new one zeroes both in one store.
  uint32_t tag = 0;
  double b1 = 0.0, b2 = 0.0;  // shape-specific: barycentrics, local coordinates, ...
  bool flip = false;          // set by CSG: a subtracted surface, its normal faces out

  bool found() const { return shape != nullptr; }
};

// The geometry at a hit, computed once for the winner.
struct SurfaceInfo {
  Vec3 p{0.0};             // hit point
  Vec3 pError{0.0};        // absolute rounding-error bound of p, per component
  Vec3 ng{0.0, 1.0, 0.0};  // unit geometric normal, outward for solids (flipped by Hit::flip)
  Vec3 ns{0.0, 1.0, 0.0};  // unit shading normal (interpolated normals), same side as ng
  Vec2 uv{0.0};
  bool hasUV = false;
  // POV-Ray's (u, v) (Shape::povUV, or the world x and y on shapes without), which
  // mapping="uv" reads; filled in by Instance only when the leaf's material asks for it.
  Vec2 mappedUV{0.0};
  bool hasMappedUV = false;
  Vec3 pObject{0.0};  // hit point in the leaf's object space, filled in by Instance
};

}  // namespace lucent
