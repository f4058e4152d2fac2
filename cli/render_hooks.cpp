#include "render_hooks.h"

#include <fmt/core.h>

#include <csignal>
#include <cstdlib>
#include <fstream>

namespace lucent::cli {

void TileCostRecorder::tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) {
  costs_.emplace_back(job.tiles()[index], tile.seconds);
}

void TileCostRecorder::jobEnded(const RenderJob& job, const TileRenderResult&) {
  const RenderSettings& r = job.settings();
  std::ofstream out(path_);
  out << "# lucent tile costs 1\n";
  out << fmt::format("# image {} {} tile {} threads {} samples {} load {:.6f} scene {}\n", r.width,
                     r.height, job.tileSize(), threads_, r.samples, job.loadSeconds(), scene_);
  out << "x0 y0 x1 y1 seconds\n";
  for (const auto& [t, seconds] : costs_)
    out << fmt::format("{} {} {} {} {:.9f}\n", t.x0, t.y0, t.x1, t.y1, seconds);
  out.close();
  costs_.clear();
  if (!out) throw IoFailure(fmt::format("cannot write the tile costs '{}'", path_));
}

void InterruptAfterTiles::tileFinished(const RenderJob&, size_t, const RenderResult&) {
  if (++finished_ == after_) std::raise(SIGTERM);
}

std::vector<std::unique_ptr<RenderObserver>> renderHooks(const RenderOptions& options,
                                                         int threads) {
  std::vector<std::unique_ptr<RenderObserver>> hooks;
  if (!options.tileCosts.empty())
    hooks.push_back(std::make_unique<TileCostRecorder>(options.tileCosts, options.scene, threads));
  if (const char* n = std::getenv("LUCENT_TEST_INTERRUPT_AFTER_TILES"); n && std::atol(n) > 0)
    hooks.push_back(std::make_unique<InterruptAfterTiles>(std::atol(n)));
  return hooks;
}

}  // namespace lucent::cli
