// The camera's samples: the ray through a position of the film (and of the lens), traced
// into the scene. Every sampler (pixel_sampler.h) takes its colours from here, and a
// sample's colour depends only on where it is and its index, never on the thread or the
// tile that asks: that is why images are bit-identical for any thread count.
#pragma once

#include "focal_blur.h"
#include "media_stack.h"
#include "projection.h"
#include "trace_context.h"
#include "tracer.h"

#include <optional>

namespace lucent {

class CameraSamples {
 public:
  // `samples`: how many a pixel takes (at least 1); `background`: a sample whose film
  // position the projection maps to no ray; `focalBlur`, if given, makes each sample the
  // average of its rays through the lens (focal_blur.h; the projection moves them).
  CameraSamples(const Projection& projection, const Tracer& tracer, Color background, int samples,
                const Camera::FocalBlur* focalBlur = nullptr);

  int samples() const { return samples_; }

  // Sample k of `count` in pixel (x, y): the Halton sub-pixel offset and the lens position
  // of sampling.h (under focal blur: its rays about that offset).
  Color sample(int x, int y, int k, int count, TraceContext& context) const;
  // Pixel (x, y): the average of its samples() samples.
  Color pixel(int x, int y, TraceContext& context) const;
  // The sample at film position (fx, fy) / step (corner sampling: a point of its lattice),
  // through the lens centre (under focal blur: its rays about that point).
  Color latticeSample(int fx, int fy, int step, TraceContext& context) const;

 private:
  // One ray at `film` through `lens`, seeded by (x, y, sample).
  Color trace(const Vec2& film, const Vec2& lens, uint32_t x, uint32_t y, uint32_t sample,
              TraceContext& context) const;
  // The sample at `film`, seeded by (x, y, sample): one ray through `lens`, or under focal
  // blur the average of its rays.
  Color sampleAt(const Vec2& film, const Vec2& lens, uint32_t x, uint32_t y, uint32_t sample,
                 TraceContext& context) const;

  const Projection& projection_;
  const Tracer& tracer_;
  const MediaStack cameraMedia_;  // the solids the camera stands in
  const Color background_;
  const int samples_;
  std::optional<FocalBlurSampler> focalBlur_;
};

}  // namespace lucent
