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

}  // namespace lucent
