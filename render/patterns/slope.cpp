#include "slope.h"

#include <cmath>

namespace lucent {

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON

// POV-Ray's range: (low, high) as an offset and a width; equal nonzero ends are ignored
// (POV-Ray warns "Zero slope range"), a zero width means no stretching.
double stretched(double v, double low, double high) {
  if (high != 0.0 && high == low) return v;
  const double width = high - low;
  return width != 0.0 ? (v - low) / width : v;
}

// Into [0, 1): a value of exactly 1 (common: a normal along the direction) stays just
// below it instead of wrapping to 0.
double wrapped(double v, bool nearOne) {
  if (nearOne) return v - kEpsilon;
  return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
}

double length(const Vec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// POV-Ray's VNormalizeEq: times the inverse of the length (not divided by it).
Vec3 unit(const Vec3& v, double len) {
  const double inv = 1.0 / len;
  return Vec3(v.x * inv, v.y * inv, v.z * inv);
}

}  // namespace

double slopeValue(const SlopeParams& s, const Vec3& p, const PatternSurface* surface) {
  if (!surface) return 0.0;
  const Vec3& n = surface->normal;
  double slopeWeight = 1.0, altitudeWeight = 0.0;
  double cosine;
  Vec3 alt(0.0);
  if (s.pointAt) {
    const Vec3 d0 = s.direction - surface->point;
    const Vec3 d = unit(d0, length(d0));
    cosine = n.x * d.x + n.y * d.y + n.z * d.z;
  } else {
    // The two vectors' lengths weigh slope against altitude (POV-Ray's parse-time sums).
    const double sl = length(s.direction), al = length(s.altitude);
    const Vec3 dir = sl != 0.0 ? unit(s.direction, sl) : s.direction;
    if (al != 0.0) alt = unit(s.altitude, al);
    slopeWeight = sl / (sl + al);
    altitudeWeight = 1.0 - slopeWeight;
    cosine = n.x * dir.x + n.y * dir.y + n.z * dir.z;
  }
  cosine = std::fmax(-1.0, std::fmin(1.0, cosine));
  double v1 = (std::asin(cosine) / kPi * 2.0 + 1.0) * 0.5;
  v1 = stretched(v1, s.low, s.high);
  if (altitudeWeight == 0.0) return wrapped(v1, v1 == 1.0);
  double v2 = p.x * alt.x + p.y * alt.y + p.z * alt.z;
  v2 = stretched(v2, s.altitudeLow, s.altitudeHigh);
  const double v = slopeWeight * v1 + altitudeWeight * v2;
  return wrapped(v, v - 1.0 < kEpsilon && v >= 1.0);
}

}  // namespace lucent
