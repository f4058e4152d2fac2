#include "pattern_value.h"

#include "crackle.h"
#include "fractal.h"
#include "image_pattern_value.h"
#include "pattern_point.h"
#include "pavement.h"
#include "primitives/noise.h"
#include "render/texture.h"
#include "scenegraph/object_pattern.h"
#include "scenegraph/turbulence.h"
#include "scenegraph/wave_shape.h"
#include "slope.h"
#include "tiling.h"
#include "wave_sources.h"

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {

constexpr double kPi = 3.1415926535897932384626;
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kTwoPi = 6.283185307179586476925286766560;

bool hasTurbulence(const PatternPlacement& t) {
  return t.turbulence.x != 0.0 || t.turbulence.y != 0.0 || t.turbulence.z != 0.0;
}

// The turbulence marble and the spirals add to their value: turbulence.x times the scalar
// turbulence (0 without turbulence).
double scalarTurbulence(const Vec3& p, const PatternSpec& spec) {
  if (!hasTurbulence(spec.placement)) return 0.0;
  return spec.placement.turbulence.x * turbulence(p, spec.placement, spec.noiseGenerator);
}

double gradient(const Vec3& p, const Vec3& axis) {
  // POV-Ray normalises the axis when it parses it (VNormalizeEq).
  const double inv = 1.0 / std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  const Vec3 g(axis.x * inv, axis.y * inv, axis.z * inv);
  const double r = p.x * g.x + p.y * g.y + p.z * g.z;
  return r > 1.0 ? std::fmod(r, 1.0) : r;
}

double onion(const Vec3& p) { return std::fmod(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0); }

double radial(const Vec3& p) {
  if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
  return 0.25 + (std::atan2(p.x, p.z) + kPi) / kTwoPi;
}

// Both spirals: the angle about z in [0, 2π) from asin, as POV-Ray computes it.
double spiralAngle(double x, double y, double rad) {
  if (rad == 0.0) return 0.0;
  return x < 0.0 ? 3.0 * kHalfPi - std::asin(y / rad) : kHalfPi + std::asin(y / rad);
}

double spiral1(const Vec3& p, const PatternSpec& spec) {
  const double turb = scalarTurbulence(p, spec);
  const double rad = std::sqrt(p.x * p.x + p.y * p.y);
  const double phi = spiralAngle(p.x, p.y, rad);
  const double arms = static_cast<short>(spec.arms);  // POV-Ray keeps arms in a short
  return p.z + rad + arms * phi / kTwoPi + turb;
}

double spiral2(const Vec3& p, const PatternSpec& spec) {
  const double turb = scalarTurbulence(p, spec);
  const double rad = std::sqrt(p.x * p.x + p.y * p.y);
  const double phi = spiralAngle(p.x, p.y, rad);
  const double arms = static_cast<short>(spec.arms);  // POV-Ray keeps arms in a short
  const double arm = triangleWave(p.z + rad + arms * phi / kTwoPi + turb);
  return triangleWave(rad) + arm;
}

double wood(const Vec3& p, const PatternPlacement& t) {
  double px = 0.0, py = 0.0;
  if (hasTurbulence(t)) {
    const Vec3 w = dturbulence(p, t);
    px = cycloidal((p.x + w.x) * t.turbulence.x);
    py = cycloidal((p.y + w.y) * t.turbulence.y);
  }
  px += p.x;
  py += p.y;
  return std::sqrt(px * px + py * py + 0.0 * 0.0);
}

double marble(const Vec3& p, const PatternSpec& spec) { return p.x + scalarTurbulence(p, spec); }

double agate(const Vec3& p, const PatternSpec& spec) {
  // POV-Ray always gives agate a turbulence record, so its octaves, omega and lambda apply
  // even without turbulence; agate_turb scales it, kept in single precision as POV-Ray's.
  const double scale = static_cast<float>(spec.agateTurb);
  const double turb = scale * turbulence(p, spec.placement, spec.noiseGenerator);
  double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
  if (v < 0.0) return 0.0;
  return std::pow(std::min(1.0, v), 0.77);
}

double granite(const Vec3& p, int generator) {
  const Vec3 base(p.x * 4.0, p.y * 4.0, p.z * 4.0);
  double sum = 0.0, freq = 1.0;
  for (int i = 0; i < 6; freq *= 2.0, ++i) {
    const double n = noise(Vec3(base.x * freq, base.y * freq, base.z * freq), generator);
    double t;
    if (generator == 1) {
      t = std::fabs(0.5 - n);
    } else {
      t = std::fabs(1.0 - 2.0 * n);
      if (t > 0.5) t = 0.5;
    }
    sum += t / freq;
  }
  return sum;
}

double leopard(const Vec3& p) {
  const double v = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
  return v * v;
}

double wrinkles(const Vec3& p, int generator) {
  double lambda = 2.0, omega = 0.5, value;
  if (generator > 1) value = std::min(std::max(noise(p, generator) * 2.0 - 0.5, 0.0), 1.0);
  else value = noise(p, generator);
  for (int i = 1; i < 10; ++i) {
    const Vec3 q(p.x * lambda, p.y * lambda, p.z * lambda);
    if (generator > 1)
      value += omega * std::min(std::max(noise(q, generator) * 2.0 - 0.5, 0.0), 1.0);
    else value += omega * noise(q, generator);
    lambda *= 2.0;
    omega *= 0.5;
  }
  return value / 2.0;
}

// 1 − |y| within the band |y| <= 1, 0 outside it (POV-Ray clips |y| to [0, 1]).
double planar(const Vec3& p) {
  const double r = std::fabs(p.y);
  return r > 1.0 ? 0.0 : 1.0 - r;
}

// POV-Ray's CLIP_DENSITY of a distance r: 1 − r within [0, 1], 0 beyond (and 1 below 0,
// which a distance never is). Spherical, cylindrical and boxed are its distance to the
// origin, to the y axis and (the largest coordinate) to the origin's cube.
double clippedDistance(double r) {
  if (r < 0.0) return 1.0;
  return r > 1.0 ? 0.0 : 1.0 - r;
}

// POV-Ray's pigment_pattern: the grey level of the pigment's colour at p (filter and
// transmit ignored), with POV-Ray's weights of red, green and blue, kept in single
// precision as POV-Ray's colour channels.
double pigmentGrey(const PatternSpec& spec, const Vec3& p) {
  if (!spec.pigment) return 0.0;
  const TextureMapEntry& e = *spec.pigment;
  const Color c = std::holds_alternative<std::monostate>(e.texture)
                      ? e.color.rgb
                      : pigmentAt(e.texture, p, Vec3(0.0)).rgb;
  return static_cast<float>(0.297 * c.r + 0.589 * c.g + 0.114 * c.b);
}

double dents(const Vec3& p, int generator) {
  const double n = noise(p, generator);
  return n * n * n;
}

}  // namespace

