// The image loop: samples per pixel, adaptive supersampling, tiles over all cores.
#pragma once

#include "image.h"
#include "projection.h"
#include "ray_stats.h"
#include "tracer.h"

#include "scenegraph/world.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace lucent {

// Live counters another thread may read while rendering (the progress bar).
struct RenderProgress {
  std::atomic<uint64_t> workDone{0};  // pixel passes finished
  std::atomic<uint64_t> workTotal{0};  // pixel passes planned (2 per pixel when adaptive)
  std::atomic<uint64_t> rays{0};
};

struct RenderControl {
  int threads = 0;  // 0: every core
  // Polled before every row of every tile: once true, rendering stops within a row.
  const std::atomic<bool>* cancel = nullptr;
  RenderProgress* progress = nullptr;
};

struct RenderResult {
  Image image;  // linear RGB; pixels never rendered (after a cancel) are black
  RayStats stats;
  double seconds = 0.0;
  bool cancelled = false;
};

class Renderer {
 public:
  // Settings (size, samples, depth, ...) come from world.scene().render, so command-line
  // overrides are applied to the scene before the renderer is built. Throws CameraError
  // for a camera that cannot form an image and TextureError for an unreadable image.
  Renderer(const World& world, const Camera& camera);

  // The whole image. Bit-identical for any thread count and from run to run: a pixel's
  // value depends only on its coordinates.
  RenderResult render(const RenderControl& control = {}) const;

  // Pixel (x, y): the average of its `samples` camera samples.
  Color renderPixel(int x, int y, RayStats& stats) const;
  // Adaptive refinement of pixel (x, y) whose centre sample is `centre`: its samples are
  // traced in stages of 4, 8, 16, ... up to `samples` (the same sub-pixel positions as
  // renderPixel's, in the same order), stopping after a stage once every sample so far,
  // the centre included, lies within `threshold` of every other in each channel (POV-Ray's
  // adaptive anti-aliasing likewise subdivides only where its samples disagree). Returns
  // their mean, which is renderPixel's value when all samples are taken; `taken` receives
  // how many were.
  static constexpr int kFirstStage = 4;
  Color refinePixel(int x, int y, const Color& centre, float threshold, RayStats& stats,
                    int* taken = nullptr) const;
  // One camera sample k of `count` in pixel (x, y).
  Color renderSample(int x, int y, int k, int count, RayStats& stats) const;

  const Projection& projection() const { return *projection_; }
  const Tracer& tracer() const { return tracer_; }

 private:
  const World& world_;
  const RenderSettings settings_;  // a copy: the scene may change after the renderer is built
  std::unique_ptr<Projection> projection_;
  Tracer tracer_;
  MediaStack cameraMedia_;  // the solids the camera stands in
};

}  // namespace lucent
