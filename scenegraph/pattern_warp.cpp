#include "pattern_warp.h"

namespace lucent {

void settleBlackHole(BlackHoleWarp& hole, bool changed[3]) {
  constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON
  for (int a = 0; a < 3; ++a) {
    changed[a] = false;
    if (!(hole.repeat[a] > 0.0)) continue;
    if (hole.center[a] < hole.radius) hole.center[a] = hole.radius;
    const double least = hole.center[a] + hole.radius + hole.turbulence[a];
    if (hole.repeat[a] < least) {
      hole.repeat[a] = least;
      changed[a] = true;
    }
    if (hole.repeat[a] < kEpsilon) hole.repeat[a] = 0.0;
  }
}

}  // namespace lucent
