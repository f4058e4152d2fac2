#include "renderer.h"

#include "corner_sampling.h"
#include "sampling.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace lucent {

namespace {

// Tiles of 16 x 16 pixels: small enough to balance two to a hundred cores, big enough
// that scheduling costs nothing next to tracing.
constexpr int kTile = 16;

// Largest per-channel difference of two linear colours, the adaptive threshold's measure.
float colorDifference(const Color& a, const Color& b) { return maxComponent(glm::abs(a - b)); }

}  // namespace

Renderer::Renderer(const World& world, const Camera& camera, ImageMapCache* textures)
    : world_(world),
      settings_(world.scene().render),
      projection_(makeProjection(camera, settings_.width, settings_.height)),
      tracer_(world, textures),
      cameraMedia_(tracer_.mediaAt(projection_->frame().origin)) {}

Color Renderer::renderSample(int x, int y, int k, int count, RayStats& stats) const {
  Vec2 film = Vec2(x, y) + pixelSampleOffset(k, count);
  Ray ray;
  if (!projection_->generateRay(film, lensSample(x, y, k, count), ray)) return settings_.background;
  PathSeed seed{static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(k), 0};
  return tracer_.traceCamera(ray, cameraMedia_, seed, stats);
}

Color Renderer::renderLatticeSample(int fx, int fy, int step, RayStats& stats) const {
  const Vec2 film = Vec2(fx, fy) / static_cast<double>(step);
  Ray ray;
  // The lens centre, as one sample per pixel takes: a lattice point is one sample.
  if (!projection_->generateRay(film, Vec2(0.5, 0.5), ray)) return settings_.background;
  // Seeded by the lattice point alone, so a sample traced by two tiles is the same sample.
  PathSeed seed{static_cast<uint32_t>(fx), static_cast<uint32_t>(fy),
                0x80000000u | static_cast<uint32_t>(step), 0};
  return tracer_.traceCamera(ray, cameraMedia_, seed, stats);
}

Color Renderer::renderPixel(int x, int y, RayStats& stats) const {
  const int count = std::max(1, settings_.samples);
  Color sum(0.0f);
  for (int k = 0; k < count; ++k) sum += renderSample(x, y, k, count, stats);
  return sum / static_cast<float>(count);
}

void Renderer::addSamples(int x, int y, int upTo, PixelRefinement& r, RayStats& stats) const {
  const int count = std::max(1, settings_.samples);
  for (; r.taken < upTo; ++r.taken) {
    const Color c = renderSample(x, y, r.taken, count, stats);
    r.sum += c;  // summed in k order, so a pixel that takes all samples equals renderPixel's
    r.lowest = glm::min(r.lowest, c);
    r.highest = glm::max(r.highest, c);
  }
}

