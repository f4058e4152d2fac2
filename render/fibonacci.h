// The Fibonacci camera: n = width x height directions spread uniformly over the sphere, one
// per pixel. XML:
//   <camera type="fibonacci"/>
// Pixel (x, y) is point k = y * width + x (row-major) of the spherical Fibonacci set of n
// points in direction_maps.h: k = 0 (top-left pixel) looks almost straight up, the last
// pixel almost straight down, and the height along camera up falls by 2/n per pixel.
// Every sample of a pixel has the same ray, so supersampling has no effect. fov is not used.
// filmPosition()/pixel() invert generateRay(): the pixel of a direction is the one whose
// point is nearest (its Voronoi cell), for reading the image back as a probe.
#pragma once

#include "projection.h"

#include <glm/vec2.hpp>

#include <cstdint>

namespace lucent {

class FibonacciProjection final : public Projection {
 public:
  FibonacciProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  uint64_t pointCount() const { return n_; }
  // Pixel -> direction: the unit world direction of point k, or of the pixel at film.
  Vec3 direction(uint64_t k) const;
  Vec3 direction(const Vec2& film) const;
  // Direction -> pixel: the nearest point's index and its pixel.
  uint64_t index(const Vec3& worldDirection) const;
  glm::ivec2 pixel(const Vec3& worldDirection) const;

 private:
  uint64_t n_;
};

}  // namespace lucent
