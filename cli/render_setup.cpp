// The options of `lucent render` that shape its run rather than its scene: the threads,
// the region, the tiles, the checkpoint (a new one, or the one --resume continues) and the
// hooks of the benchmarks and tests.
#include "render_run.h"

#include "checkpoint_identity.h"
#include "render_hooks.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <filesystem>
#include <sstream>
#include <thread>

namespace lucent::cli {

namespace {

// --region X0,Y0,X1,Y1: four whole numbers, X0 < X1 and Y0 < Y1, none negative.
PixelRect parseRegion(const std::string& text) {
  PixelRect r;
  char c1 = 0, c2 = 0, c3 = 0;
  std::istringstream in(text);
  if (!(in >> r.x0 >> c1 >> r.y0 >> c2 >> r.x1 >> c3 >> r.y1) || c1 != ',' || c2 != ',' ||
      c3 != ',' || !(in >> std::ws).eof())
    throw UsageError(
        fmt::format("--region {}: expected X0,Y0,X1,Y1 (pixel bounds, e.g. 0,0,320,240)", text));
  if (r.x0 < 0 || r.y0 < 0 || r.x1 <= r.x0 || r.y1 <= r.y0)
    throw UsageError(
        fmt::format("--region {}: needs 0 <= X0 < X1 and 0 <= Y0 < Y1 (the right and bottom "
                    "bounds are not part of the region)",
                    text));
  return r;
}

// --region, --tile-size and --checkpoint-interval.
void setUpTiles(RenderRun& run, const RenderOptions& options) {
  if (!options.region.empty()) run.region = parseRegion(options.region);
  if (options.tileSize) {
    if (*options.tileSize < 1 || *options.tileSize > kMaxTileSize)
      throw UsageError(
          fmt::format("--tile-size {}: must be 1 to {}", *options.tileSize, kMaxTileSize));
    run.tileSize = *options.tileSize;
  }
  if (options.checkpointInterval) {
    if (!(*options.checkpointInterval >= 0.0) || *options.checkpointInterval > 1e9)
      throw UsageError(
          fmt::format("--checkpoint-interval {}: must be 0 (no checkpoint) or a number of seconds",
                      *options.checkpointInterval));
    run.checkpointInterval = *options.checkpointInterval;
  }
}

// --resume with a checkpoint there: it is read, checked against this run and continued.
void resumeCheckpoint(RenderRun& run, const RenderOptions& options, const CommonOptions& common) {
  try {
    run.resumed = readCheckpoint(run.checkpointPath);
  } catch (const CheckpointError& e) {
    throw IoFailure(e.what());
  }
  // The frames' identities are checked as each is loaded.
  const std::vector<std::string> differ =
      identityDifferences(run.resumed->run, runIdentity(options, common, run.region));
  if (!differ.empty())
    throw UsageError(fmt::format("--resume: the checkpoint '{}' was made for another render; {}",
                                 run.checkpointPath, fmt::join(differ, "; ")));
  run.checkpoint.emplace(CheckpointWriter::continuing(run.checkpointPath, *run.resumed));
}

// The checkpoint beside the output: continued with --resume, else a new one.
void setUpCheckpoint(RenderRun& run, const RenderOptions& options, const CommonOptions& common,
                     const std::string& output) {
  run.checkpointPath = checkpointPathFor(output);
  if (options.resume && run.checkpointInterval == 0.0)
    throw UsageError("--resume needs a checkpoint, and --checkpoint-interval 0 keeps none");
  if (run.checkpointInterval == 0.0) return;
  const bool exists = std::filesystem::exists(run.checkpointPath);
  if (options.resume && exists) {
    resumeCheckpoint(run, options, common);
    return;
  } else if (options.resume) {
    if (!options.quiet)
      fmt::print(stderr, "lucent: no checkpoint '{}' to resume; rendering from the start\n",
                 run.checkpointPath);
  } else if (exists && !options.quiet) {
    fmt::print(stderr,
               "lucent: '{}' holds the checkpoint of an earlier render; it is replaced when this "
               "render saves its own (--resume continues it instead)\n",
               run.checkpointPath);
  }
  run.checkpoint.emplace(run.checkpointPath, runIdentity(options, common, run.region));
}

}  // namespace

void setUpRun(RenderRun& run, const RenderOptions& options, const CommonOptions& common,
              const std::string& output) {
  run.threads = options.threads.value_or(0);
  setUpTiles(run, options);
  run.hooks = renderHooks(options, threadsShown(run.threads));
  setUpCheckpoint(run, options, common, output);
}

int threadsShown(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void checkFrameIdentity(const RenderRun& run, const Identity& saved, const Identity& current) {
  const std::vector<std::string> differ = identityDifferences(saved, current);
  if (!differ.empty())
    throw UsageError(
        fmt::format("--resume: the checkpoint '{}' was made for another scene or other files; {}",
                    run.checkpointPath, fmt::join(differ, "; ")));
}

}  // namespace lucent::cli
