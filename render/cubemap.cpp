#include "cubemap.h"

#include "direction_maps.h"

#include <fmt/core.h>

#include <algorithm>

namespace lucent {

CubemapProjection::CubemapProjection(const CameraFrame& frame, const Camera& camera, int width,
                                     int height)
    : Projection(frame, camera, width, height), layout_(camera.layout) {
  const int cols = cubeLayoutColumns(layout_), rows = cubeLayoutRows(layout_);
  // Whole-pixel faces: a reflection probe must never have a pixel shared by two faces.
  if (width % cols != 0 || height % rows != 0)
    throw LocatedError(
        camera.loc,
        fmt::format("a cubemap camera with layout=\"{}\" needs a width divisible by {} and a "
                    "height divisible by {} (got {}x{}; for square faces use e.g. {}x{})",
                    layout_ == CubemapLayout::Cross ? "cross" : "strip", cols, rows, width, height,
                    cols * 128, rows * 128));
  cellWidth_ = width / cols;
  cellHeight_ = height / rows;
}

bool CubemapProjection::direction(const Vec2& film, Vec3& worldDirection) const {
  Vec3 local;
  if (!cubemapDirection(layout_, Vec2(film.x / width_, film.y / height_), local)) return false;
  worldDirection = glm::normalize(frame_.toWorld(local));
  return true;
}

bool CubemapProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  Vec3 d;
  if (!direction(film, d)) return false;
  ray = primaryRay(frame_.origin, d);
  return true;
}

Vec2 CubemapProjection::filmPosition(const Vec3& worldDirection) const {
  Vec2 uv = cubemapUV(layout_, frameLocal(frame_, worldDirection));
  return Vec2(uv.x * width_, uv.y * height_);
}

glm::ivec2 CubemapProjection::pixel(const Vec3& worldDirection) const {
  CubeFacePoint p = cubeFacePoint(frameLocal(frame_, worldDirection));
  int col = 0, row = 0;
  cubeFaceCell(layout_, p.face, col, row);
  // Clamp inside the face's own cell so a direction on its border never lands on a
  // neighbouring (possibly empty) cell.
  int x = std::clamp(static_cast<int>(std::floor(p.st.x * cellWidth_)), 0, cellWidth_ - 1);
  int y = std::clamp(static_cast<int>(std::floor(p.st.y * cellHeight_)), 0, cellHeight_ - 1);
  return glm::ivec2(col * cellWidth_ + x, row * cellHeight_ + y);
}

}  // namespace lucent
