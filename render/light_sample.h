// What a light offers a surface point before shadows: the direction towards it, its
// distance, and the light colour after distance attenuation and the light's shape (a
// spot's cone).
#pragma once

#include "scenegraph/light.h"

#include <algorithm>

namespace lucent {

struct LightIncidence {
  Vec3 toLight{0.0, 1.0, 0.0};  // unit, from the point towards the light (an area light's centre)
  double distance = kInf;       // to the light along toLight; infinite for a directional light
  Color radiance{0.0f};         // I_L · A_dist · spot factor
  // The light's rays are parallel: its shadow ray goes along toLight for `distance` (to
  // infinity for a directional light), not to the light's sample points.
  bool parallel = false;
};

// A_dist = min(1, 1 / (a + b·r + c·r²)); 1 when the denominator is not positive (a light
// with attenuation "0 0 0" does not fade).
double distanceAttenuation(const Vec3& abc, double r);

// POV-Ray's fade: 2 / (1 + (distance / fadeDistance)^fadePower).
double povFade(double distance, double fadeDistance, double fadePower);
// The light's factor at distance r: its fade when it has one, else its attenuation.
double lightDistanceFactor(const Light& light, double r);

// POV-Ray's spotlight: 1 inside the `inner` cone, 0 beyond `angle`, between them the
// smoothstep (3 − 2u)u² of u = (cos θ − cos angle)/(cos inner − cos angle); all of it times
// cos^tightness θ. cosTheta is the cosine between the spot axis and the direction from the
// light to the point.
double spotFactor(const Light& light, double cosTheta);

// Direction, distance and unshadowed light at point p. Directional lights are not
// attenuated (they have no distance). An area light uses its centre, as POV-Ray does,
// for its cone too: every shadow sample carries the centre's spot factor.
LightIncidence lightIncidence(const Light& light, const Vec3& p);

// The shadow-ray targets of a light: 1 for point and spot lights, nu·nv for area lights.
inline int shadowSampleCount(const Light& light) {
  if (light.type != LightType::Area) return 1;
  return std::max(light.samplesU, 2) * std::max(light.samplesV, 2);  // the contract's minimum
}

// Shadow sample k of an area light: grid point (a, b) = (k mod nu, k div nu) of the
// rectangle, the grid including its edges: position + u·(a/(nu−1) − ½) + v·(b/(nv−1) − ½).
// With jitter, `jitter` ∈ [0,1)² moves the point within ±½ grid step, clamped to the
// rectangle. Other lights: their position.
Vec3 lightSamplePoint(const Light& light, int k, const Vec2& jitter);

}  // namespace lucent
