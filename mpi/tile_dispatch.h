// Rank 0 of lucent-mpi: the TileExecutor (cli/tile_executor.h) that renders a frame's tiles
// over every rank. It sends the frame's files to the workers (file_bundle.h), then hands
// out tiles in row order, one at a time, to whichever rank asks (the workers, and a thread
// of rank 0 itself that renders too), and reports each finished tile as renderTiles
// would: the same checkpoint, progress and image as a single process. The main thread
// only coordinates, polling with short naps.
#pragma once

#include "tile_executor.h"

#include <filesystem>
#include <set>

namespace lucent::mpi {

class TileDispatch {
 public:
  explicit TileDispatch(std::filesystem::path scene) : scene_(std::move(scene)) {}

  TileRenderResult operator()(const Renderer& renderer, const cli::LoadedScene& loaded, int frame,
                              const std::vector<PixelRect>& tiles, const std::vector<char>& skip,
                              const RenderControl& control, bool oneAtATime, const TileFinished& finished);

  // No worker is rendering a tile (none was lost mid-way): they can be told to stop,
  // rather than the job aborted.
  bool workersIdle() const { return busy_.empty(); }
  // Sends every worker the end of the run.
  void stopWorkers();

 private:
  std::filesystem::path scene_;
  std::set<std::filesystem::path> sent_;  // files the workers have
  std::set<int> busy_;                    // workers with a tile or a frame to load
};

}  // namespace lucent::mpi