double povFloor(double x) { return x >= 0.0 ? std::floor(x) : 0.0 - std::floor(0.0 - x) - 1.0; }

Vec3 quiltedOffset(const Vec3& p, const QuiltedParams& q) {
  Vec3 v(p.x - povFloor(p.x) - 0.5, p.y - povFloor(p.y) - 0.5, p.z - povFloor(p.z) - 0.5);
  const double t = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  // The Bézier cubic from 0 to 1 with inner controls control0 and control1 (single
  // precision in POV-Ray), scaled by 1/√(3/4).
  const double p1 = static_cast<float>(q.control0), p2 = static_cast<float>(q.control1);
  const double it = 1 - t;
  const double k = (t * t * t + 3.0 * t * (it * it) * p1 + 3.0 * (t * t) * it * p2) * 1.154700538;
  return Vec3(v.x * k, v.y * k, v.z * k);
}

namespace {

double quilted(const Vec3& p, const QuiltedParams& q) {
  const Vec3 v = quiltedOffset(p, q);
  return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

}  // namespace

double rawPatternValue(const PatternSpec& spec, const Vec3& p) {
  const int gen = spec.noiseGenerator;
  switch (spec.type) {
    case PatternType::gradient:
      return gradient(p, spec.axis);
    case PatternType::onion:
      return onion(p);
    case PatternType::radial:
      return radial(p);
    case PatternType::spiral1:
      return spiral1(p, spec);
    case PatternType::spiral2:
      return spiral2(p, spec);
    case PatternType::wood:
      return wood(p, spec.placement);
    case PatternType::marble:
      return marble(p, spec);
    case PatternType::agate:
      return agate(p, spec);
    case PatternType::granite:
      return granite(p, gen);
    case PatternType::bozo:
    case PatternType::spotted:
    case PatternType::bumps:
      return noise(p, gen);
    case PatternType::leopard:
      return leopard(p);
    case PatternType::crackle:
      return crackleValue(p, spec.crackle, gen);
    case PatternType::wrinkles:
      return wrinkles(p, gen);
    case PatternType::dents:
      return dents(p, gen);
    case PatternType::ripples:
      return ripplesValue(p, spec.frequency, spec.phase, spec.waveSources);
    case PatternType::waves:
      return wavesValue(p, spec.frequency, spec.phase, spec.waveSources);
    case PatternType::planar:
      return planar(p);
    case PatternType::quilted:
      return quilted(p, spec.quilted);
    case PatternType::mandel:
    case PatternType::julia:
    case PatternType::magnet:
      return fractalValue(spec.type, spec.fractal, p);
    case PatternType::function: {
      // POV-Ray's function pattern: above 1 only the fraction (below 0 the value is left
      // to the frequency's wrap).
      if (!spec.function || !spec.function->field) return 0.0;
      const double v = spec.function->field->value(p);
      return v > 1.0 ? std::fmod(v, 1.0) : v;
    }
    case PatternType::spherical:
      return clippedDistance(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
    case PatternType::cylindrical:
      return clippedDistance(std::sqrt(p.x * p.x + p.z * p.z));
    case PatternType::boxed:
      return clippedDistance(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
    case PatternType::cells:
      return cellsValue(p);
    case PatternType::tiling:
      return tilingValue(spec.tiling, p);
    case PatternType::pavement:
      return pavementValue(spec.pavement, p);
    case PatternType::pigment:
      return pigmentGrey(spec, p);
    case PatternType::slope:
      return slopeValue(spec.slope, p, currentPatternSurface());
    case PatternType::image:
      return spec.image ? imagePatternValue(*spec.image, p) : 0.0;
    case PatternType::object:
      // POV-Ray's Inside_Object: the solid's own test, its clips included.
      return spec.object && spec.object->solid && spec.object->solid->inside(p) ? 1.0 : 0.0;
    case PatternType::facets:  // a normal only, with no value (the parsers refuse one)
      return 0.0;
  }
  return 0.0;
}

double patternValueAt(const PatternSpec& spec, const Vec3& patternPoint) {
  const double v = shapeValue(rawPatternValue(spec, patternPoint), spec);
  // Only absurd points (|p| near 1e300, where squares overflow) give NaN; POV-Ray would
  // return it, Lucent returns 0 so a colour map or a normal never sees it.
  return std::isnan(v) ? 0.0 : v;
}

double patternValue(const PatternSpec& spec, const Vec3& objectPoint) {
  const Vec3 p = warpPoint(spec.placement, objectPoint, turbulenceDisplaces(spec.type));
  return patternValueAt(spec, p);
}

}  // namespace lucent
