// Fixed sampling: every pixel is the average of its `samples` camera samples (one: the
// pixel centre).
#pragma once

#include "pixel_sampler.h"

namespace lucent {

class FixedSampler : public PixelSampler {
 public:
  explicit FixedSampler(const CameraSamples& camera) : camera_(camera) {}

  uint64_t work(const PixelRect& rect) const override {
    return static_cast<uint64_t>(rect.pixels());
  }
  void render(const PixelRect& rect, PixelPasses& passes, Image& out) const override;

 private:
  const CameraSamples& camera_;
};

}  // namespace lucent
