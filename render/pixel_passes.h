// The render loop: passes over the pixels of a rectangle in tiles of 16 x 16, spread over
// the threads. Every sampler (pixel_sampler.h) renders through it. Each tile traces with
// its thread's TraceContext (trace_context.h: counts, shadow cache, scratch), started empty
// for the tile; a tile adds its pixels to the progress and its rays to the ray count, and
// stops between two rows once the render is cancelled.
#pragma once

#include "pixel_rect.h"
#include "ray_stats.h"
#include "render_control.h"
#include "trace_context.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cstdint>

namespace lucent {

class PixelPasses {
 public:
  // `control`: its cancel flag and progress (either may be null); it must outlive this.
  explicit PixelPasses(const RenderControl& control);

  bool cancelled() const {
    return control_.cancel && control_.cancel->load(std::memory_order_relaxed);
  }

  // Runs body(state, x, y, context) for every pixel of `over`, tile by tile and in row order
  // inside a tile, where state = startTile(firstColumn, endColumn) is made once per tile (a
  // tile's own scratch). `countsAsWork`: the pixels count into the progress's workDone.
  template <class StartTile, class Body>
  void forEachTile(const PixelRect& over, StartTile&& startTile, Body&& body, bool countsAsWork);

  // Runs body(x, y, context) for every pixel of `over`, in tiles.
  template <class Body>
  void forEachPixel(const PixelRect& over, Body&& body, bool countsAsWork = true) {
    forEachTile(
        over, [](int, int) { return 0; },
        [&](int, int x, int y, TraceContext& context) { body(x, y, context); }, countsAsWork);
  }

  // The counts of every tile so far, summed.
  RayStats stats() const;

 private:
  // Tiles of 16 x 16 pixels: small enough to balance two to a hundred cores, big enough
  // that scheduling costs nothing next to tracing.
  static constexpr int kTile = 16;

  // A tile is done: its `done` pixels and its counts go to the progress and the sums.
  void finishTile(TraceContext& context, uint64_t done, bool countsAsWork);

  const RenderControl& control_;
  RenderProgress localProgress_;  // when the caller has none
  RenderProgress& progress_;
  // One trace context per worker thread.
  tbb::enumerable_thread_specific<TraceContext> contexts_;
};

template <class StartTile, class Body>
void PixelPasses::forEachTile(const PixelRect& over, StartTile&& startTile, Body&& body,
                              bool countsAsWork) {
  tbb::parallel_for(
      tbb::blocked_range2d<int>(over.y0, over.y1, kTile, over.x0, over.x1, kTile),
      [&](const tbb::blocked_range2d<int>& tile) {
        // The tile runs on this thread from start to end.
        TraceContext& context = contexts_.local();
        context.startTile();
        uint64_t done = 0;
        auto state = startTile(tile.cols().begin(), tile.cols().end());
        for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
          if (cancelled()) break;
          for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) body(state, x, y, context);
          done += tile.cols().size();
        }
        finishTile(context, done, countsAsWork);
      },
      tbb::simple_partitioner());
}

}  // namespace lucent
