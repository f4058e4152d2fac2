#include "corner_sampler.h"

#include "corner_sampling.h"
#include "pixel_passes.h"

namespace lucent {

void CornerSampler::traceCorners(const PixelRect& rect, PixelPasses& passes, int step,
                                 Image& corners, Image& encoded) const {
  passes.forEachPixel(rect, [&](int x, int y, TraceContext& context) {
    auto trace = [&](int i, int j) {
      Color& c = corners.at(i - rect.x0, j - rect.y0);
      c = camera_.latticeSample(i * step, j * step, step, context);
      encoded.at(i - rect.x0, j - rect.y0) = encodeForCornerTest(c);
    };
    trace(x, y);
    if (x == rect.x1 - 1) trace(x + 1, y);
    if (y == rect.y1 - 1) trace(x, y + 1);
    if (x == rect.x1 - 1 && y == rect.y1 - 1) trace(x + 1, y + 1);
  });
}

void CornerSampler::render(const PixelRect& rect, PixelPasses& passes, Image& out) const {
  const int step = 1 << (depth_ - 1);
  Image corners(rect.width() + 1, rect.height() + 1), encoded(rect.width() + 1, rect.height() + 1);
  traceCorners(rect, passes, step, corners, encoded);
  if (passes.cancelled()) return;
  const LatticeTrace trace = [&](int fx, int fy, TraceContext& context) {
    return camera_.latticeSample(fx, fy, step, context);
  };
  passes.forEachTile(
      rect,
      [&](int x0, int x1) {
        return CornerTile(corners, encoded, rect.x0, rect.y0, threshold_, depth_, x0, x1);
      },
      [&](CornerTile& tile, int x, int y, TraceContext& context) {
        out.at(x - rect.x0, y - rect.y0) = tile.pixel(x, y, trace, context);
      },
      true);
}

}  // namespace lucent
