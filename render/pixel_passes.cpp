#include "pixel_passes.h"

namespace lucent {

PixelPasses::PixelPasses(const RenderControl& control)
    : control_(control), progress_(control.progress ? *control.progress : localProgress_) {}

void PixelPasses::finishTile(RayStats& stats, uint64_t done, bool countsAsWork) {
  if (countsAsWork) progress_.workDone.fetch_add(done, std::memory_order_relaxed);
  progress_.rays.fetch_add(stats.rays(), std::memory_order_relaxed);
  perThread_.local() += stats;
}

RayStats PixelPasses::stats() const {
  RayStats sum;
  for (const RayStats& s : perThread_) sum += s;
  return sum;
}

}  // namespace lucent
