// A transfer curve between stored values and linear light: sRGB's, or a power law x^power.
// A scene's working gamma (POV-Ray's assumed_gamma) is one; an image file's encoding (the
// `gamma` of POV-Ray's image_map) is another.
#pragma once

namespace lucent {

struct GammaCurve {
  bool srgb = false;   // sRGB's curve
  double power = 1.0;  // otherwise a value x is the light x^power
  bool linear() const { return !srgb && power == 1.0; }
  bool operator==(const GammaCurve& o) const { return srgb == o.srgb && power == o.power; }
};

}  // namespace lucent
