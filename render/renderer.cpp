#include "renderer.h"

#include "corner_sampling.h"
#include "sampling.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
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
    : settings_(world.scene().render),
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
  const PixelRect image = wholeImage(settings_.width, settings_.height);
  if (control.progress) control.progress->workTotal = work(image);
  return renderRect(image, control);
}

bool Renderer::adaptiveCentres() const {
  return settings_.adaptiveMode != AdaptiveMode::Corners && settings_.adaptive > 0.0 &&
         settings_.samples > 1;
}

int Renderer::adaptiveMargin() const { return adaptiveMargin(settings_); }

int Renderer::adaptiveMargin(const RenderSettings& settings) {
  const bool centres = settings.adaptiveMode != AdaptiveMode::Corners && settings.adaptive > 0.0 &&
                       settings.samples > 1;
  if (!centres) return 0;
  const int samples = settings.samples;
  int stages = 1;
  for (int stage = std::min(kFirstStage, samples); stage < samples;
       stage = std::min(2 * stage, samples))
    ++stages;
  return stages;
}

uint64_t Renderer::work(const PixelRect& rect) const {
  const bool corners = settings_.adaptiveMode == AdaptiveMode::Corners;
  if (corners) return 2 * static_cast<uint64_t>(rect.pixels());
  if (!adaptiveCentres()) return static_cast<uint64_t>(rect.pixels());
  const PixelRect area =
      rect.grown(adaptiveMargin(), wholeImage(settings_.width, settings_.height));
  return 2 * static_cast<uint64_t>(area.pixels());
}

