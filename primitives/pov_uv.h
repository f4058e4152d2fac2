// POV-Ray 3.7's (u, v) of its shapes (each shape's UVCoord: what uv_mapping reads), taken
// in POV-Ray's left-handed space: the importer places POV-Ray's object point (x, y, z) at
// Lucent's (x, y, -z), so a Lucent object point is carried back by negating z first.
#pragma once

#include "math.h"

#include <cmath>

namespace lucent {

// POV-Ray's angle of (x, z) about +y from +x towards +z, in turns ([0, 1)), as its sphere,
// lathe and sor find it (acos of x over the radius, mirrored where z < 0); 0 where
// x² + z² is at most its EPSILON, 1e-10.
inline double povTurnsAboutY(double x, double z) {
  const double len2 = x * x + z * z;
  if (!(len2 > 1e-10)) return 0.0;
  double theta;
  if (z == 0.0) {
    theta = x > 0.0 ? 0.0 : kPi;
  } else {
    theta = std::acos(x / std::sqrt(len2));
    if (z < 0.0) theta = 2.0 * kPi - theta;
  }
  return theta / (2.0 * kPi);
}

// POV-Ray's sphere mapping of a point seen from a centre, the offset d = p - centre given
// in Lucent's space: the longitude about +y from +x, and 0.5 + the latitude over pi, in
// POV-Ray's space (z negated); (0, 0) at the centre itself.
inline Vec2 povSphereUV(Vec3 d) {
  d.z = -d.z;
  const double len = glm::length(d);
  if (len == 0.0) return Vec2(0.0);
  d /= len;
  return Vec2(povTurnsAboutY(d.x, d.z), 0.5 + std::asin(d.y) / kPi);
}

}  // namespace lucent
