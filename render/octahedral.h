// The octahedral camera: every direction around the camera on one image, as an octahedral
// map (direction_maps.h has the formulas). XML:
//   <camera type="octahedral" position="0 1 0" look-at="0 1 -1"/>
// The image centre looks forward, the midpoints of the right and top edges look right and
// up, the four corners look straight back; the diamond between the edge midpoints is the
// front hemisphere. Every pixel has a ray (no empty pixel). Use a square image; another
// aspect ratio stretches the map to fill the image. fov is not used.
// filmPosition()/pixel() invert generateRay(), for reading the image back as a probe.
#pragma once

#include "projection.h"

#include <glm/vec2.hpp>

namespace lucent {

class OctahedralProjection final : public Projection {
 public:
  OctahedralProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // Pixel -> direction: the unit world direction at a film position (pixels).
  Vec3 direction(const Vec2& film) const;
  // Direction -> pixel: the film position (pixels) whose ray has this world direction, and
  // the pixel that holds it (the right and bottom image edges belong to the last pixel).
  Vec2 filmPosition(const Vec3& worldDirection) const;
  glm::ivec2 pixel(const Vec3& worldDirection) const;
};

}  // namespace lucent
