#include "ultra_wide_angle.h"

#include <cmath>

namespace lucent {

UltraWideAngleProjection::UltraWideAngleProjection(const CameraFrame& frame, const Camera& camera,
                                                   int width, int height)
    : Projection(frame, camera, width, height) {
  double across = 0.0, down = 0.0;
  ultraWideAngles(camera, width, height, across, down);
  across_ = radians(across);
  down_ = radians(down);
}

bool UltraWideAngleProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  const double x = (film.x / width_ - 0.5) * across_;
  const double y = (0.5 - film.y / height_) * down_;
  const Vec3 local(std::sin(x), std::sin(y), std::cos(x) * std::cos(y));
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
