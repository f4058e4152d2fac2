// A scene's <fog> (docs/scene-language.md, "<fog>"): POV-Ray's constant fog (fog_type 1)
// and ground fog (fog_type 2), with the fog colour's filter and transmit and POV-Ray's fog
// turbulence. A scene may have several; they all apply, as in POV-Ray.
#pragma once

#include "source_loc.h"

#include "primitives/math.h"

#include <optional>

namespace lucent {

enum class FogType { Constant, Ground };

// POV-Ray's fog turbulence: a stretch of length t is shortened to
// t·(1 − exp(−t/distance)·min(1, depth·T(q))), T POV-Ray's scalar turbulence (octaves,
// omega, lambda, noise generator) at q = strength ⊙ (noiseFromWorld · the stretch's middle).
struct FogTurbulence {
  Vec3 strength{0.0};  // POV-Ray's `turbulence` vector: it scales the noise point, per axis
  int octaves = 6;     // 1..10
  double omega = 0.5;
  double lambda = 2.0;
  double depth = 0.5;        // POV-Ray's turb_depth
  int noiseGenerator = 2;    // as a pattern's noise-generator
  Mat4 noiseFromWorld{1.0};  // where the noise sits (the importer: POV-Ray's space)
};

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
  double altitude = 1.0;                    // > 0
  Vec3 up{0.0, 1.0, 0.0};                   // unit
  std::optional<FogTurbulence> turbulence;  // none: a smooth fog
};

}  // namespace lucent
