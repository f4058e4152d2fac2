// The generalized Panini camera (Sharpless, Postle, German 2010, "Pannini: A New Projection
// for Rendering Wide Angle Perspective Images"; the authors' reference code is libpano13's
// PaniniGeneral.c). XML:
//   <camera type="panini" fov="150" distance="1" vertical-compression="0"/>
// The view sphere is first projected onto a vertical cylinder, which is then seen in
// perspective from `distance` d (in cylinder radii) behind its axis. A direction at
// longitude phi (about camera up, from forward towards right) and latitude theta lands at
//   h = S sin(phi),  v = S tan(theta),  S = (d + 1) / (d + cos(phi)).
// d = 0 is the rectilinear (pinhole) projection, d = 1 the cylindrical stereographic one.
// Vertical lines and lines through the image centre stay straight.
// vertical-compression q (0..1) is the paper's "hard squeeze", applied in the reference
// code's plane-to-sphere form: the latitude seen at image point (h, v) is
//   theta = (1 - q) atan(v / S) + q atan(v cos(phi)),
// so q = 0 is the Panini projection above and q = 1 keeps horizontal lines (parallel to the
// image plane) straight as well, like a rectilinear image does vertically. q > 0 needs the
// image to stay within 90 degrees of the axis horizontally.
// fov spans fov-axis: horizontal = the longitude at the left/right edge is fov/2; vertical =
// the latitude at the top/bottom centre is fov/2; diagonal = the corners are fov/2 off the
// axis. Pixels are square.
#pragma once

#include "projection.h"

namespace lucent {

class PaniniProjection final : public Projection {
 public:
  PaniniProjection(const CameraFrame& frame, const Camera& camera, int width, int height);
  bool generateRay(const Vec2& film, const Vec2& lens, Ray& ray) const override;

  // Camera-local direction (x right, y up, z forward) at Panini plane coordinates (h, v);
  // false where the plane point has no direction (beyond the projection's reach for d > 1).
  bool localDirection(double h, double v, Vec3& direction) const;
  // Plane half extents of the image.
  double halfWidth() const { return halfWidth_; }
  double halfHeight() const { return halfHeight_; }

 private:
  double d_, q_;
  double halfWidth_, halfHeight_;
};

// Panini plane coordinates (h, v) of a camera-local direction with vertical compression 0
// (the forward map above): for tests and for mapping points into a Panini image.
Vec2 paniniPlane(const Vec3& localDirection, double distance);

}  // namespace lucent
