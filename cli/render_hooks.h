// The hooks of the benchmarks and tests into `lucent render`: observers attached to every
// frame's render job (app/render_job.h) when an option or the environment asks for them,
// so that the job itself has no branch for either.
#pragma once

#include "commands.h"

#include "app/render_job.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lucent::cli {

// --tile-costs FILE: each tile's render time, one line per tile, for bench/tile_schedule
// (docs/distributed.md; the format is bench/tile_cost_trace.h's). The tiles are rendered one
// after another (each over every thread), so that a tile's time is its own cost; the file
// is written when the job ends.
class TileCostRecorder : public RenderObserver {
 public:
  // `scene`: as named on the command line; `threads`: the threads each tile ran on.
  TileCostRecorder(std::string path, std::string scene, int threads)
      : path_(std::move(path)), scene_(std::move(scene)), threads_(threads) {}

  bool wantsTilesOneAtATime() const override { return true; }
  void tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) override;
  // Throws IoFailure when the file cannot be written.
  void jobEnded(const RenderJob& job, const TileRenderResult& result) override;

 private:
  const std::string path_, scene_;
  const int threads_;
  std::vector<std::pair<PixelRect, double>> costs_;
};

// A test's stand-in for Ctrl-C: SIGTERM once `tiles` tiles of the run are finished
// (LUCENT_TEST_INTERRUPT_AFTER_TILES=N), so that a test interrupts a render at a known
// point; the InterruptCatcher then stops it as it stops a Ctrl-C.
class InterruptAfterTiles : public RenderObserver {
 public:
  explicit InterruptAfterTiles(long tiles) : after_(tiles) {}
  void tileFinished(const RenderJob& job, size_t index, const RenderResult& tile) override;

 private:
  const long after_;
  long finished_ = 0;  // over every frame of the run
};

// The hooks `options` and the environment ask for; `threads`: the threads a tile renders on.
std::vector<std::unique_ptr<RenderObserver>> renderHooks(const RenderOptions& options, int threads);

}  // namespace lucent::cli
