#include "pixel_passes.h"

namespace lucent {

PixelPasses::PixelPasses(const RenderControl& control)
    : control_(control), progress_(control.progress ? *control.progress : localProgress_) {}

void PixelPasses::finishTile(TraceContext& context, uint64_t done, bool countsAsWork) {
  const RayStats& counts = context.finishTile();
  if (countsAsWork) progress_.workDone.fetch_add(done, std::memory_order_relaxed);
  progress_.rays.fetch_add(counts.rays(), std::memory_order_relaxed);
}

RayStats PixelPasses::stats() const {
  RayStats sum;
  for (const TraceContext& c : contexts_) sum += c.total();
  return sum;
}

}  // namespace lucent
