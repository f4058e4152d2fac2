#include "octahedral.h"

#include "direction_maps.h"

#include <algorithm>

namespace lucent {

OctahedralProjection::OctahedralProjection(const CameraFrame& frame, const Camera& camera,
                                           int width, int height)
    : Projection(frame, camera, width, height) {}

Vec3 OctahedralProjection::direction(const Vec2& film) const {
  Vec2 uv(film.x / width_, film.y / height_);
  return glm::normalize(frame_.toWorld(octahedralDirection(uv)));
}

bool OctahedralProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  ray = primaryRay(frame_.origin, direction(film));
  return true;
}

Vec2 OctahedralProjection::filmPosition(const Vec3& worldDirection) const {
  Vec2 uv = octahedralUV(frameLocal(frame_, worldDirection));
  return Vec2(uv.x * width_, uv.y * height_);
}

glm::ivec2 OctahedralProjection::pixel(const Vec3& worldDirection) const {
  Vec2 film = filmPosition(worldDirection);
  return glm::ivec2(std::clamp(static_cast<int>(std::floor(film.x)), 0, width_ - 1),
                    std::clamp(static_cast<int>(std::floor(film.y)), 0, height_ - 1));
}

}  // namespace lucent
