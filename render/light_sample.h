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

// An area light's edge vectors as its samples at point p use them: its u and v, or for an
// oriented light POV-Ray's turn to face p. With d = (centre − p)/|centre − p| and
// r = (0, 1, 0) when | |d.z| − 1 | < 0.01, else (0, 0, 1):
//   u' = |u|·normalize(d × r),  v' = |u|·normalize(d × u'),
// a square of side |u| across d (the numbers as written, in Lucent's space; at the centre
// itself the light's own axes). With handedness="left" the same is done in POV-Ray's space,
// Lucent's with z negated (F = diag(1, 1, −1)): d is F·d, and the axes found are carried
// back by F, so u' = −|u|·normalize(d × F·r) and v' = −|u|·normalize(d × u'): for an
// imported scene, the disc POV-Ray turns.
struct AreaAxes {
  Vec3 u;
  Vec3 v;
};
AreaAxes areaAxes(const Light& light, const Vec3& p);

// Where grid point (a, b) of an nu × nv grid lies on the rectangle, in units of its edge
// vectors: (a/(nu−1) − ½, b/(nv−1) − ½). Circular (POV-Ray's): with x = a/(nu−1) − ½ +
// 0.001 and y likewise (the offset keeps the centre off 0/0), (x, y)·max(|x|, |y|)/√(x² + y²)
// — each square shell of the grid pulled onto the circle of its half-width.
Vec2 areaGridCoordinates(double a, double b, int nu, int nv, bool circular);

// Shadow sample k of an area light: grid point (a, b) = (k mod nu, k div nu), the grid
// including the rectangle's edges: position + u·x + v·y for (x, y) from
// areaGridCoordinates. With jitter, `jitter` ∈ [0,1)² moves (a, b) within ±½ grid step,
// clamped to the grid, before the circular remap (as POV-Ray jitters before it). Other
// lights: their position. The light's own axes, or `axes` (areaAxes at the lit point).
Vec3 lightSamplePoint(const Light& light, int k, const Vec2& jitter);
Vec3 lightSamplePoint(const Light& light, const AreaAxes& axes, int k, const Vec2& jitter);

}  // namespace lucent
