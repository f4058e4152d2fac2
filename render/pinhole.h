// The pinhole camera: rectilinear perspective through one point.
#pragma once

#include "projection.h"

namespace lucent {

// The image plane sits at distance 1 along the view direction; `fov` spans its full width
// (fov-axis horizontal, the default), height (vertical) or diagonal. The other extents
// follow from the image's aspect ratio, so pixels are square.
class PinholeProjection final : public Projection {
 public:
  PinholeProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // Half extents of the image plane at distance 1 (tan of the half field of view).
  double halfWidth() const { return halfWidth_; }
  double halfHeight() const { return halfHeight_; }

 private:
  double halfWidth_, halfHeight_;
};

// Half extents at distance 1 of an image of width x height whose `fov` (degrees) spans
// the given axis. Shared by the projections that have a rectilinear image plane (a
// lenslet camera's cells, of fractional sizes, too).
void imagePlaneHalfExtents(double fovDegrees, FovAxis axis, double width, double height,
                           double& halfWidth, double& halfHeight);

}  // namespace lucent
