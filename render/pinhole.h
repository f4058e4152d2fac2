// The pinhole camera: rectilinear perspective through one point.
#pragma once

#include "projection.h"

#include <optional>

namespace lucent {

// The image plane sits at distance 1 along the view direction; `fov` spans its full width
// (fov-axis horizontal, the default), height (vertical) or diagonal. The other extents
// follow from the image's aspect ratio, so pixels are square. A camera's image-plane gives
// the plane's half extents as vectors instead, for a frame that is not a rectangle.
class PinholeProjection final : public Projection {
 public:
  PinholeProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // Half extents of the image plane at distance 1 (tan of the half field of view).
  double halfWidth() const { return halfWidth_; }
  double halfHeight() const { return halfHeight_; }

 private:
  double halfWidth_, halfHeight_;
  std::optional<Vec3> halfRight_, halfUp_;  // image-plane / 2, camera space
};

// Half extents at distance 1 of an image of width x height whose `fov` (degrees) spans
// the given axis. Shared by the projections that have a rectilinear image plane (a
// lenslet camera's cells, of fractional sizes, too).
void imagePlaneHalfExtents(double fovDegrees, FovAxis axis, double width, double height,
                           double& halfWidth, double& halfHeight);

}  // namespace lucent
