#include "panoramic.h"

#include <cmath>

namespace lucent {

bool PanoramicProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  const double lon = (1.0 - film.x / width_) * kPi;
  const double lat = (0.5 - film.y / height_) * kPi;
  // At the very top and bottom edges tan(lat) is huge (or exactly +-90 degrees): the ray
  // looks along up, as POV-Ray's (which takes a huge number there).
  const double rise =
      std::abs(0.5 * kPi - std::abs(lat)) < 1e-10 ? std::copysign(1e30, lat) : std::tan(lat);
  const Vec3 local(std::cos(lon) * rightLength_, rise * upLength_, std::sin(lon));
  ray = primaryRay(frame_.origin, glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
