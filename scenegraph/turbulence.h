// POV-Ray 3.7's turbulence: fractal sums of noise over octaves (texture.cpp: Turbulence,
// DTurbulence), with the octaves, omega and lambda of a pattern's placement.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The scalar sum marble, spiral1, spiral2 and agate add to their value. For generators 2
// and 3 the first octave is 2·noise − 0.5 clamped to [0, 1] and the others are unclamped.
double turbulence(const Vec3& p, const PatternPlacement& placement, int generator);

// The vector sum that displaces the pattern point (and bends wood's rings). It does not
// depend on the noise generator.
Vec3 dturbulence(const Vec3& p, const PatternPlacement& placement);
// The same with the octaves, omega and lambda given (a turbulence warp's).
Vec3 dturbulence(const Vec3& p, int octaves, double omega, double lambda);

}  // namespace lucent
