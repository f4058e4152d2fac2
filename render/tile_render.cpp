#include "tile_render.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <mutex>

namespace lucent {

int defaultTileSize(const RenderSettings& settings) {
  return Renderer::adaptiveMargin(settings) > 0 ? 128 : 32;
}

TilesToDo tilesToDo(const Renderer& renderer, const std::vector<PixelRect>& tiles,
                    const std::vector<char>& skip) {
  TilesToDo out;
  for (size_t i = 0; i < tiles.size(); ++i)
    if (skip.empty() || !skip[i]) {
      out.indices.push_back(i);
      out.work += renderer.work(tiles[i]);
    }
  return out;
}

RenderControl tileControl(const RenderControl& control, uint64_t work, RenderProgress& local) {
  RenderControl inner = control;
  inner.threads = 0;  // the caller's arena bounds them
  if (!inner.progress) inner.progress = &local;
  inner.progress->workTotal = work;
  return inner;
}

TileRenderResult renderTiles(const Renderer& renderer, const std::vector<PixelRect>& tiles,
                             const std::vector<char>& skip, const RenderControl& control,
                             bool oneAtATime, const TileFinished& finished) {
  const auto start = std::chrono::steady_clock::now();
  const TilesToDo toDo = tilesToDo(renderer, tiles, skip);
  const std::vector<size_t>& todo = toDo.indices;
  RenderProgress localProgress;
  const RenderControl inner = tileControl(control, toDo.work, localProgress);

  TileRenderResult result;
  std::mutex reporting;
  auto cancelled = [&] {
    return control.cancel && control.cancel->load(std::memory_order_relaxed);
  };
  auto renderOne = [&](size_t i) {
    if (cancelled()) return;
    RenderResult tile = renderer.renderRect(tiles[todo[i]], inner);
    std::lock_guard<std::mutex> lock(reporting);
    result.stats += tile.stats;
    if (!tile.cancelled) finished(todo[i], tile);
  };
  auto run = [&] {
    if (oneAtATime) {
      for (size_t i = 0; i < todo.size(); ++i) renderOne(i);
    } else {
      // One tile a task: tiles differ in cost, and each splits into threads' tiles anyway.
      tbb::parallel_for(
          size_t(0), todo.size(), [&](size_t i) { renderOne(i); }, tbb::simple_partitioner());
    }
  };
  if (control.threads > 0) {
    tbb::task_arena arena(control.threads);
    arena.execute(run);
  } else {
    run();
  }
  result.cancelled = cancelled();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lucent
