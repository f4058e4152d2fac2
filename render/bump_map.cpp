#include "bump_map.h"

#include <cmath>

namespace lucent {

float bumpGrey(const Color& c) {
  return static_cast<float>(0.297 * c.r + 0.589 * c.g + 0.114 * c.b);
}

Vec3 bumpMapNormal(const ImageMap& map, double depth, const Vec2& uv, const Vec3& n) {
  const double w = map.width(), h = map.height();
  const double x = uv.x * w, y = (1.0 - uv.y) * h;
  const float amount = static_cast<float>(depth);
  // The sampler repeats the image, so the neighbours need no wrapping of their own.
  const double y1 = static_cast<double>(amount * bumpGrey(map.lookupPixel(x, y)));
  const double y2 = static_cast<double>(amount * bumpGrey(map.lookupPixel(x - 1.0, y + 1.0)));
  const double y3 = static_cast<double>(amount * bumpGrey(map.lookupPixel(x + 1.0, y + 1.0)));
  const Vec3 p1(0.0, y1, 0.0), p2(-1.0, y2, 1.0), p3(1.0, y3, 1.0);
  const Vec3 b = glm::normalize(glm::cross(p3 - p2, p1 - p2));

  Vec3 yAxis = n;
  Vec3 xAxis = glm::cross(n, Vec3(0.0, 1.0, 0.0));
  double length = glm::length(xAxis);
  if (length < 1e-10) {  // POV-Ray's EPSILON
    yAxis = std::fabs(n.y - 1.0) < 1e-10 ? Vec3(0.0, 1.0, 0.0) : Vec3(0.0, -1.0, 0.0);
    xAxis = Vec3(1.0, 0.0, 0.0);
    length = 1.0;
  }
  xAxis /= length;
  const Vec3 zAxis = glm::normalize(glm::cross(xAxis, yAxis));
  return glm::normalize(b.x * xAxis + b.y * yAxis - b.z * zAxis);
}

}  // namespace lucent
