// The fisheye camera: the angle from the view axis maps to the distance from the image
// centre. XML:
//   <camera type="fisheye" fov="180" fov-axis="horizontal" mapping="equidistant"/>
// The image circle is centred on the image and its diameter spans the image along
// fov-axis: the full width (horizontal, the default), the full height (vertical) or the
// diagonal (so the circle reaches the corners: a "full-frame" fisheye). `fov` (up to 360)
// is the angle across that diameter, so the rim is fov/2 off the axis; at 360 the rim looks
// straight back. With r = distance from the centre / circle radius (0..1):
//   equidistant: theta = r * fov/2                      (r proportional to theta)
//   equisolid:   theta = 2 asin(r sin(fov/4))           (r proportional to sin(theta/2):
//                equal areas of the image see equal solid angles)
// The direction's azimuth is the pixel's angle about the centre (right = +right, up = +up).
// Points outside the circle have no ray and get the background.
#pragma once

#include "projection.h"

namespace lucent {

class FisheyeProjection final : public Projection {
 public:
  FisheyeProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // The image circle's radius in pixels, and the angle from the axis (radians) at the
  // normalised radius r in [0, 1].
  double circleRadius() const { return radius_; }
  double angleAt(double r) const;

 private:
  FisheyeMapping mapping_;
  double radius_;   // pixels
  double halfFov_;  // radians
  double sinQuarterFov_;
};

}  // namespace lucent
