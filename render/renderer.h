// The image: the camera's samples (camera_samples.h) taken by the sampler the scene's
// <render> chooses (pixel_sampler.h), through the render loop's tiles over all cores
// (pixel_passes.h).
#pragma once

#include "camera_samples.h"
#include "image.h"
#include "pixel_rect.h"
#include "pixel_sampler.h"
#include "projection.h"
#include "ray_stats.h"
#include "render_control.h"
#include "tracer.h"

#include "scenegraph/world.h"

#include <cstdint>
#include <memory>

namespace lucent {

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
  // Its parts refer to each other (the sampler to the camera's samples, those to the tracer).
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The whole image. Bit-identical for any thread count and from run to run: a pixel's
  // value depends only on its coordinates. Sets control.progress's workTotal.
  RenderResult render(const RenderControl& control = {}) const;

  // The pixels of `rect` (inside the image, not empty) as an image of its size, each equal
  // bit for bit to the same pixel of render(): regions, checkpoint tiles and the tiles of
  // a distributed render are rendered with this. Leaves workTotal to the caller (work()).
  RenderResult renderRect(const PixelRect& rect, const RenderControl& control = {}) const;

  // The pixel passes renderRect(rect) counts into workDone (for a progress bar's total).
  uint64_t work(const PixelRect& rect) const;

  // How many pixels around a rectangle its pixels depend on (samplingMargin: adaptive
  // supersampling of centres decides after each stage whether a pixel goes on from its
  // neighbours' samples, so each stage reaches one pixel further; 0 in the other modes).
  int adaptiveMargin() const { return samplingMargin(settings_); }
  static int adaptiveMargin(const RenderSettings& settings) { return samplingMargin(settings); }

  // Pixel (x, y): the average of its `samples` camera samples.
  Color renderPixel(int x, int y, TraceContext& context) const {
    return camera_.pixel(x, y, context);
  }
  // One camera sample k of `count` in pixel (x, y).
  Color renderSample(int x, int y, int k, int count, TraceContext& context) const {
    return camera_.sample(x, y, k, count, context);
  }

  const Projection& projection() const { return *projection_; }
  const Tracer& tracer() const { return tracer_; }

 private:
  const RenderSettings settings_;  // a copy: the scene may change after the renderer is built
  std::unique_ptr<Projection> projection_;
  Tracer tracer_;
  CameraSamples camera_;
  std::unique_ptr<PixelSampler> sampler_;
};

}  // namespace lucent
