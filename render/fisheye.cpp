#include "fisheye.h"

#include <fmt/core.h>

namespace lucent {

FisheyeProjection::FisheyeProjection(const CameraFrame& frame, const Camera& camera, int width,
                                     int height)
    : Projection(frame, camera, width, height), mapping_(camera.mapping) {
  if (!(camera.fov > 0.0 && camera.fov <= 360.0))
    throw LocatedError(
        camera.loc,
        fmt::format("a fisheye camera needs 0 < fov <= 360 degrees (got {})", camera.fov));
  switch (camera.fovAxis) {
    case FovAxis::Horizontal:
      radius_ = 0.5 * width;
      break;
    case FovAxis::Vertical:
      radius_ = 0.5 * height;
      break;
    case FovAxis::Diagonal:
      radius_ = 0.5 * std::hypot(double(width), double(height));
      break;
  }
  halfFov_ = 0.5 * radians(camera.fov);
  sinQuarterFov_ = std::sin(0.5 * halfFov_);
}

double FisheyeProjection::angleAt(double r) const {
  if (mapping_ == FisheyeMapping::Equidistant) return r * halfFov_;
  // Equisolid: image radius = 2 f sin(theta/2); the rim (r = 1) is at theta = fov/2, so
  // 2f = R / sin(fov/4) and theta = 2 asin(r sin(fov/4)).
  return 2.0 * std::asin(std::min(1.0, r * sinQuarterFov_));
}

bool FisheyeProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  double px = film.x - 0.5 * width_;
  double py = 0.5 * height_ - film.y;  // +y up
  double r = std::hypot(px, py) / radius_;
  if (r > 1.0) return false;
  double theta = angleAt(r);
  double phi = std::atan2(py, px);
  double s = std::sin(theta);
  Vec3 local(s * std::cos(phi), s * std::sin(phi), std::cos(theta));
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
