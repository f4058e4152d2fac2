#include "fog.h"

#include "scenegraph/turbulence.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

// POV-Ray's EPSILON: below this height difference (in altitudes) a stretch counts as level.
constexpr double kLevel = 1e-10;

// The ground fog's density integrated over height (in altitudes): y below 0 has density 1,
// above it 1/(1 + y²), whose integral is atan(y).
double heightIntegral(double y) { return y <= 0.0 ? y : std::atan(y); }

// The stretch's length shortened by the fog's turbulence at `middle` (POV-Ray's
// ComputeConstantFogColour and ComputeGroundFogColour): the nearer, the more turbulence.
double turbulentLength(const FogTurbulence& turb, double distance, const Vec3& middle,
                       double length) {
  PatternPlacement octaves;
  octaves.octaves = turb.octaves;
  octaves.omega = turb.omega;
  octaves.lambda = turb.lambda;
  const Vec3 q = Vec3(turb.noiseFromWorld * Vec4(middle, 1.0)) * turb.strength;
  const double k = std::exp(-length / distance);
  return length *
         (1.0 - k * std::min(1.0, turbulence(q, octaves, turb.noiseGenerator) * turb.depth));
}

double groundDepth(const Fog& fog, const Vec3& origin, const Vec3& dir, double length) {
  const double start = (glm::dot(origin, fog.up) - fog.offset) / fog.altitude;
  if (std::isinf(length)) {
    // (Turbulence changes nothing here: it is weighted by exp(−length/distance) = 0.)
    // A ray that leaves the scene: it climbs out of the fog (a finite depth) only if it
    // rises. POV-Ray traces such rays to 2e10, which gives the same to ~1e-10 relative.
    const double rise = glm::dot(dir, fog.up);
    if (!(rise > 0.0)) return kInf;
    return (kPi / 2.0 - heightIntegral(start)) * fog.altitude / rise;
  }
  // POV-Ray's cases, in its order: the mean density over the stretch times its length.
  const Vec3 end3 = origin + dir * length;
  const double end = (glm::dot(end3, fog.up) - fog.offset) / fog.altitude;
  double density;
  if (start <= 0.0) {
    density = end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
  } else if (end <= 0.0) {
    density = (std::atan(start) - end) / (start - end);
  } else {
    const double delta = start - end;
    density = std::fabs(delta) > kLevel ? (std::atan(start) - std::atan(end)) / delta
                                        : 1.0 / (start * start + 1.0);
  }
  if (fog.turbulence)
    length = turbulentLength(*fog.turbulence, fog.distance, (origin + end3) * 0.5, length);
  return length * density;
}

}  // namespace

double fogDepth(const Fog& fog, const Vec3& origin, const Vec3& dir, double length) {
  if (fog.type == FogType::Ground) return groundDepth(fog, origin, dir, length);
  if (fog.turbulence && !std::isinf(length))
    return turbulentLength(*fog.turbulence, fog.distance, origin + dir * (length / 2.0), length);
  return length;
}

FogEffect fogAlong(const Fog& fog, const Vec3& origin, const Vec3& dir, double length) {
  double kept = std::exp(-fogDepth(fog, origin, dir, length) / fog.distance);
  kept = std::max(kept, static_cast<double>(fog.transmit));
  const float a = static_cast<float>(kept);
  FogEffect e;
  e.keep = a * ((1.0f - fog.filter) + fog.filter * fog.color);
  e.add = (1.0f - a) * fog.color;
  return e;
}

FogEffect fogsAlong(const std::vector<Fog>& fogs, const Vec3& origin, const Vec3& dir,
                    double length) {
  if (fogs.size() == 1) return fogAlong(fogs[0], origin, dir, length);
  FogEffect sum;
  for (auto fog = fogs.rbegin(); fog != fogs.rend(); ++fog) {
    const FogEffect e = fogAlong(*fog, origin, dir, length);
    sum.keep *= e.keep;
    sum.add += e.add;
  }
  return sum;
}

}  // namespace lucent
