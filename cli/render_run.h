// What `lucent render` keeps from one frame to the next (render_setup.cpp makes it from the
// options), and the render of one frame to its file (render_frame.cpp). cmd_render.cpp
// runs the frames.
#pragma once

#include "commands.h"
#include "load_scene.h"

#include "app/checkpoint.h"
#include "app/progress_bar.h"
#include "app/render_job.h"
#include "render/image_map_cache.h"
#include "render/pixel_rect.h"

#include <chrono>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lucent::cli {

struct RenderRun {
  RenderRun(const RenderOptions& o, const TileExecutor& e) : options(o), executor(e) {}
  const RenderOptions& options;
  const TileExecutor& executor;  // empty: renderTiles
  int threads = 0;               // 0: every core
  ImageMapCache textures;
  std::set<std::string> printed;  // after-render warnings, each once for all the frames
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::optional<PixelRect> region;  // --region; none: the whole image
  std::optional<int> tileSize;      // --tile-size; none: defaultTileSize of each frame
  double checkpointInterval = kDefaultCheckpointInterval;  // seconds; 0: no checkpoint
  std::optional<CheckpointWriter> checkpoint;
  std::optional<CheckpointContents> resumed;  // --resume: the checkpoint as read
  std::string checkpointPath;
  // Attached to every frame's job: the hooks of the benchmarks and tests (render_hooks.h).
  std::vector<std::unique_ptr<RenderObserver>> hooks;
};

// --threads, --region, --tile-size, --checkpoint-interval, --resume and the hooks: throws
// UsageError for a value out of range or a checkpoint made for another render, IoFailure
// for one that cannot be read.
void setUpRun(RenderRun& run, const RenderOptions& options, const CommonOptions& common,
              const std::string& output);

// Throws UsageError when the checkpoint's identity of a frame differs from `current`.
void checkFrameIdentity(const RenderRun& run, const Identity& saved, const Identity& current);

// Renders the loaded scene (frame `frame`) tile by tile and writes it to `output`, keeping
// a checkpoint as it goes (app/frame_checkpoint.h) and taking the tiles a resumed
// checkpoint holds. The scene is freed before the image is written. `cancelled` in the
// result: nothing was written (the checkpoint holds the finished tiles).
TileRenderResult renderToFile(LoadedScene loaded, const std::string& output, RenderRun& run,
                              const std::optional<SequencePosition>& position, int frame,
                              double loadSeconds);

// The threads a render runs on: `threads`, or every core for 0.
int threadsShown(int threads);
double secondsSince(std::chrono::steady_clock::time_point start);

}  // namespace lucent::cli
