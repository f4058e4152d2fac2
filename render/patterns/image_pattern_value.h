// POV-Ray 3.7's image_pattern at a pattern-space point (core/support/imageutil.cpp,
// image_pattern): the image's value at the projected point, blended as `interpolate` says,
// clamped to [0, 1]; 0 off a `once` image and where the projection leaves the point
// undefined.
#pragma once

#include "scenegraph/image_pattern.h"

namespace lucent {

double imagePatternValue(const ImagePattern& image, const Vec3& patternPoint);

}  // namespace lucent
