// The panoramic camera, POV-Ray 3.7's `panoramic` (after Graphics Gems III). XML:
//   <camera type="panoramic" right-length="1" up-length="1"/>
// Longitude lon runs from 180 degrees at the left edge to 0 at the right, latitude lat from
// -90 at the bottom edge to 90 at the top; the ray goes along
//   cos(lon) right-length right + tan(lat) up-length up + sin(lon) forward
// (normalised): 180 degrees across on a cylinder, tan(latitude) up it, so the top and
// bottom rows look straight up and down. Every pixel has a ray.
#pragma once

#include "projection.h"

namespace lucent {

class PanoramicProjection final : public Projection {
 public:
  PanoramicProjection(const CameraFrame& frame, const Camera& camera, int width, int height)
      : Projection(frame, camera, width, height),
        rightLength_(camera.rightLength),
        upLength_(camera.upLength) {}
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

 private:
  double rightLength_, upLength_;
};

}  // namespace lucent
