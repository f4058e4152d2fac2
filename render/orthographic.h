// The orthographic camera: parallel rays, no perspective. XML:
//   <camera type="orthographic" position="0 10 0" look-at="0 0 0" up="0 0 -1" width="12"/>
// Every ray has the view direction; the ray origins fill a rectangle through the position,
// perpendicular to the view, `width` world units across the image (the height follows from
// the aspect ratio, so pixels are square). near/far are measured from that rectangle. A
// camera's image-plane spans a parallelogram of origins instead.
#pragma once

#include "projection.h"

namespace lucent {

class OrthographicProjection final : public Projection {
 public:
  OrthographicProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

 private:
  double halfWidth_, halfHeight_;  // world units
  std::optional<Camera::ImagePlane> plane_;
};

}  // namespace lucent
