#include "warp.h"

#include "crackle.h"
#include "pattern_point.h"
#include "primitives/noise.h"
#include "scenegraph/turbulence.h"

#include <cmath>

namespace lucent {

namespace {

constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.1415926535897932384626433832795;

Vec3 repeatWarp(const RepeatWarp& r, const Vec3& p) {
  const int a = r.axis;
  Vec3 q = p;
  // POV-Ray keeps the slab number in single precision.
  const float slab = static_cast<float>(std::floor(p[a] / r.width));
  q[a] = p[a] - slab * r.width;
  if (static_cast<int>(slab) & 1) {
    for (int i = 0; i < 3; ++i)
      if (r.flip[i]) q[i] = -q[i];
    if (r.flip[a]) q[a] = r.width + q[a];
  }
  for (int i = 0; i < 3; ++i) q[i] += slab * r.offset[i];
  return q;
}

Vec3 blackHoleWarp(const BlackHoleWarp& h, const Vec3& p) {
  Vec3 center = h.center;
  if (h.repeat != Vec3(0.0)) {
    int block[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
      if (h.repeat[a] >= kEpsilon) block[a] = static_cast<int>(std::floor(p[a] / h.repeat[a]));
    if (h.turbulence != Vec3(0.0)) {
      const int seed = latticeHash(block[0], block[1], block[2]);
      for (int a = 0; a < 3; ++a) center[a] += patternRandom(seed + a) * h.turbulence[a];
    }
    for (int a = 0; a < 3; ++a) center[a] += h.repeat[a] * block[a];
  }
  Vec3 delta = p - center;
  const double d = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
  if (d >= h.radius) return p;
  const double s = std::min(std::pow((h.radius - d) / h.radius, h.falloff) * h.strength, 1.0);
  delta *= h.inverse ? -s : s;
  return p + delta;
}

// The angle of (x, z) from +x, 0 to 2π, as POV-Ray's mapping warps find it.
double angleAround(double x, double z, double len) {
  if (z == 0.0) return x > 0 ? 0.0 : kPi;
  const double theta = std::acos(x / len);
  return z < 0.0 ? kTwoPi - theta : theta;
}

// (x, y, z) of the flat coordinates turned so that z becomes the orientation.
Vec3 orient(const Vec3& o, double x, double y, double z) {
  if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return Vec3(x, y, z);
  return Vec3(o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y,
              o.x * -x + o.y * y + o.z * z);
}

double distanceFactor(double distExp, double len) {
  return distExp == 1.0 ? len : std::pow(len, distExp);
}

Vec3 cubicWarp(const Vec3& p) {
  double x = p.x, y = p.y, z = p.z;
  const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
  constexpr double third = 1.0 / 3.0;
  if (x >= 0 && x >= ay && x >= az)
    return Vec3(0.75 - 0.25 * (z / x + 1.0) / 2.0, third + third * (y / x + 1.0) / 2.0, x);
  if (y >= 0 && y >= ax && y >= az)
    return Vec3(0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - third * (z / y + 1.0) / 2.0, y);
  if (z >= 0 && z >= ax && z >= ay)
    return Vec3(0.25 + 0.25 * (x / z + 1.0) / 2.0, third + third * (y / z + 1.0) / 2.0, z);
  if (x < 0 && x <= -ay && x <= -az) {
    x = -x;
    return Vec3(0.25 * (z / x + 1.0) / 2.0, third + third * (y / x + 1.0) / 2.0, x);
  }
  if (y < 0 && y <= -ax && y <= -az) {
    y = -y;
    return Vec3(0.25 + 0.25 * (x / y + 1.0) / 2.0, third * (z / y + 1.0) / 2.0, y);
  }
  z = -z;
  return Vec3(1.0 - 0.25 * (x / z + 1.0) / 2.0, third + third * (y / z + 1.0) / 2.0, z);
}

Vec3 mappingWarp(const MappingWarp& m, const Vec3& p) {
  switch (m.kind) {
    case MappingWarpKind::planar:
      return orient(m.orientation, p.x, p.y, m.distance);
    case MappingWarpKind::cylindrical: {
      const double len = std::sqrt(p.x * p.x + p.z * p.z);
      if (len == 0.0) return p;  // POV-Ray leaves the axis alone
      double theta = angleAround(p.x, p.z, len) / kTwoPi;
      if (m.distExp != 0.0) theta *= distanceFactor(m.distExp, len);
      return orient(m.orientation, theta, p.y, len);
    }
    case MappingWarpKind::spherical: {
      const double dist = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
      if (dist == 0.0) return p;
      const double x = p.x / dist, y = p.y / dist, z = p.z / dist;
      double phi = 0.5 + std::asin(y) / kPi;
      const double len = std::sqrt(x * x + z * z);
      double theta = len == 0.0 ? 0.0 : angleAround(x, z, len) / kTwoPi;
      if (m.distExp != 0.0) {
        theta *= distanceFactor(m.distExp, dist);
        phi *= distanceFactor(m.distExp, dist);
      }
      return orient(m.orientation, theta, phi, dist);
    }
    case MappingWarpKind::toroidal: {
      double len = std::sqrt(p.x * p.x + p.z * p.z);
      if (len == 0.0) return p;
      double theta = angleAround(p.x, p.z, len) / kTwoPi;
      const double x = len - m.majorRadius;
      len = std::sqrt(x * x + p.y * p.y);
      double phi = std::acos(-x / len);
      if (p.y > 0.0) phi = kTwoPi - phi;
      phi /= kTwoPi;
      if (m.distExp != 0.0) {
        theta *= distanceFactor(m.distExp, len);
        phi *= distanceFactor(m.distExp, len);
      }
      return orient(m.orientation, theta, phi, len);
    }
    case MappingWarpKind::cubic:
      return cubicWarp(p);
  }
  return p;
}

struct ApplyWarp {
  const Vec3& p;
  Vec3 operator()(const TransformWarp& t) const { return toPatternSpace(t.patternFromPrevious, p); }
  Vec3 operator()(const TurbulenceWarp& t) const {
    const Vec3 d = dturbulence(p, t.octaves, t.omega, t.lambda);
    return Vec3(p.x + d.x * t.strength.x, p.y + d.y * t.strength.y, p.z + d.z * t.strength.z);
  }
  Vec3 operator()(const RepeatWarp& r) const { return repeatWarp(r, p); }
  Vec3 operator()(const BlackHoleWarp& h) const { return blackHoleWarp(h, p); }
  Vec3 operator()(const MappingWarp& m) const { return mappingWarp(m, p); }
};

}  // namespace

Vec3 applyWarps(const std::vector<PatternWarp>& warps, Vec3 p) {
  for (auto w = warps.rbegin(); w != warps.rend(); ++w) p = std::visit(ApplyWarp{p}, *w);
  return p;
}

}  // namespace lucent
