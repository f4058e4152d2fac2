#include "renderer.h"

#include "sampling.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>

namespace lucent {

namespace {

// Tiles of 16 x 16 pixels: small enough to balance two to a hundred cores, big enough
// that scheduling costs nothing next to tracing.
constexpr int kTile = 16;

// Largest per-channel difference of two linear colours, the adaptive threshold's measure.
float colorDifference(const Color& a, const Color& b) { return maxComponent(glm::abs(a - b)); }

}  // namespace

Renderer::Renderer(const World& world, const Camera& camera)
    : world_(world),
      settings_(world.scene().render),
      projection_(makeProjection(camera, settings_.width, settings_.height)),
      tracer_(world),
      cameraMedia_(tracer_.mediaAt(projection_->frame().origin)) {}

Color Renderer::renderSample(int x, int y, int k, int count, RayStats& stats) const {
  Vec2 film = Vec2(x, y) + pixelSampleOffset(k, count);
  Ray ray;
  if (!projection_->generateRay(film, lensSample(x, y, k, count), ray)) return settings_.background;
  PathSeed seed{static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(k), 0};
  return tracer_.traceCamera(ray, cameraMedia_, seed, stats);
}

Color Renderer::renderPixel(int x, int y, RayStats& stats) const {
  const int count = std::max(1, settings_.samples);
  Color sum(0.0f);
  for (int k = 0; k < count; ++k) sum += renderSample(x, y, k, count, stats);
  return sum / static_cast<float>(count);
}

RenderResult Renderer::render(const RenderControl& control) const {
  const auto start = std::chrono::steady_clock::now();
  const int width = settings_.width, height = settings_.height;
  const int samples = std::max(1, settings_.samples);
  // Adaptive: every pixel's centre first; then the pixels that differ from a neighbour
  // by more than the threshold get all `samples` samples (the centre is not counted
  // again, so such a pixel equals the non-adaptive render's).
  const bool adaptive = settings_.adaptive > 0.0 && samples > 1;
  const uint64_t pixels = static_cast<uint64_t>(width) * height;

  RenderResult result;
  result.image = Image(width, height);
  RenderProgress localProgress;
  RenderProgress& progress = control.progress ? *control.progress : localProgress;
  progress.workTotal = adaptive ? 2 * pixels : pixels;
  auto cancelled = [&] { return control.cancel && control.cancel->load(std::memory_order_relaxed); };

  tbb::enumerable_thread_specific<RayStats> perThread;
  // Runs body(x, y, stats) over the image in tiles, counting progress per tile.
  auto forEachPixel = [&](auto&& body) {
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, kTile, 0, width, kTile),
        [&](const tbb::blocked_range2d<int>& tile) {
          RayStats stats;
          uint64_t done = 0;
          // The tile runs on this thread from start to end, so the difference of the
          // thread's test counts is the tile's.
          const TestCounts testsBefore = threadTestCounts;
          for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
            if (cancelled()) break;
            for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) body(x, y, stats);
            done += tile.cols().size();
          }
          stats.tests = threadTestCounts - testsBefore;
          progress.workDone.fetch_add(done, std::memory_order_relaxed);
          progress.rays.fetch_add(stats.rays(), std::memory_order_relaxed);
          perThread.local() += stats;
        },
        tbb::simple_partitioner());
  };

  Image& image = result.image;
  auto run = [&] {
    if (!adaptive) {
      forEachPixel([&](int x, int y, RayStats& stats) { image.at(x, y) = renderPixel(x, y, stats); });
      return;
    }
    Image centres(width, height);
    forEachPixel([&](int x, int y, RayStats& stats) {
      centres.at(x, y) = renderSample(x, y, 0, 1, stats);
    });
    image = centres;
    if (cancelled()) return;
    const float threshold = static_cast<float>(settings_.adaptive);
    forEachPixel([&](int x, int y, RayStats& stats) {
      const Color c = centres.at(x, y);
      bool differs = (x > 0 && colorDifference(c, centres.at(x - 1, y)) > threshold) ||
                     (x + 1 < width && colorDifference(c, centres.at(x + 1, y)) > threshold) ||
                     (y > 0 && colorDifference(c, centres.at(x, y - 1)) > threshold) ||
                     (y + 1 < height && colorDifference(c, centres.at(x, y + 1)) > threshold);
      if (differs) image.at(x, y) = renderPixel(x, y, stats);
    });
  };

  if (control.threads > 0) {
    tbb::task_arena arena(control.threads);
    arena.execute(run);
  } else {
    run();
  }

  for (const RayStats& s : perThread) result.stats += s;
  result.cancelled = cancelled();
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lucent
