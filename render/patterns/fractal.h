// POV-Ray 3.7's fractal patterns (pattern.cpp): mandel, julia and magnet, iterated in the
// x-y plane of pattern space, and their exterior and interior colourings.
#pragma once

#include "scenegraph/pattern.h"

namespace lucent {

// The value of mandel, julia or magnet (type) at p: the orbit of z under POV-Ray's map,
// stopped when it escapes (|z|² > 4; magnet: |z|² > 10000 or |z − 1|² < 1/10000) or
// after `iterations` steps, then coloured by the exterior or the interior rule.
// Unbounded for some colourings (a factor times a coordinate); the caller wraps it.
double fractalValue(PatternType type, const FractalParams& f, const Vec3& p);

}  // namespace lucent
