// The cube-map camera: six 90-degree pinhole views around the camera on one image. XML:
//   <camera type="cubemap" layout="cross"/>     (or layout="strip")
// cross = a 4 x 3 grid of cells, strip = 6 x 1; direction_maps.h says which face is in
// which cell and how each face is oriented. Every face is what a 90-degree pinhole camera
// at the position would see, not mirrored. The image must divide into whole cells (width a
// multiple of 4 or 6, height of 3 or 1); square faces need 4:3 (cross) or 6:1 (strip).
// The empty cells of the cross have no ray and get the background. fov is not used.
// filmPosition()/pixel() invert generateRay(), for reading the image back as a probe.
#pragma once

#include "projection.h"

#include <glm/vec2.hpp>

namespace lucent {

class CubemapProjection final : public Projection {
 public:
  CubemapProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // Pixel -> direction: false on an empty cell of the cross.
  bool direction(const Vec2& film, Vec3& worldDirection) const;
  // Direction -> pixel: the film position (pixels) on the direction's face, and the pixel
  // that holds it; a direction on a face's border goes to that face's own border pixel.
  Vec2 filmPosition(const Vec3& worldDirection) const;
  glm::ivec2 pixel(const Vec3& worldDirection) const;

 private:
  CubemapLayout layout_;
  int cellWidth_, cellHeight_;  // pixels
};

}  // namespace lucent
