#include "normal_map.h"

#include "block_pattern.h"

#include <cmath>

namespace lucent {

double slopeMapHeight(const std::vector<SlopeMapEntry>& map, double value) {
  const MapSearch s = searchMap(map, value);
  const SlopeMapEntry& a = map[s.prev];
  const SlopeMapEntry& b = map[s.cur];
  if (s.prev == s.cur) return b.height;
  const double t = s.t, tt = t * t, ttt = tt * t;
  // h0(2t³ − 3t² + 1) + s0(t³ − 2t² + t) + h1(3t² − 2t³) + s1(t³ − t²), gathered by powers.
  return ttt * (a.slope + b.slope + 2.0 * (a.height - b.height)) -
         tt * (2.0 * a.slope + b.slope + 3.0 * (a.height - b.height)) + t * a.slope + a.height;
}

int normalBlockIndex(const NormalSpec& normal, const Vec3& p) {
  switch (normal.block) {
    case NormalBlock::checker: {
      constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON: a boundary is the upper cell's
      const double sum =
          std::floor(p.x + kEpsilon) + std::floor(p.y + kEpsilon) + std::floor(p.z + kEpsilon);
      return std::isfinite(sum) ? static_cast<int>(std::fmod(std::fabs(sum), 2.0)) : 0;
    }
    case NormalBlock::hexagon:
      return hexagonIndex(p);
    case NormalBlock::brick:
      return brickIndex(normal.brick, p);
    case NormalBlock::none:
      break;
  }
  return 0;
}

}  // namespace lucent
