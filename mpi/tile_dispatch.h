// Rank 0 of lucent-mpi: the TileExecutor (cli/tile_executor.h) that renders a frame's tiles
// over every rank. As rank 0 parses a frame it sends the workers the scene and each file
// the parse is granted (a LoadObserver), so they parse at the same time rather than after
// it (file_bundle.h). Then it hands out tiles in row order to whichever rank asks (the
// workers, each holding two so the next is there when one is done, and a thread of rank 0
// itself that renders too), and reports each finished tile as renderTiles would: the same
// checkpoint, progress and image as a single process. The main thread only coordinates,
// polling with short naps.
#pragma once

#include "load_scene.h"
#include "tile_executor.h"

#include <atomic>
#include <filesystem>
#include <optional>
#include <set>
#include <thread>

namespace lucent::mpi {

class FrameTiles;

class TileDispatch : public cli::LoadObserver {
 public:
  // `scene`: the scene named on the command line (canonical).
  explicit TileDispatch(std::filesystem::path scene) : scene_(std::move(scene)) {}

  // A frame's parse begins, and grants the name of a file (from the main thread only: MPI
  // is called from it alone; a grant from another thread waits for kLoaded).
  void loading(int frame, const std::filesystem::path& scene) override;
  void granted(const FileGrant& grant) override;

  TileRenderResult operator()(const Renderer& renderer, const cli::LoadedScene& loaded, int frame,
                              const std::vector<PixelRect>& tiles, const std::vector<char>& skip,
                              const RenderControl& control, bool oneAtATime,
                              const TileFinished& finished);

  // No worker is rendering a tile (none was lost mid-way): they can be told to stop,
  // rather than the job aborted (a worker still loading a frame can).
  bool workersIdle() const { return busy_.empty(); }
  // Sends every worker the end of the run.
  void stopWorkers();

 private:
  void sendAll(int tag, const std::vector<char>& bytes);
  // Completes the workers' load of `frame` (kLoaded, every file its parse read); they are
  // then busy with it.
  void sendLoaded(const cli::LoadedScene& loaded, int frame);
  // Hands the frame's tiles to the workers as they ask, until each has none left.
  void serveWorkers(FrameTiles& tiles, const std::vector<PixelRect>& rects, int frame,
                    const std::atomic<bool>* cancel);
  std::filesystem::path scene_;      // canonical, of the frame being loaded
  std::optional<int> loadingFrame_;  // sent kFrame, not yet kLoaded or kNoMore
  std::thread::id mainThread_ = std::this_thread::get_id();
  std::set<std::filesystem::path> sent_;  // files the workers have
  std::set<int> busy_;                    // workers with tiles of a frame
};

}  // namespace lucent::mpi
