#include "fixed_sampler.h"

#include "pixel_passes.h"

namespace lucent {

void FixedSampler::render(const PixelRect& rect, PixelPasses& passes, Image& out) const {
  passes.forEachPixel(rect, [&](int x, int y, TraceContext& context) {
    out.at(x - rect.x0, y - rect.y0) = camera_.pixel(x, y, context);
  });
}

}  // namespace lucent
