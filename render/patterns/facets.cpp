#include "facets.h"

#include "crackle.h"
#include "primitives/noise.h"

#include <cmath>

namespace lucent {

namespace {

// POV-Ray's facet distances: metric 1 sums the signed differences (not their absolute
// values), as its facets does; crackle's metric 1 differs.
double facetDistance(const Vec3& d, double metric) {
  if (metric == 2.0) return d.x * d.x + d.y * d.y + d.z * d.z;
  if (metric == 1.0) return d.x + d.y + d.z;
  return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
         std::pow(std::fabs(d.z), metric);
}

}  // namespace

Vec3 facetsNormal(const FacetsParams& facets, const Vec3& n, const Vec3& p) {
  const double inv = 1.0 / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  const Vec3 unit(n.x * inv, n.y * inv, n.z * inv);
  // A size below 1e-6 counts as 1e-6 (POV-Ray's guard against dividing by zero).
  const double scale = facets.size < 1e-6 ? 1e6 : 1.0 / facets.size;
  const Vec3 base = facets.coords != 0.0 ? p : unit;
  const Vec3 tv(base.x * scale, base.y * scale, base.z * scale);

  Vec3 points[kCrackleCubes];
  crackleCubePoints(tv, points);
  Vec3 nearest = points[0];
  double best = facetDistance(points[0] - tv, facets.metric);
  for (int i = 1; i < kCrackleCubes; ++i) {
    const double d = facetDistance(points[i] - tv, facets.metric);
    if (d < best) {
      best = d;
      nearest = points[i];
    }
  }
  if (facets.coords == 0.0) return nearest;
  // The noise gradient at the facet's point, less its part along the normal.
  const Vec3 g = dnoise(nearest);
  const double along = g.x * unit.x + g.y * unit.y + g.z * unit.z;
  const Vec3 across(g.x - along * unit.x, g.y - along * unit.y, g.z - along * unit.z);
  return Vec3(unit.x + facets.coords * across.x, unit.y + facets.coords * across.y,
              unit.z + facets.coords * across.z);
}

}  // namespace lucent
