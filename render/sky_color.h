// The colour of <sky> for a ray that leaves the scene (scenegraph/sky.h).
#pragma once

#include "scenegraph/sky.h"

namespace lucent {

// `direction` need not be unit: it is normalised first, as POV-Ray's rays are.
Color skyColor(const Sky& sky, const Vec3& direction);

}  // namespace lucent
