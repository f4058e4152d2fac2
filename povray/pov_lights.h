// light_source blocks, from the light table (scenegraph/light.h): each light placed as its
// type's row says (at its position, the contract's distance attenuation mapped onto fade;
// or parallel, from far away), then the keyword and modifiers its row writes.
#pragma once

#include "pov_writer.h"

#include "scenegraph/light.h"

#include <functional>
#include <string>

namespace lucent {

// min(1, 1/(a + b·r + c·r²)) as POV-Ray's `fade_distance fd fade_power p`, which gives
// 2/(1 + (r/fd)^p), times a constant `scale` on the light colour:
//   b = 0: 1/(a + c·r²) = (1/2a) · 2/(1 + r²·c/a)  → p = 2, fd = √(a/c), scale 1/(2a);
//   c = 0: 1/(a + b·r)  = (1/2a) · 2/(1 + r·b/a)   → p = 1, fd = a/b,   scale 1/(2a).
// Equal wherever the clamp min(1, ·) is inactive: everywhere when a ≥ 1, else beyond
// `exactBeyond` from the light. Both b and c non-zero has no equivalent (b is dropped).
struct PovFade {
  bool fade = false;  // false: no fade keywords (constant factor `scale`)
  double distance = 0.0;
  double power = 0.0;
  double scale = 1.0;
  bool exact = true;
  double exactBeyond = 0.0;  // > 0: exact only this far from the light or farther
  std::string problem;       // why not exact, for the warning
};
PovFade povFade(const Vec3& attenuation);

// How far the light of a directional light is put along −direction: POV-Ray's parallel
// lights shadow only what lies between the hit point and the plane through the light.
constexpr double kParallelLightDistance = 1e6;

// Writes one light_source. `anySpecular`: some material has a highlight, which a
// shadowless light would lose (POV-Ray drops highlights of shadowless lights).
// `projection` writes the light's projected_through block (PovGeometry::writeProjection),
// called for a light that has one.
void writeLight(const Light& light, bool anySpecular, PovWriter& out, PovIssues& issues,
                const std::function<void(PovWriter&)>& projection = {});

}  // namespace lucent
