// The lenslet (light-field, plenoptic) camera: a grid of pinhole cameras in one image, like
// the image behind a microlens array or a camera array (Levoy & Hanrahan 1996, "Light Field
// Rendering"; Ng et al. 2005). XML:
//   <camera type="lenslet" lenses="4 4" pitch="0.1" fov="40"/>
// The image is divided into nx x ny equal cells. Cell (i, j), column i from the left and
// row j from the top, is an upright pinhole image seen from the lens centre
//   position + ((i + 1/2 - nx/2) pitch) right + ((ny/2 - j - 1/2) pitch) up,
// so the cell on the left looks from the left. All lenses look along the view direction
// (parallel optical axes, no toe-in), and fov spans each cell along fov-axis, as a pinhole
// camera's fov spans its image. Pick a width divisible by nx and a height divisible by ny
// so every pixel belongs to one lens.
#pragma once

#include "projection.h"

namespace lucent {

class LensletProjection final : public Projection {
 public:
  LensletProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // The world position of lens (i, j).
  Vec3 lensCentre(int i, int j) const;

 private:
  int nx_, ny_;
  double pitch_;
  double cellWidth_, cellHeight_;  // pixels
  double halfWidth_, halfHeight_;  // image plane at distance 1, per cell
};

}  // namespace lucent
