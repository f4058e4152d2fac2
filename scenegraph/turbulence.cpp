#include "turbulence.h"

#include "primitives/noise.h"

#include <algorithm>

namespace lucent {

namespace {

// POV-Ray's parser keeps octaves in 1..10 ("avoid DOMAIN errors") and stores omega and
// lambda in single precision.
int octaves(int n) { return std::clamp(n, 1, 10); }
double single(double v) { return static_cast<float>(v); }

}  // namespace

double turbulence(const Vec3& p, const PatternPlacement& placement, int generator) {
  const int n = octaves(placement.octaves);
  const double lam = single(placement.lambda), om = single(placement.omega);
  double value;
  if (generator > 1) value = std::min(std::max(2.0 * noise(p, generator) - 0.5, 0.0), 1.0);
  else value = noise(p, generator);
  double l = lam, o = om;
  for (int i = 2; i <= n; ++i) {
    const Vec3 q(p.x * l, p.y * l, p.z * l);
    if (generator > 1) value += o * (2.0 * noise(q, generator) - 0.5);
    else value += o * noise(q, generator);
    if (i < n) {
      l *= lam;
      o *= om;
    }
  }
  return value;
}

Vec3 dturbulence(const Vec3& p, const PatternPlacement& placement) {
  return dturbulence(p, placement.octaves, placement.omega, placement.lambda);
}

Vec3 dturbulence(const Vec3& p, int octaveCount, double omegaValue, double lambdaValue) {
  const int n = octaves(octaveCount);
  const double lam = single(lambdaValue), om = single(omegaValue);
  Vec3 result = dnoise(p);
  double l = lam, o = om;
  for (int i = 2; i <= n; ++i) {
    const Vec3 v = dnoise(Vec3(p.x * l, p.y * l, p.z * l));
    result.x += o * v.x;
    result.y += o * v.y;
    result.z += o * v.z;
    if (i < n) {
      l *= lam;
      o *= om;
    }
  }
  return result;
}

}  // namespace lucent
