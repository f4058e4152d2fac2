// Corner sampling, POV-Ray's adaptive anti-aliasing method 2: first the pixel corners of the
// rectangle, each traced once (pixel (x, y) traces its top-left corner, the last column and
// row the corners beyond); then each tile splits its pixels where their corners differ
// (CornerTile, corner_sampling.h). A corner's colour depends on its lattice point alone, so
// a rectangle needs no margin.
#pragma once

#include "pixel_sampler.h"

namespace lucent {

class CornerSampler : public PixelSampler {
 public:
  // `threshold`: the test of corner_sampling.h; `depth` (1 to kMaxAdaptiveDepth): a pixel is
  // split at most depth - 1 times.
  CornerSampler(const CameraSamples& camera, float threshold, int depth)
      : camera_(camera), threshold_(threshold), depth_(depth) {}

  // A pass over the corners, then one over the pixels.
  uint64_t work(const PixelRect& rect) const override {
    return 2 * static_cast<uint64_t>(rect.pixels());
  }
  void render(const PixelRect& rect, PixelPasses& passes, Image& out) const override;

 private:
  // The pixel corners of `rect` into `corners` and, encoded for the corner test, into
  // `encoded` (both (width + 1) x (height + 1)), on the lattice of `step` points a pixel.
  void traceCorners(const PixelRect& rect, PixelPasses& passes, int step, Image& corners,
                    Image& encoded) const;

  const CameraSamples& camera_;
  const float threshold_;
  const int depth_;
};

}  // namespace lucent
