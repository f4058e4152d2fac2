#include "orthographic.h"

#include <fmt/core.h>

namespace lucent {

OrthographicProjection::OrthographicProjection(const CameraFrame& frame, const Camera& camera,
                                               int width, int height)
    : Projection(frame, camera, width, height), plane_(camera.imagePlane) {
  if (!(camera.width > 0.0) || !std::isfinite(camera.width))
    throw LocatedError(
        camera.loc, fmt::format("an orthographic camera needs a width > 0 (got {})", camera.width));
  halfWidth_ = 0.5 * camera.width;
  double w = 0.0, h = 0.0;
  frameProportions(camera, width, height, w, h);
  halfHeight_ = halfWidth_ * h / w;
}

bool OrthographicProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  double sx = 2.0 * film.x / width_ - 1.0;
  double sy = 1.0 - 2.0 * film.y / height_;
  if (plane_) {
    const Vec3 offset = frame_.toWorld(0.5 * (sx * plane_->right + sy * plane_->up));
    ray = primaryRay(frame_.origin + offset, frame_.forward);
    return true;
  }
  Vec3 origin = frame_.origin + (sx * halfWidth_) * frame_.right + (sy * halfHeight_) * frame_.up;
  ray = primaryRay(origin, frame_.forward);
  return true;
}

}  // namespace lucent
