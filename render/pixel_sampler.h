// How a render chooses the samples of its pixels, one strategy per class behind one
// interface, picked by the scene's <render> (docs/scene-language.md):
//   fixed             every pixel takes `samples` samples (fixed_sampler.h);
//   adaptive centres  every pixel's centre, then more samples, in stages, where neighbouring
//                     centres differ (adaptive_centre_sampler.h);
//   corners           POV-Ray's method 2: pixel corners shared with the neighbours, squares
//                     split where they differ (corner_sampler.h, corner_sampling.h).
// A sampler takes its colours from CameraSamples (camera_samples.h) and renders through the
// render loop (pixel_passes.h); whatever the strategy, a pixel's value depends on its
// coordinates alone, never on the rectangle asked for or the threads.
#pragma once

#include "camera_samples.h"
#include "image.h"
#include "pixel_rect.h"

#include "scenegraph/render_settings.h"

#include <cstdint>
#include <memory>

namespace lucent {

class PixelPasses;

class PixelSampler {
 public:
  virtual ~PixelSampler() = default;

  // The pixel passes render(rect) counts into the progress's workDone.
  virtual uint64_t work(const PixelRect& rect) const = 0;

  // The pixels of `rect` (inside the image, not empty) into `out`, an image of rect's size:
  // pixel (x, y) is out.at(x - rect.x0, y - rect.y0). Pixels left unrendered by a cancel
  // are left as they were.
  virtual void render(const PixelRect& rect, PixelPasses& passes, Image& out) const = 0;
};

// The sampler `settings` choose, over `camera` (which it keeps a reference to).
std::unique_ptr<PixelSampler> makePixelSampler(const RenderSettings& settings,
                                               const CameraSamples& camera);

// How many pixels around a rectangle its pixels depend on with these settings: the
// adaptive centre sampler's stage count, 0 with the others.
int samplingMargin(const RenderSettings& settings);

}  // namespace lucent
