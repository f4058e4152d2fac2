#include "renderer.h"

#include "pixel_passes.h"

#include <tbb/task_arena.h>

#include <chrono>
#include <stdexcept>

namespace lucent {

Renderer::Renderer(const World& world, const Camera& camera, ImageMapCache* textures)
    : settings_(world.scene().render),
      projection_(makeProjection(camera, settings_.width, settings_.height)),
      tracer_(world, textures),
      camera_(*projection_, tracer_, settings_.background, settings_.samples,
              camera.focalBlur ? &*camera.focalBlur : nullptr),
      sampler_(makePixelSampler(settings_, camera_)) {}

RenderResult Renderer::render(const RenderControl& control) const {
  const PixelRect image = wholeImage(settings_.width, settings_.height);
  if (control.progress) control.progress->workTotal = work(image);
  return renderRect(image, control);
}

uint64_t Renderer::work(const PixelRect& rect) const { return sampler_->work(rect); }

RenderResult Renderer::renderRect(const PixelRect& rect, const RenderControl& control) const {
  const auto start = std::chrono::steady_clock::now();
  if (rect.empty() || !wholeImage(settings_.width, settings_.height).contains(rect))
    throw std::invalid_argument("Renderer::renderRect: the rectangle is empty or leaves the image");
  RenderResult result;
  result.image = Image(rect.width(), rect.height());
  PixelPasses passes(control);
  auto run = [&] { sampler_->render(rect, passes, result.image); };
  if (control.threads > 0) {
    tbb::task_arena arena(control.threads);
    arena.execute(run);
  } else {
    run();
  }
  result.stats = passes.stats();
  result.cancelled = passes.cancelled();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lucent