RenderResult Renderer::render(const RenderControl& control) const {
  const auto start = std::chrono::steady_clock::now();
  const int width = settings_.width, height = settings_.height;
  const int samples = std::max(1, settings_.samples);
  // Adaptive: every pixel's centre first; then each pixel whose centre differs from one of
  // its eight neighbours' by more than the threshold is refined, in stages (see
  // PixelRefinement and the stopping rule below).
  const bool corners = settings_.adaptiveMode == AdaptiveMode::Corners;
  const bool adaptive = corners || (settings_.adaptive > 0.0 && samples > 1);
  const uint64_t pixels = static_cast<uint64_t>(width) * height;

  RenderResult result;
  result.image = Image(width, height);
  RenderProgress localProgress;
  RenderProgress& progress = control.progress ? *control.progress : localProgress;
  progress.workTotal = adaptive ? 2 * pixels : pixels;
  auto cancelled = [&] { return control.cancel && control.cancel->load(std::memory_order_relaxed); };

  tbb::enumerable_thread_specific<RayStats> perThread;
  // Runs body(state, x, y, stats) for every pixel, tile by tile and in row order inside a
  // tile, where state = startTile(firstColumn, endColumn) is made once per tile (a tile's
  // own scratch). Counts progress per tile.
  auto forEachTile = [&](auto&& startTile, auto&& body, bool countsAsWork) {
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, kTile, 0, width, kTile),
        [&](const tbb::blocked_range2d<int>& tile) {
          RayStats stats;
          uint64_t done = 0;
          // The tile runs on this thread from start to end, so the difference of the
          // thread's test counts is the tile's.
          const TestCounts testsBefore = threadTestCounts;
          auto state = startTile(tile.cols().begin(), tile.cols().end());
          for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
            if (cancelled()) break;
            for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) body(state, x, y, stats);
            done += tile.cols().size();
          }
          stats.tests = threadTestCounts - testsBefore;
          if (countsAsWork) progress.workDone.fetch_add(done, std::memory_order_relaxed);
          progress.rays.fetch_add(stats.rays(), std::memory_order_relaxed);
          perThread.local() += stats;
        },
        tbb::simple_partitioner());
  };
  // Runs body(x, y, stats) over the image in tiles.
  auto forEachPixel = [&](auto&& body, bool countsAsWork = true) {
    forEachTile([](int, int) { return 0; },
                [&](int, int x, int y, RayStats& stats) { body(x, y, stats); }, countsAsWork);
  };

  Image& image = result.image;
  // Corners mode: first the (W+1) x (H+1) pixel corners, each traced once (pixel (x, y)
  // traces its top-left corner, the last column and row the corners beyond); then each tile
  // splits its pixels where their corners differ (corner_sampling.h).
  auto runCorners = [&] {
    const int depth = std::clamp(settings_.adaptiveDepth, 1, kMaxAdaptiveDepth);
    const int step = 1 << (depth - 1);
    Image cornerImage(width + 1, height + 1), encodedCorners(width + 1, height + 1);
    forEachPixel([&](int x, int y, RayStats& stats) {
      auto trace = [&](int i, int j) {
        cornerImage.at(i, j) = renderLatticeSample(i * step, j * step, step, stats);
        encodedCorners.at(i, j) = encodeForCornerTest(cornerImage.at(i, j));
      };
      trace(x, y);
      if (x == width - 1) trace(width, y);
      if (y == height - 1) trace(x, height);
      if (x == width - 1 && y == height - 1) trace(width, height);
    });
    if (cancelled()) return;
    const float threshold = static_cast<float>(settings_.adaptive);
    const LatticeTrace trace = [&](int fx, int fy, RayStats& stats) {
      return renderLatticeSample(fx, fy, step, stats);
    };
    forEachTile(
        [&](int x0, int x1) {
          return CornerTile(cornerImage, encodedCorners, threshold, depth, x0, x1);
        },
        [&](CornerTile& tile, int x, int y, RayStats& stats) {
          image.at(x, y) = tile.pixel(x, y, trace, stats);
        },
        true);
  };

  auto run = [&] {
    if (corners) {
      runCorners();
      return;
    }
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
    auto at = [&](int x, int y) { return static_cast<size_t>(y) * width + x; };
    auto differ = [&](int x, int y, int nx, int ny) {
      return colorDifference(centres.at(x, y), centres.at(nx, ny)) > threshold;
    };
    // Calls f(nx, ny) for each of the eight neighbours of (x, y) inside the image: a
    // diagonal edge shows first between diagonal neighbours.
    auto forNeighbours = [&](int x, int y, auto&& f) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx || dy) && nx >= 0 && nx < width && ny >= 0 && ny < height) f(nx, ny);
        }
    };
    std::vector<PixelRefinement> refine(pixels);
    std::vector<char> active(pixels, 0), next(pixels, 0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        PixelRefinement& r = refine[at(x, y)];
        r.lowest = r.highest = centres.at(x, y);
        forNeighbours(x, y, [&](int nx, int ny) { active[at(x, y)] |= differ(x, y, nx, ny); });
      }
    // Stages of 6, 12, 24, ... samples. After a stage a pixel stops when its samples (and
    // its centre) agree within the threshold AND every neighbour whose centre differs from
    // its own shows that disagreement inside itself: the edge between the two centres is
    // then in the neighbour. Otherwise the edge may be in this pixel where its samples so
    // far missed it (a silhouette cutting off a corner that no sample fell in), so both
    // go on.
    bool first = true;
    for (int stage = std::min(kFirstStage, samples);; stage = std::min(2 * stage, samples)) {
      forEachPixel(
          [&](int x, int y, RayStats& stats) {
            if (active[at(x, y)]) addSamples(x, y, stage, refine[at(x, y)], stats);
          },
          first);
      first = false;
      if (cancelled() || stage == samples) break;
      bool any = false;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const size_t i = at(x, y);
          next[i] = 0;
          if (!active[i]) continue;
          bool settled = !refine[i].disagrees(threshold);
          forNeighbours(x, y, [&](int nx, int ny) {
            if (settled && differ(x, y, nx, ny) && !refine[at(nx, ny)].disagrees(threshold))
              settled = false;
          });
          next[i] = !settled;
          any |= !settled;
        }
      active.swap(next);
      if (!any) break;
    }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (const PixelRefinement& r = refine[at(x, y)]; r.taken > 0)
          image.at(x, y) = r.sum / static_cast<float>(r.taken);
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
