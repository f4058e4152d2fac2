// The colour of <sky> for a ray that leaves the scene (scenegraph/sky.h).
#pragma once

#include "scenegraph/sky.h"

namespace lucent {

// `direction` need not be unit: it is normalised first, as POV-Ray's rays are. The layers
// are composed as POV-Ray 3.7 composes a sky_sphere's pigments: from the top (the last)
// down, each adds its colour times its opacity 1 - f - t times what the layers above let
// through, and lets through C·f + t of what is below; under the first layer lies
// `background` (opaque).
// With layering pov36 (POV-Ray's for #version 3.6 and earlier): each layer adds its colour
// times its opacity times s, s the product of the filters of the layers above plus the
// product of their transmits; under all lies the background times the product of every
// colour times the product of every filter, plus the product of every transmit.
Color skyColor(const Sky& sky, const Vec3& direction, const Color& background);

}  // namespace lucent
