// The thin-lens camera: Gaussian thin-lens depth of field (pbrt-v4's PerspectiveCamera with
// a lens radius; Kolb, Mitchell, Hanrahan 1995). XML:
//   <camera type="thin-lens" fov="60" fov-axis="horizontal"
//           focal-length="0.05" f-stop="8" focus-distance="0"/>
// Framed exactly like the pinhole camera (fov across fov-axis). The aperture is a disc of
// diameter focal-length / f-stop in the camera plane, centred on the position; points on
// the focus plane (perpendicular to the view direction, focus-distance in front of the
// position; 0 = the distance from position to look-at) are sharp. focal-length only sizes
// the aperture: the field of view comes from fov.
#pragma once

#include "projection.h"

namespace lucent {

class ThinLensProjection final : public Projection {
 public:
  ThinLensProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  // lens in [0,1)^2 is mapped onto the aperture disc with the concentric map, so
  // well-stratified lens samples stay well stratified on the disc.
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  double apertureRadius() const { return apertureRadius_; }
  double focusDistance() const { return focusDistance_; }

 private:
  double halfWidth_, halfHeight_;
  double apertureRadius_, focusDistance_;
};

// Shirley and Chiu's concentric map of the unit square onto the unit disc ("A Low
// Distortion Map Between Disk and Square", 1997): area-preserving, low distortion.
Vec2 concentricDisc(const Vec2& u);

}  // namespace lucent