RenderResult Renderer::renderRect(const PixelRect& rect, const RenderControl& control) const {
  const auto start = std::chrono::steady_clock::now();
  const int width = settings_.width, height = settings_.height;
  const PixelRect whole = wholeImage(width, height);
  if (rect.empty() || !whole.contains(rect))
    throw std::invalid_argument("Renderer::renderRect: the rectangle is empty or leaves the image");
  const int samples = std::max(1, settings_.samples);
  // Adaptive: every pixel's centre first; then each pixel whose centre differs from one of
  // its eight neighbours' by more than the threshold is refined, in stages (see
  // PixelRefinement and the stopping rule below). Whether a pixel goes on after a stage
  // depends on its neighbours' samples, so the pixels of `rect` depend on pixels up to one
  // stage count beyond it: `area` holds those (adaptiveMargin), each pixel at distance d
  // from `rect` refined only through the stages that can still reach it.
  const bool corners = settings_.adaptiveMode == AdaptiveMode::Corners;
  const bool adaptive = corners || adaptiveCentres();
  const int margin = adaptiveMargin();
  const PixelRect area = rect.grown(margin, whole);

  RenderResult result;
  result.image = Image(rect.width(), rect.height());
  RenderProgress localProgress;
  RenderProgress& progress = control.progress ? *control.progress : localProgress;
  auto cancelled = [&] {
    return control.cancel && control.cancel->load(std::memory_order_relaxed);
  };

  tbb::enumerable_thread_specific<RayStats> perThread;
  // Runs body(state, x, y, stats) for every pixel of `over`, tile by tile and in row order
  // inside a tile, where state = startTile(firstColumn, endColumn) is made once per tile (a
  // tile's own scratch). Counts progress per tile.
  auto forEachTile = [&](const PixelRect& over, auto&& startTile, auto&& body, bool countsAsWork) {
    tbb::parallel_for(
        tbb::blocked_range2d<int>(over.y0, over.y1, kTile, over.x0, over.x1, kTile),
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
  // Runs body(x, y, stats) over `over` in tiles.
  auto forEachPixel = [&](const PixelRect& over, auto&& body, bool countsAsWork = true) {
    forEachTile(
        over, [](int, int) { return 0; },
        [&](int, int x, int y, RayStats& stats) { body(x, y, stats); }, countsAsWork);
  };

  Image& image = result.image;
  auto out = [&](int x, int y) -> Color& { return image.at(x - rect.x0, y - rect.y0); };
  // Corners mode: first the pixel corners of `rect`, each traced once (pixel (x, y) traces
  // its top-left corner, the last column and row the corners beyond); then each tile
  // splits its pixels where their corners differ (corner_sampling.h). A corner's colour
  // depends on its lattice point alone, so no margin is needed.
  auto runCorners = [&] {
    const int depth = std::clamp(settings_.adaptiveDepth, 1, kMaxAdaptiveDepth);
    const int step = 1 << (depth - 1);
    Image cornerImage(rect.width() + 1, rect.height() + 1),
        encodedCorners(rect.width() + 1, rect.height() + 1);
    forEachPixel(rect, [&](int x, int y, RayStats& stats) {
      auto trace = [&](int i, int j) {
        Color& c = cornerImage.at(i - rect.x0, j - rect.y0);
        c = renderLatticeSample(i * step, j * step, step, stats);
        encodedCorners.at(i - rect.x0, j - rect.y0) = encodeForCornerTest(c);
      };
      trace(x, y);
      if (x == rect.x1 - 1) trace(x + 1, y);
      if (y == rect.y1 - 1) trace(x, y + 1);
      if (x == rect.x1 - 1 && y == rect.y1 - 1) trace(x + 1, y + 1);
    });
    if (cancelled()) return;
    const float threshold = static_cast<float>(settings_.adaptive);
    const LatticeTrace trace = [&](int fx, int fy, RayStats& stats) {
      return renderLatticeSample(fx, fy, step, stats);
    };
    forEachTile(
        rect,
        [&](int x0, int x1) {
          return CornerTile(cornerImage, encodedCorners, rect.x0, rect.y0, threshold, depth, x0,
                            x1);
        },
        [&](CornerTile& tile, int x, int y, RayStats& stats) {
          out(x, y) = tile.pixel(x, y, trace, stats);
        },
        true);
  };

  auto run = [&] {
    if (corners) {
      runCorners();
      return;
    }
    if (!adaptive) {
      forEachPixel(rect,
                   [&](int x, int y, RayStats& stats) { out(x, y) = renderPixel(x, y, stats); });
      return;
    }
    const int areaWidth = area.width();
    auto at = [&](int x, int y) {
      return static_cast<size_t>(y - area.y0) * areaWidth + (x - area.x0);
    };
    // How far (in pixels, the chessboard distance) (x, y) lies outside `rect`.
    auto distance = [&](int x, int y) {
      return std::max({rect.x0 - x, x - (rect.x1 - 1), rect.y0 - y, y - (rect.y1 - 1), 0});
    };
    // Whether (x, y) still decides a pixel of `rect` when decisions reach `reach` pixels
    // further (the pixels of `rect` always do).
    auto reaches = [&](int x, int y, int reach) {
      const int d = distance(x, y);
      return d == 0 || d <= reach;
    };
    std::vector<Color> centres(static_cast<size_t>(area.pixels()));
    forEachPixel(area, [&](int x, int y, RayStats& stats) {
      centres[at(x, y)] = renderSample(x, y, 0, 1, stats);
    });
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) out(x, y) = centres[at(x, y)];
    if (cancelled()) return;
    const float threshold = static_cast<float>(settings_.adaptive);
    auto differ = [&](int x, int y, int nx, int ny) {
      return colorDifference(centres[at(x, y)], centres[at(nx, ny)]) > threshold;
    };
    // Calls f(nx, ny) for each of the eight neighbours of (x, y) inside the image (not
    // only inside `area`: a pixel sees the same neighbours in every rectangle): a diagonal
    // edge shows first between diagonal neighbours.
    auto forNeighbours = [&](int x, int y, auto&& f) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx || dy) && nx >= 0 && nx < width && ny >= 0 && ny < height) f(nx, ny);
        }
    };
    std::vector<PixelRefinement> refine(centres.size());
    std::vector<char> active(centres.size(), 0), next(centres.size(), 0);
    for (int y = area.y0; y < area.y1; ++y)
      for (int x = area.x0; x < area.x1; ++x) {
        PixelRefinement& r = refine[at(x, y)];
        r.lowest = r.highest = centres[at(x, y)];
        // A pixel at the margin's edge is never refined (its neighbours are not all known).
        if (distance(x, y) < margin)
          forNeighbours(x, y, [&](int nx, int ny) { active[at(x, y)] |= differ(x, y, nx, ny); });
      }
    // Stages of 6, 12, 24, ... samples. After a stage a pixel stops when its samples (and
    // its centre) agree within the threshold AND every neighbour whose centre differs from
    // its own shows that disagreement inside itself: the edge between the two centres is
    // then in the neighbour. Otherwise the edge may be in this pixel where its samples so
    // far missed it (a silhouette cutting off a corner that no sample fell in), so both
    // go on. Stage k (from 1) refines the pixels within margin - k of `rect`: only those
    // still decide a pixel of `rect` (one stage's decision reaches one pixel further).
    int k = 1;
    for (int stage = std::min(kFirstStage, samples);; stage = std::min(2 * stage, samples), ++k) {
      const int reach = margin - k;
      forEachPixel(
          area,
          [&](int x, int y, RayStats& stats) {
            if (active[at(x, y)] && reaches(x, y, reach))
              addSamples(x, y, stage, refine[at(x, y)], stats);
          },
          k == 1);
      if (cancelled() || stage == samples) break;
      bool any = false;
      for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x) {
          const size_t i = at(x, y);
          next[i] = 0;
          if (!active[i] || !reaches(x, y, reach - 1)) continue;
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
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x)
        if (const PixelRefinement& r = refine[at(x, y)]; r.taken > 0)
          out(x, y) = r.sum / static_cast<float>(r.taken);
  };

  if (control.threads > 0) {
    tbb::task_arena arena(control.threads);
    arena.execute(run);
  } else {
    run();
  }

  for (const RayStats& s : perThread) result.stats += s;
  result.cancelled = cancelled();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lucent
