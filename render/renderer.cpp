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

Color Renderer::refinePixel(int x, int y, const Color& centre, float threshold,
                            RayStats& stats, int* taken) const {
  const int count = std::max(1, settings_.samples);
  Color sum(0.0f);
  // The spread of everything seen in the pixel so far, the centre included.
  Color lowest = centre, highest = centre;
  int k = 0;
  for (int stage = std::min(kFirstStage, count);; stage = std::min(2 * stage, count)) {
    for (; k < stage; ++k) {
      const Color c = renderSample(x, y, k, count, stats);
      sum += c;  // summed in k order, so a pixel that takes all samples equals renderPixel's
      lowest = glm::min(lowest, c);
      highest = glm::max(highest, c);
    }
    if (k == count || maxComponent(highest - lowest) <= threshold) break;
  }
  if (taken) *taken = k;
  return sum / static_cast<float>(k);
}

RenderResult Renderer::render(const RenderControl& control) const {
  const auto start = std::chrono::steady_clock::now();
  const int width = settings_.width, height = settings_.height;
  const int samples = std::max(1, settings_.samples);
  // Adaptive: every pixel's centre first; then each pixel whose centre differs from one of
  // its eight neighbours' by more than the threshold is refined (refinePixel): its samples
  // come in doubling stages and stop once they all agree within the threshold.
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
      // The eight neighbours: a diagonal edge shows first between diagonal neighbours.
      bool differs = false;
      for (int dy = -1; dy <= 1 && !differs; ++dy)
        for (int dx = -1; dx <= 1 && !differs; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx || dy) && nx >= 0 && nx < width && ny >= 0 && ny < height)
            differs = colorDifference(c, centres.at(nx, ny)) > threshold;
        }
      if (differs) image.at(x, y) = refinePixel(x, y, c, threshold, stats);
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
