// The omnimax camera, POV-Ray 3.7's `omnimax`: a dome-projection lens. XML:
//   <camera type="omnimax" frame-aspect="0"/>
// With u from -1 (left edge) to 1 (right edge), v from -1 (bottom) to 1 (top) and the
// frame's aspect A = width / height (frame-aspect, or the image's):
//   A > 1.283458: u *= A / 1.283458 and v = (v - 1) / 1.283458 + 1;
//   1 < A <= 1.283458: v = (v - 1) / A + 1;   A <= 1: v /= A
// (the circle stands on the frame's top edge when the frame is wide). At r = |(u, v)| the
// angle from the view axis is theta = 1.411269 r - 0.09439 r^3 + 0.25674 r^5, and the ray
// goes along sin(theta) (u right + v up) / r + cos(theta) forward. Points with r > 1, or
// whose ray has up + forward components below 0 (more than 45 degrees below the axis, in
// the plane of up and forward), have no ray and get the background.
#pragma once

#include "projection.h"

namespace lucent {

class OmnimaxProjection final : public Projection {
 public:
  OmnimaxProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

 private:
  double aspect_;
};

}  // namespace lucent
