// The image loop: samples per pixel, adaptive supersampling (of pixel centres, or of
// shared pixel corners: corner_sampling.h), tiles over all cores.
#pragma once

#include "image.h"
#include "pixel_rect.h"
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
  std::atomic<uint64_t> workDone{0};   // pixel passes finished
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
  // overrides are applied to the scene before the renderer is built. Throws LocatedError
  // for a camera that cannot form an image or an unreadable image texture. Image textures
  // come from `textures` when given (shared with other renderers), else are loaded.
  Renderer(const World& world, const Camera& camera, ImageMapCache* textures = nullptr);

  // The whole image. Bit-identical for any thread count and from run to run: a pixel's
  // value depends only on its coordinates. Sets control.progress's workTotal.
  RenderResult render(const RenderControl& control = {}) const;

  // The pixels of `rect` (inside the image, not empty) as an image of its size, each equal
  // bit for bit to the same pixel of render(): regions, checkpoint tiles and the tiles of
  // a distributed render are rendered with this. Leaves workTotal to the caller (work()).
  RenderResult renderRect(const PixelRect& rect, const RenderControl& control = {}) const;

  // The pixel passes renderRect(rect) counts into workDone (for a progress bar's total).
  uint64_t work(const PixelRect& rect) const;

  // How many pixels around a rectangle its pixels depend on: adaptive supersampling of
  // centres decides after each stage whether a pixel goes on from its neighbours' samples,
  // so each stage reaches one pixel further (the number of stages; 0 in the other modes).
  int adaptiveMargin() const;
  static int adaptiveMargin(const RenderSettings& settings);

  // Pixel (x, y): the average of its `samples` camera samples.
  Color renderPixel(int x, int y, RayStats& stats) const;
  // Adaptive supersampling takes a refined pixel's samples in stages of 6, 12, 24, ... up
  // to `samples`: the same sub-pixel positions as renderPixel's, in the same order, so a
  // pixel that takes them all equals renderPixel's. Why 6: Halton (2,3) points 1..6 fall one
  // in each cell of the pixel's 2 x 3 grid (index mod 2 picks the column, index mod 3 the
  // row), while points 1..4 leave the quarter x, y > 1/2 empty.
  static constexpr int kFirstStage = 6;

  // One camera sample k of `count` in pixel (x, y).
  Color renderSample(int x, int y, int k, int count, RayStats& stats) const;

  const Projection& projection() const { return *projection_; }
  const Tracer& tracer() const { return tracer_; }

 private:
  // The samples a refined pixel has taken so far: their sum and the range of their values
  // (the centre sample included in the range).
  struct PixelRefinement {
    Color sum{0.0f}, lowest{0.0f}, highest{0.0f};
    int taken = 0;
    bool disagrees(float threshold) const { return maxComponent(highest - lowest) > threshold; }
  };
  bool adaptiveCentres() const;  // adaptive supersampling of pixel centres
  // The sample at film position (fx, fy) / step (corners mode: a point of its lattice).
  Color renderLatticeSample(int fx, int fy, int step, RayStats& stats) const;
  // Traces samples r.taken .. upTo-1 of pixel (x, y) into r.
  void addSamples(int x, int y, int upTo, PixelRefinement& r, RayStats& stats) const;

  const RenderSettings settings_;  // a copy: the scene may change after the renderer is built
  std::unique_ptr<Projection> projection_;
  Tracer tracer_;
  MediaStack cameraMedia_;  // the solids the camera stands in
};

}  // namespace lucent
