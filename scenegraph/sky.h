// <sky>: a colour pattern evaluated on the direction of each ray that leaves the scene, as
// POV-Ray's sky_sphere (the contract's "Sky"); it replaces the background for those rays.
#pragma once

#include "material.h"
#include "source_loc.h"

#include <vector>

namespace lucent {

// Its layers: colour textures (<pattern>, <checker>, <hexagon>, <brick>) evaluated at the
// direction, the last written on top. Where a layer's colour has filter or transmit, the
// layers below it (and under the first, the background colour) show through, as POV-Ray
// 3.7 composes a sky_sphere's pigments (render/sky_color.h).
// How the layers let the ones below show: POV-Ray 3.7's rule, or the one POV-Ray uses for
// scenes of #version 3.6 and earlier (render/sky_color.h).
enum class SkyLayering { pov37, pov36 };

struct Sky {
  std::vector<Texture> layers;
  SkyLayering layering = SkyLayering::pov37;
  // The inverse of the sky's transform, applied to the unit direction as to a point (as
  // POV-Ray's sky_sphere does, so a translation moves the pattern too).
  Mat4 skyFromWorld{1.0};
  SourceLoc loc;
};

}  // namespace lucent
