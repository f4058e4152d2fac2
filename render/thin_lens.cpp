#include "thin_lens.h"

#include "pinhole.h"

#include <fmt/core.h>

namespace lucent {

Vec2 concentricDisc(const Vec2& u) {
  Vec2 p = 2.0 * u - Vec2(1.0);
  if (p.x == 0.0 && p.y == 0.0) return Vec2(0.0);
  double r, theta;
  if (std::abs(p.x) > std::abs(p.y)) {
    r = p.x;
    theta = (kPi / 4.0) * (p.y / p.x);
  } else {
    r = p.y;
    theta = kPi / 2.0 - (kPi / 4.0) * (p.x / p.y);
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}

ThinLensProjection::ThinLensProjection(const CameraFrame& frame, const Camera& camera, int width,
                                       int height)
    : Projection(frame, camera, width, height) {
  if (!(camera.fov > 0.0 && camera.fov < 180.0))
    throw LocatedError(
        camera.loc,
        fmt::format("a thin-lens camera needs 0 < fov < 180 degrees (got {})", camera.fov));
  if (!(camera.focalLength > 0.0) || !(camera.fStop > 0.0) || !(camera.focusDistance >= 0.0))
    throw LocatedError(
        camera.loc,
        "a thin-lens camera needs focal-length > 0, f-stop > 0 and focus-distance >= 0");
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  imagePlaneHalfExtents(camera.fov, camera.fovAxis, w, h, halfWidth_, halfHeight_);
  // Aperture diameter = focal length / f-number (the definition of the f-number); an
  // infinite f-stop closes the lens to a pinhole.
  apertureRadius_ = 0.5 * camera.focalLength / camera.fStop;
  focusDistance_ = camera.focusDistance > 0.0 ? camera.focusDistance : frame.lookDistance;
}

bool ThinLensProjection::generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const {
  double sx = 2.0 * film.x / width_ - 1.0;
  double sy = 1.0 - 2.0 * film.y / height_;
  // The pinhole ray through the lens centre meets the focus plane at focusDistance x this
  // (relative to the position); every ray through the aperture for this film point passes
  // through that point (the thin-lens equation). Relative vectors keep the direction exact
  // far from the origin.
  Vec3 toFocus = focusDistance_ * frame_.toWorld(Vec3(sx * halfWidth_, sy * halfHeight_, 1.0));
  Vec2 disc = apertureRadius_ * concentricDisc(lens);
  Vec3 offset = disc.x * frame_.right + disc.y * frame_.up;
  ray = primaryRay(frame_.origin + offset, glm::normalize(toFocus - offset));
  return true;
}

}  // namespace lucent
