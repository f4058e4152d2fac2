#include "normal_perturbation.h"

#include "facets.h"
#include "normal_map.h"
#include "pattern_point.h"
#include "pattern_value.h"
#include "primitives/noise.h"
#include "warp.h"
#include "wave_sources.h"

#include <cmath>

namespace lucent {

namespace {

// POV-Ray's sampling directions (normal.cpp, Pyramid_Vect): a regular tetrahedron.
constexpr double kPyramid[4][3] = {{0.942809041, -0.333333333, 0.0},
                                   {-0.471404521, -0.333333333, 0.816496581},
                                   {-0.471404521, -0.333333333, -0.816496581},
                                   {0.0, 1.0, 0.0}};

// POV-Ray's VNormalize: a multiplication by the reciprocal length.
Vec3 normalised(const Vec3& v) {
  const double inv = 1.0 / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return Vec3(v.x * inv, v.y * inv, v.z * inv);
}

// r_i = Σ_j n_j·m[i][j] (POV-Ray's normal transforms; POV-Ray's row-vector matrices have
// glm's memory layout): with m = patternFromObject this is its transpose times n.
Vec3 transposedTimes(const Mat3& m, const Vec3& n) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = n.x * m[i][0] + n.y * m[i][1] + n.z * m[i][2];
  return r;
}

Vec3 addScaled(const Vec3& n, double k, const Vec3& v) {
  return Vec3(n.x + k * v.x, n.y + k * v.y, n.z + k * v.z);
}

Vec3 wrinkles(const Vec3& n, const Vec3& p, double amount) {
  Vec3 sum(0.0);
  double scale = 1.0;
  for (int i = 0; i < 10; scale *= 2.0, ++i) {
    const Vec3 d = dnoise(Vec3(p.x * scale, p.y * scale, p.z * scale));
    sum.x += std::fabs(d.x / scale);
    sum.y += std::fabs(d.y / scale);
    sum.z += std::fabs(d.z / scale);
  }
  return addScaled(n, amount, sum);
}

// The slope estimate; a slope map turns each sampled value into its height first.
Vec3 slope(const NormalSpec& normal, const Vec3& n, const Vec3& p, double amount) {
  const double delta = static_cast<float>(normal.accuracy);  // single precision, as POV-Ray's
  const double k = amount * -5.0 * (0.02 / delta);           // POV-Ray's "fudge factor"
  Vec3 r = n;
  for (const auto& d : kPyramid) {
    const Vec3 q(p.x + delta * d[0], p.y + delta * d[1], p.z + delta * d[2]);
    // A block pattern without a list of normals: the slope of its cell index, as POV-Ray's.
    double value = normal.block != NormalBlock::none ? normalBlockIndex(normal, q)
                                                     : patternValueAt(normal.pattern, q);
    if (!normal.slopeMap.empty()) value = slopeMapHeight(normal.slopeMap, value);
    r = addScaled(r, value * k, Vec3(d[0], d[1], d[2]));
  }
  return r;
}

// The pattern's own bend of the pattern-space normal n at the pattern point p.
Vec3 perturbByPattern(const NormalSpec& normal, Vec3 n, const Vec3& p, double amount) {
  const PatternSpec& spec = normal.pattern;
  switch (spec.type) {
    case PatternType::bumps:
      return addScaled(n, amount, dnoise(p));
    case PatternType::dents: {
      const double v = noise(p, spec.noiseGenerator);
      return addScaled(n, v * v * v * amount, dnoise(p));
    }
    case PatternType::wrinkles:
      return wrinkles(n, p, amount);
    case PatternType::quilted:  // POV-Ray's own quilted normal, not the slope
      return addScaled(n, amount, quiltedOffset(p, spec.quilted));
    case PatternType::ripples:
      return ripplesNormal(n, p, spec.frequency, spec.phase, amount, spec.waveSources);
    case PatternType::waves:
      return wavesNormal(n, p, spec.frequency, spec.phase, amount, spec.waveSources);
    case PatternType::facets:  // POV-Ray's facets takes no amount
      return facetsNormal(spec.facets, n, p);
    default:
      return slope(normal, n, p, amount);
  }
}

// POV-Ray's average: each normal bent at the average's point in the average's space (its
// own placement composing with the average's), weighted in single precision; the mean is
// normalised on the way back.
Vec3 averageNormal(const NormalSpec& normal, const Vec3& n, const Vec3& objPoint) {
  const Vec3 q = warpPoint(normal.pattern.placement, objPoint);
  Vec3 sum(0.0);
  float total = 0.0f;
  for (const WeightedNormal& e : normal.average) {
    const float w = static_cast<float>(e.weight);
    sum = addScaled(sum, w, perturbNormal(e.normal, q, n));
    total += w;
  }
  return sum / static_cast<double>(total);
}

// POV-Ray's normal_map and block lists: the pattern's value (a block pattern's cell) at
// the map's point picks one entry, or two whose bent normals are blended linearly (not
// normalised in between); each entry is bent at that point from the map-space normal n.
Vec3 mapNormal(const NormalSpec& normal, const Vec3& n, const Vec3& objPoint) {
  const PatternSpec& spec = normal.pattern;
  const bool block = normal.block != NormalBlock::none;
  const Vec3 q = warpPoint(spec.placement, objPoint, block || turbulenceDisplaces(spec.type));
  const double value = block ? normalBlockIndex(normal, q) : patternValueAt(spec, q);
  const MapSearch s = searchMap(normal.map, value);
  auto bent = [&](const NormalMapEntry& e) { return e.flat ? n : perturbNormal(e.normal, q, n); };
  const Vec3 cur = bent(normal.map[s.cur]);
  if (s.prev == s.cur) return cur;
  const Vec3 prev = bent(normal.map[s.prev]);
  return addScaled(Vec3(prev.x * (1.0 - s.t), prev.y * (1.0 - s.t), prev.z * (1.0 - s.t)), s.t,
                   cur);
}

}  // namespace

Vec3 perturbNormal(const NormalSpec& normal, const Vec3& objPoint, const Vec3& objNormal) {
  const PatternSpec& spec = normal.pattern;
  // POV-Ray carries the normal through the transforms only, not through the other warps.
  const Mat4 m = spec.placement.warps.empty() ? spec.placement.patternFromObject
                                              : linearPatternFromObject(spec.placement);
  const bool identity = m == Mat4(1.0);
  const Mat3 toPattern = identity ? Mat3(1.0) : glm::inverse(Mat3(m));
  const double amount = static_cast<float>(normal.depth);

  // Into pattern space with the transform's inverse transpose, normalised before and after
  // as POV-Ray's Warp_Normal does (twice even without a transform).
  Vec3 n = normalised(objNormal);
  if (!identity) n = transposedTimes(toPattern, n);
  n = normalised(n);

  if (!normal.average.empty()) {
    n = averageNormal(normal, n, objPoint);
  } else if (!normal.map.empty()) {
    n = mapNormal(normal, n, objPoint);
  } else if (normal.block != NormalBlock::none) {
    n = slope(normal, n, warpPoint(spec.placement, objPoint), amount);
  } else {
    n = perturbByPattern(
        normal, n, warpPoint(spec.placement, objPoint, turbulenceDisplaces(spec.type)), amount);
  }

  // Back to object space (POV-Ray's UnWarp_Normal), unit length.
  n = normalised(n);
  if (!identity) n = transposedTimes(Mat3(m), n);
  n = normalised(n);
  // A perturbation that overflowed (points near 1e300) leaves the normal unperturbed.
  return isFinite(n) ? n : normalised(objNormal);
}

}  // namespace lucent
