#include "preview_render.h"

#include "coarse_passes.h"
#include "json_text.h"
#include "png_bytes.h"

#include "render/renderer.h"
#include "render/tile_render.h"
#include "render/trace_context.h"
#include "render/working_gamma.h"
#include "scenegraph/world.h"

#include <fmt/core.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace lucent::preview {

namespace {

using Contexts = tbb::enumerable_thread_specific<TraceContext>;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The PNG of the image's light: its values decoded when the scene has a working gamma.
std::string lightPng(const Image& image, const WorkingGamma& gamma) {
  Image storage;
  return pngBytes(lightOf(image, gamma, storage));
}

// A picture of the whole width x height image: `image` holds one value per step x step
// block.
std::string pictureEvent(const Image& image, int step, int width, int height,
                         const WorkingGamma& gamma) {
  return fmt::format(
      "{{\"step\":{},\"width\":{},\"height\":{},\"imageWidth\":{},\"imageHeight\":{},"
      "\"png\":\"{}\"}}",
      step, image.width, image.height, width, height, base64(lightPng(image, gamma)));
}

std::string tileEvent(const PixelRect& r, const Image& image, const WorkingGamma& gamma) {
  return fmt::format("{{\"x\":{},\"y\":{},\"width\":{},\"height\":{},\"png\":\"{}\"}}", r.x0, r.y0,
                     r.width(), r.height(), base64(lightPng(image, gamma)));
}

void publishStatus(PreviewRun& run) {
  run.status.seconds = secondsSince(run.start);
  run.board.publishStatus(run.status.json());
}

// One coarse pass: the pixels it traces into `traced`, then its grid sent as a picture.
// False when cancelled.
bool coarsePass(const Renderer& renderer, Image& traced, int step, int firstStep, PreviewRun& run,
                Contexts& contexts) {
  const int rows = gridSize(traced.height, step);
  tbb::parallel_for(0, rows, [&](int j) {
    if (run.cancel.load(std::memory_order_relaxed)) return;
    TraceContext& context = contexts.local();
    const int y = j * step;
    for (int x = 0; x < traced.width; x += step)
      if (tracedInPass(x, y, step, firstStep))
        traced.at(x, y) = renderer.renderPixel(x, y, context);
  });
  if (run.cancel.load()) return false;
  Image grid(gridSize(traced.width, step), rows);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) grid.at(i, j) = traced.at(i * step, j * step);
  run.board.publishImage(pictureEvent(grid, step, traced.width, traced.height, run.gamma));
  run.status.phase = "coarse";
  run.status.step = step;
  publishStatus(run);
  return true;
}

bool coarsePasses(const Renderer& renderer, int width, int height, PreviewRun& run) {
  Image traced(width, height);
  Contexts contexts;
  const std::vector<int> steps = coarseSteps(width, height);
  tbb::task_arena arena(run.threads > 0 ? run.threads : tbb::task_arena::automatic);
  for (int step : steps) {
    bool done = false;
    arena.execute([&] { done = coarsePass(renderer, traced, step, steps.front(), run, contexts); });
    if (!done) return false;
  }
  return true;
}

// The tiles of `area` into `out.image`. False when cancelled.
bool tilePass(const Renderer& renderer, const RenderSettings& settings, const PixelRect& area,
              PreviewRun& run, PreviewOutcome& out) {
  const std::vector<PixelRect> tiles = tilesOf(area, defaultTileSize(settings));
  RenderControl control;
  control.threads = run.threads;
  control.cancel = &run.cancel;
  run.status.phase = "tiles";
  run.status.done = 0;
  run.status.total = tiles.size();
  publishStatus(run);
  const TileRenderResult result =
      renderTiles(renderer, tiles, {}, control, false, [&](size_t i, const RenderResult& tile) {
        const PixelRect& r = tiles[i];
        for (int y = 0; y < r.height(); ++y)
          for (int x = 0; x < r.width(); ++x)
            out.image.at(r.x0 + x, r.y0 + y) = tile.image.at(x, y);
        run.board.publishTile(fmt::format("{},{}", r.x0, r.y0),
                              tileEvent(r, tile.image, run.gamma));
        ++run.status.done;
        publishStatus(run);
      });
  out.stats = result.stats;
  out.seconds = result.seconds;
  return !result.cancelled;
}

}  // namespace

PreviewOutcome renderForPage(const cli::LoadedScene& loaded, PreviewRun& run) {
  const RenderSettings& settings = loaded.scene->render;
  World world(*loaded.scene);
  Renderer renderer(world, *loaded.camera);
  PreviewOutcome out;
  run.gamma = settings.workingGamma;
  run.status.width = settings.width;
  run.status.height = settings.height;
  const PixelRect whole = wholeImage(settings.width, settings.height);
  const bool sameSize = run.previous && run.previous->width == settings.width &&
                        run.previous->height == settings.height;
  if (run.region && whole.contains(*run.region)) {
    out.image = sameSize ? *run.previous : Image(settings.width, settings.height);
    out.cancelled = !tilePass(renderer, settings, *run.region, run, out);
  } else {
    run.status.region.clear();  // none, or not inside this image: the whole image
    out.image = Image(settings.width, settings.height);
    out.cancelled = !coarsePasses(renderer, settings.width, settings.height, run) ||
                    !tilePass(renderer, settings, whole, run, out);
  }
  if (out.cancelled) return out;
  run.board.publishImage(pictureEvent(out.image, 1, out.image.width, out.image.height, run.gamma));
  run.status.phase = "done";
  return out;
}

}  // namespace lucent::preview
