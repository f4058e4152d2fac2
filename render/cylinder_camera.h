// The cylinder camera, POV-Ray 3.7's `cylinder 1` to `cylinder 4`. XML:
//   <camera type="cylinder" cylinder-type="1" sweep="90" axis-length="0"/>
// With s from -1/2 (left edge) to 1/2 (right edge), t from -1/2 (bottom) to 1/2 (top),
// a = sweep in radians and L = cylinderAxisLength() (axis-length, or square pixels at the
// image centre):
//   1: the axis along up through the position; x = s a: from the position along
//      sin(x) right + t L up + cos(x) forward
//   2: the axis along right; y = t a: from the position along
//      s L right + sin(y) up + cos(y) forward
//   3: as 1, but from position + t L up along sin(x) right + cos(x) forward
//   4: as 2, but from position + s L right along sin(y) up + cos(y) forward
// (directions normalised). Every pixel has a ray.
#pragma once

#include "projection.h"

namespace lucent {

class CylinderProjection final : public Projection {
 public:
  CylinderProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

 private:
  int type_;
  double angle_;       // radians about the axis
  double axisLength_;  // along the axis
};

}  // namespace lucent
