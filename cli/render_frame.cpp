// One frame of `lucent render`, from its loaded scene to its image file: a render job
// (app/render_job.h) with the run's checkpoint and hooks attached, resumed from the
// checkpoint when asked, rendered with a progress bar, then written.
#include "render_run.h"

#include "checkpoint_identity.h"
#include "interrupt_catcher.h"

#include "app/frame_checkpoint.h"
#include "app/image_output.h"
#include "memory/system_memory.h"
#include "render/renderer.h"
#include "render/working_gamma.h"
#include "scenegraph/gradient_report.h"

#include <fmt/core.h>

#include <optional>

#include <malloc.h>
#include <unistd.h>

namespace lucent::cli {

namespace {

// The image in memory: the renderer's linear float pixels, the encoded copy handed to the
// writer (at most float RGB), and the copy read back to prove the file complete.
constexpr std::uintmax_t kImageBytesPerPixel = 3 * sizeof(Color);

// An image too large for the memory left is refused before the render, not after hours.
std::optional<std::string> imageMemoryProblem(const PixelRect& area) {
  const std::uintmax_t need =
      std::uintmax_t(area.width()) * std::uintmax_t(area.height()) * kImageBytesPerPixel;
  const std::optional<std::uintmax_t> available = availableMemoryBytes();
  if (!available || need <= *available) return std::nullopt;
  return fmt::format("a {}x{} image needs about {} of memory, more than the {} available",
                     area.width(), area.height(), formatBytes(need), formatBytes(*available));
}

// The rectangle a frame renders: --region, checked against the frame's image size.
PixelRect frameArea(const RenderRun& run, const RenderSettings& r) {
  const PixelRect whole = wholeImage(r.width, r.height);
  if (!run.region) return whole;
  if (!whole.contains(*run.region))
    throw UsageError(
        fmt::format("--region {}: outside the {}x{} image", run.options.region, r.width, r.height));
  return *run.region;
}

// --resume: the tiles the checkpoint holds of this frame, once the frame is shown to be the
// one the checkpoint was made for.
void resumeFrame(const RenderRun& run, RenderJob& job, FrameCheckpoint& checkpoint,
                 const FrameCheckpoint::IdentityOf& identity, const std::string& output) {
  const auto it = run.resumed->frames.find(job.frame());
  if (it == run.resumed->frames.end() || it->second.identity.empty()) return;
  checkFrameIdentity(run, it->second.identity, identity());
  checkpoint.resumed();
  const size_t taken = job.takeFinished(it->second.tiles);
  if (!run.options.quiet)
    fmt::print(stderr, "lucent: resuming '{}': {} of {} tiles from the checkpoint\n", output, taken,
               job.tiles().size());
}

// Renders the job's tiles over a world built for them, gone when this returns, with a
// progress bar on a terminal.
TileRenderResult renderJob(RenderJob& job, const LoadedScene& loaded, RenderRun& run,
                           const std::optional<SequencePosition>& position) {
  World world(*loaded.scene);
  Renderer renderer(world, *loaded.camera, &run.textures);
  RenderProgress progress;
  RenderControl control;
  control.threads = run.threads;
  control.cancel = &InterruptCatcher::flag();
  control.progress = &progress;
  std::optional<ProgressBar> bar;
  if (!run.options.quiet && ::isatty(STDERR_FILENO)) bar.emplace(progress, stderr, position);
  TileRunner runner;
  if (run.executor)
    runner = [&](const Renderer& r, const std::vector<PixelRect>& tiles,
                 const std::vector<char>& skip, const RenderControl& c, bool oneAtATime,
                 const TileFinished& finished) {
      return run.executor(r, loaded, job.frame(), tiles, skip, c, oneAtATime, finished);
    };
  return job.render(renderer, control, runner);
}

// The finished image to `output`, with the scene freed first: linear light, the values of a
// scene with a working gamma (POV-Ray's assumed_gamma) decoded.
void writeOutput(const RenderJob& job, LoadedScene& loaded, const std::string& output) {
  const WorkingGamma gamma = loaded.scene->render.workingGamma;
  // The world is gone and the scene goes too before the image is written: writing an EXR,
  // TIFF, HDR or JPEG loads OpenImageIO (images/image_plugin.h, 130 MB of libraries), and
  // the two need not be in memory at once. (PNG and PPM are written without it.)
  loaded.scene.reset();
  // glibc keeps freed blocks for reuse (in each thread's arena, and below the top of
  // the heap); hand them back to the system, or they would count twice.
  ::malloc_trim(0);
  Image storage;
  writeImageFile(lightOf(job.image(), gamma, storage), output);
}

}  // namespace

TileRenderResult renderToFile(LoadedScene loaded, const std::string& output, RenderRun& run,
                              const std::optional<SequencePosition>& position, int frame,
                              double loadSeconds) {
  const Scene& scene = *loaded.scene;
  const PixelRect area = frameArea(run, scene.render);
  if (auto problem = imageMemoryProblem(area)) throw IoFailure(*problem);
  RenderJob job(scene.render, area, run.tileSize.value_or(defaultTileSize(scene.render)), frame,
                loadSeconds);
  std::optional<Identity> identity;  // made when first needed: it reads every file again
  auto frameId = [&]() -> const Identity& {
    if (!identity) identity = frameIdentity(loaded, frame, job.tileSize());
    return *identity;
  };
  for (const std::unique_ptr<RenderObserver>& hook : run.hooks) job.observe(*hook);
  std::optional<FrameCheckpoint> checkpoint;
  if (run.checkpoint) {
    checkpoint.emplace(*run.checkpoint, frame, frameId, run.checkpointInterval);
    job.observe(*checkpoint);
    if (run.resumed) resumeFrame(run, job, *checkpoint, frameId, output);
  }

  const TileRenderResult result = renderJob(job, loaded, run, position);
  if (result.cancelled) {
    if (checkpoint)
      fmt::print(stderr,
                 "lucent: the checkpoint '{}' keeps the finished tiles; run again with --resume to "
                 "go on\n",
                 run.checkpoint->path());
    return result;
  }
  // Printed even with -q, like every warning.
  for (const std::string& w : gradientWarnings(scene))
    if (run.printed.insert(w).second) fmt::print(stderr, "{}\n", w);
  // A frame of an animation: its identity is kept with the record that it was written, so
  // that a resumed run can tell the frame is this scene's before it skips it.
  if (checkpoint && position) frameId();

  writeOutput(job, loaded, output);
  if (checkpoint && position) checkpoint->imageWritten();
  if (checkpoint && !position) run.checkpoint->remove();
  if (!run.options.quiet) {
    const std::string frameText =
        position ? fmt::format("frame {}/{}, ", position->frame, position->frames) : "";
    fmt::print(stderr, "lucent: wrote '{}' ({}{}x{}, {})\n", output, frameText, area.width(),
               area.height(), formatDuration(result.seconds));
  }
  return result;
}

}  // namespace lucent::cli
