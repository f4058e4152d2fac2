#include "fibonacci.h"

#include "direction_maps.h"

#include <algorithm>

namespace lucent {

FibonacciProjection::FibonacciProjection(const CameraFrame& frame, const Camera& camera, int width,
                                         int height)
    : Projection(frame, camera, width, height),
      n_(static_cast<uint64_t>(width) * static_cast<uint64_t>(height)) {}

Vec3 FibonacciProjection::direction(uint64_t k) const {
  return glm::normalize(frame_.toWorld(fibonacciDirection(k, n_)));
}

Vec3 FibonacciProjection::direction(const Vec2& film) const {
  int x = std::clamp(static_cast<int>(std::floor(film.x)), 0, width_ - 1);
  int y = std::clamp(static_cast<int>(std::floor(film.y)), 0, height_ - 1);
  return direction(static_cast<uint64_t>(y) * width_ + x);
}

bool FibonacciProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  ray = primaryRay(frame_.origin, direction(film));
  return true;
}

uint64_t FibonacciProjection::index(const Vec3& worldDirection) const {
  return nearestFibonacciIndex(frameLocal(frame_, worldDirection), n_);
}

glm::ivec2 FibonacciProjection::pixel(const Vec3& worldDirection) const {
  uint64_t k = index(worldDirection);
  return glm::ivec2(static_cast<int>(k % width_), static_cast<int>(k / width_));
}

}  // namespace lucent
