// The ultra-wide-angle camera, POV-Ray 3.7's `ultra_wide_angle`. XML:
//   <camera type="ultra-wide-angle" fov="180" fov-axis="horizontal" frame-aspect="0"/>
// (fov-axis diagonal: fov is the diagonal of the flat map of the two angles.)
// With s from -1/2 (left edge) to 1/2 (right edge) and t from -1/2 (bottom) to 1/2 (top),
// x = s * across and y = t * down (the angles of ultraWideAngles(), in radians), the ray
// goes along
//   sin(x) right + sin(y) up + cos(x) cos(y) forward   (then normalised).
// The angles grow evenly along each axis, so fov may reach 360 (the edges look back).
// Every pixel has a ray.
#pragma once

#include "projection.h"

namespace lucent {

class UltraWideAngleProjection final : public Projection {
 public:
  UltraWideAngleProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

 private:
  double across_, down_;  // radians across the width and down the height
};

}  // namespace lucent
