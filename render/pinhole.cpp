#include "pinhole.h"

#include <fmt/core.h>

namespace lucent {

void imagePlaneHalfExtents(double fovDegrees, FovAxis axis, double width, double height,
                           double& halfWidth, double& halfHeight) {
  double half = std::tan(radians(fovDegrees) * 0.5);
  const double w = width, h = height;
  switch (axis) {
    case FovAxis::Horizontal:
      halfWidth = half;
      halfHeight = half * h / w;
      break;
    case FovAxis::Vertical:
      halfHeight = half;
      halfWidth = half * w / h;
      break;
    case FovAxis::Diagonal: {
      double diagonal = std::hypot(w, h);
      halfWidth = half * w / diagonal;
      halfHeight = half * h / diagonal;
      break;
    }
  }
}

PinholeProjection::PinholeProjection(const CameraFrame& frame, const Camera& camera, int width,
                                     int height)
    : Projection(frame, camera, width, height) {
  if (!(camera.fov > 0.0 && camera.fov < 180.0))
    throw LocatedError(
        camera.loc,
        fmt::format("a pinhole camera needs 0 < fov < 180 degrees (got {})", camera.fov));
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  imagePlaneHalfExtents(camera.fov, camera.fovAxis, w, h, halfWidth_, halfHeight_);
  if (camera.imagePlane) {
    halfRight_ = 0.5 * camera.imagePlane->right;
    halfUp_ = 0.5 * camera.imagePlane->up;
  }
}

bool PinholeProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  // Screen coordinates in [-1, 1], +y up (film y grows downwards: row 0 is the top).
  double sx = 2.0 * film.x / width_ - 1.0;
  double sy = 1.0 - 2.0 * film.y / height_;
  const Vec3 local = halfRight_ ? Vec3(0.0, 0.0, 1.0) + sx * *halfRight_ + sy * *halfUp_
                                : Vec3(sx * halfWidth_, sy * halfHeight_, 1.0);
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
