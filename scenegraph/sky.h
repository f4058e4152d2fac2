// <sky>: a colour pattern evaluated on the direction of each ray that leaves the scene, as
// POV-Ray's sky_sphere (the contract's "Sky"); it replaces the background for those rays.
#pragma once

#include "material.h"
#include "source_loc.h"

namespace lucent {

struct Sky {
  PatternTexture pattern;
  // The inverse of the sky's transform, applied to the unit direction as to a point (as
  // POV-Ray's sky_sphere does, so a translation moves the pattern too).
  Mat4 skyFromWorld{1.0};
  SourceLoc loc;
};

}  // namespace lucent
