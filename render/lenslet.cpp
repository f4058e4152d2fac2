#include "lenslet.h"
#include "pinhole.h"

#include <fmt/core.h>

#include <algorithm>

namespace lucent {

LensletProjection::LensletProjection(const CameraFrame& frame, const Camera& camera, int width,
                                     int height)
    : Projection(frame, camera, width, height),
      nx_(camera.lensesX),
      ny_(camera.lensesY),
      pitch_(camera.pitch) {
  if (nx_ < 1 || ny_ < 1 || !(pitch_ > 0.0) || !std::isfinite(pitch_))
    throw LocatedError(camera.loc, "a lenslet camera needs at least 1 x 1 lenses and a pitch > 0");
  if (nx_ > width || ny_ > height)
    throw LocatedError(
        camera.loc,
        fmt::format(
            "a lenslet camera with {} x {} lenses needs an image of at least {} x {} pixels "
            "(got {} x {})",
            nx_, ny_, nx_, ny_, width, height));
  if (!(camera.fov > 0.0 && camera.fov < 180.0))
    throw LocatedError(
        camera.loc,
        fmt::format("a lenslet camera needs 0 < fov < 180 degrees (got {})", camera.fov));
  cellWidth_ = static_cast<double>(width) / nx_;
  cellHeight_ = static_cast<double>(height) / ny_;
  // Each cell is framed like a pinhole image of the cell's size (square pixels), with
  // fractional cell sizes.
  imagePlaneHalfExtents(camera.fov, camera.fovAxis, cellWidth_, cellHeight_, halfWidth_,
                        halfHeight_);
}

Vec3 LensletProjection::lensCentre(int i, int j) const {
  double x = (i + 0.5 - 0.5 * nx_) * pitch_;
  double y = (0.5 * ny_ - j - 0.5) * pitch_;
  return frame_.origin + x * frame_.right + y * frame_.up;
}

bool LensletProjection::generateRay(const Vec2& film, const Vec2&, Ray& ray) const {
  // The cell, with the right and bottom image edges in the last cell.
  int i = std::clamp(static_cast<int>(std::floor(film.x / cellWidth_)), 0, nx_ - 1);
  int j = std::clamp(static_cast<int>(std::floor(film.y / cellHeight_)), 0, ny_ - 1);
  double sx = 2.0 * (film.x - i * cellWidth_) / cellWidth_ - 1.0;
  double sy = 1.0 - 2.0 * (film.y - j * cellHeight_) / cellHeight_;
  Vec3 local(sx * halfWidth_, sy * halfHeight_, 1.0);
  ray = primaryRay(lensCentre(i, j), glm::normalize(frame_.toWorld(local)));
  return true;
}

}  // namespace lucent
