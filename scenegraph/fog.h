// The scene's <fog> (docs/scene-language.md, "<fog>"): POV-Ray's constant fog (fog_type 1)
// and ground fog (fog_type 2), with the fog colour's filter and transmit.
#pragma once

#include "source_loc.h"

#include "primitives/math.h"

namespace lucent {

enum class FogType { Constant, Ground };

struct Fog {
  FogType type = FogType::Constant;
  SourceLoc loc;
  Color color{1.0f};
  double distance = 1.0;  // > 0: a stretch t of constant fog keeps exp(−t/distance)
  // POV-Ray's rgbft fog colour: `transmit` is the least fraction of the ray's colour that
  // any stretch keeps; `filter` tints what is kept by the fog colour.
  float filter = 0.0f;
  float transmit = 0.0f;
  // Ground fog: full density at or below `offset` along `up`, 1/(1 + y²) above it, with
  // y = (height − offset)/altitude.
  double offset = 0.0;
  double altitude = 1.0;   // > 0
  Vec3 up{0.0, 1.0, 0.0};  // unit
};

}  // namespace lucent
