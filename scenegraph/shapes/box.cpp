// <box min="-1 -1 -1" max="1 1 1"/>: a solid axis-aligned box (primitives/box.h).
#include "scenegraph/shape_type.h"

#include "primitives/box.h"

#include <fmt/format.h>

namespace lucent {

namespace {

// Each face takes its own copy of the image, placed on the face's [0,1]² square as
// primitives/box.cpp computes (u, v): frac(i, fromMax) is the position along axis i across
// the box, measured from its min side or (fromMax) its max side.
std::vector<ImageMapFace> imageMapFaces(const BoxSpec& box) {
  const Vec3 lo = glm::min(box.min, box.max), hi = glm::max(box.min, box.max);
  const Vec3 e = hi - lo;
  auto frac = [&](int i, bool fromMax) {
    Vec4 row(0.0);  // row·(p, 1)
    if (!(e[i] > 0.0)) return row;
    row[i] = fromMax ? -1.0 / e[i] : 1.0 / e[i];
    row[3] = fromMax ? hi[i] / e[i] : -lo[i] / e[i];
    return row;
  };
  std::vector<ImageMapFace> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const bool maxSide = side == 1;
      Vec4 u, v;
      if (axis == 0) {  // ±x: right is ∓z, up is +y
        u = frac(2, maxSide);
        v = frac(1, false);
      } else if (axis == 1) {  // +y: right +x, up −z; −y: right +x, up +z
        u = frac(0, false);
        v = frac(2, maxSide);
      } else {  // ±z: right is ±x, up is +y
        u = frac(0, !maxSide);
        v = frac(1, false);
      }
      Vec4 w(0.0);
      w[axis] = 1.0;
      ImageMapFace f;
      f.normal[axis] = maxSide ? 1.0 : -1.0;
      f.offset = maxSide ? hi[axis] : -lo[axis];
      f.mapping.kind = ImageMapping::Planar;
      f.mapping.uvFromObject = rowsMatrix(u, v, w);
      faces.push_back(f);
    }
  }
  return faces;
}

}  // namespace

template <>
ShapeEntry<BoxSpec> shapeEntry<BoxSpec>() {
  ShapeEntry<BoxSpec> e(
      "box", "boxes", [](const BoxSpec& s) { return std::make_shared<Box>(s.min, s.max); },
      [](const BoxSpec& s, PovShapeOut& out) {
        out.open("box");
        out.line(fmt::format("{}, {}", out.vector(s.min), out.vector(s.max)));
      });
  e.doc = "An axis-aligned box from min to max (solid).";
  e.fields = {vectorField("min", &BoxSpec::min).doc("Minimum corner."),
              vectorField("max", &BoxSpec::max)
                  .doc("Maximum corner: each coordinate must be above min's.")};
  e.finish = [](BoxSpec& b, AttributeInput& in) {
    for (int k = 0; k < 3; ++k)
      if (!(b.min[k] < b.max[k])) {
        in.attrError(in.has("max") ? "max" : "min",
                     fmt::format("'min' must be below 'max' in every coordinate, but {} {} >= {}",
                                 "xyz"[k], b.min[k], b.max[k]));
        break;
      }
  };
  e.povImageFaces = imageMapFaces;
  e.samples = [] {
    return std::vector<std::pair<std::string, BoxSpec>>{
        {"box", {Vec3(-1, -0.5, 0), Vec3(1, 2, 3)}},
        {"thin box", {Vec3(-1, -1e-3, -1), Vec3(1, 1e-3, 1)}}};
  };
  return e;
}

}  // namespace lucent
