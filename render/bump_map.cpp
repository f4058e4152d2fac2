#include "bump_map.h"

#include "image_projection.h"

#include <cmath>

namespace lucent {

float bumpGrey(const Color& c) {
  return static_cast<float>(0.297 * c.r + 0.589 * c.g + 0.114 * c.b);
}

namespace {

// POV-Ray's bent normal from the three grey levels (bump_map.h, bumpMapNormal).
Vec3 normalFromGreys(float amount, float g1, float g2, float g3, const Vec3& n) {
  const double y1 = static_cast<double>(amount * g1);
  const double y2 = static_cast<double>(amount * g2);
  const double y3 = static_cast<double>(amount * g3);
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

// One step of POV-Ray's neighbour wrap: back into [0, limit) from just outside it.
double wrapOnce(double x, double limit) { return x < 0.0 ? x + limit : x >= limit ? x - limit : x; }

}  // namespace

Vec3 bumpMapNormal(const ImageMap& map, double depth, const Vec2& uv, const Vec3& n) {
  const double w = map.width(), h = map.height();
  const double x = uv.x * w, y = (1.0 - uv.y) * h;
  // The sampler repeats the image, so the neighbours need no wrapping of their own.
  return normalFromGreys(static_cast<float>(depth), bumpGrey(map.lookupPixel(x, y)),
                         bumpGrey(map.lookupPixel(x - 1.0, y + 1.0)),
                         bumpGrey(map.lookupPixel(x + 1.0, y + 1.0)), n);
}

Vec3 bumpMapNormalAt(const Image& pixels, double depth, const Vec2& xy,
                     ImageInterpolation interpolation, bool once, const Vec3& n,
                     const ImageValueGrid* indices) {
  auto grey = [&](double x, double y) {
    return bumpGrey(sampleImage(pixels, Vec2(x, y), interpolation, once, {}).rgb);
  };
  const double w = pixels.width, h = pixels.height;
  const double x2 = wrapOnce(xy.x - 1.0, w), y2 = wrapOnce(xy.y + 1.0, h);
  const double x3 = wrapOnce(x2 + 2.0, w);
  if (indices) {
    auto index = [&](double x, double y) {
      return samplePaletteIndex(*indices, Vec2(x, y), interpolation, once);
    };
    const int i1 = index(xy.x, xy.y), i2 = index(x2, y2), i3 = index(x3, y2);
    if (i1 != -1 && i2 != -1 && i3 != -1)
      return normalFromGreys(static_cast<float>(depth), static_cast<float>(i1),
                             static_cast<float>(i2), static_cast<float>(i3), n);
  }
  return normalFromGreys(static_cast<float>(depth), grey(xy.x, xy.y), grey(x2, y2), grey(x3, y2),
                         n);
}

}  // namespace lucent
