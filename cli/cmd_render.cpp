// lucent render SCENE [-o OUT]: load the scene (load_scene.h: parse, overrides, the
// checks `check` makes too), build the world, render over every core, write the image
// atomically; without -o the image is SCENE.png beside the scene.
//
// An animated scene is rendered frame by frame, each parsed again for its frame (the
// scene graph differs), to the numbered files frame_names.h makes of OUT; --frames picks
// some. Files the frames read (meshes, image textures, the image plugin) are loaded once
// for the run. -D frame=F or -D clock=C renders that one moment to OUT itself.
//
// Exit statuses (the contract's): 1 for wrong usage, which includes option values out of
// range, a --frames range beyond the scene's frames and a --camera name the scene does not
// define (the scene itself is valid, the request is not; the message lists the scene's
// camera names); 2 for an invalid scene (parse errors, a camera that cannot form an image;
// in an animation the message names the frame); 3 for input/output and runtime failures
// (unwritable output, unknown output extension, unreadable texture, Ctrl-C).
#include "commands.h"

#include "checkpoint_identity.h"
#include "frame_loading.h"
#include "frame_names.h"
#include "frame_range.h"
#include "interrupt_catcher.h"
#include "load_scene.h"
#include "render_run.h"
#include "render_stats.h"

#include "app/image_output.h"
#include "meshes/mesh_file_cache.h"
#include "render/tile_render.h"
#include "scenegraph/shape_registry.h"

#include <fmt/core.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <set>

namespace lucent::cli {

namespace {

void printStats(const RayStats& s, double seconds, int threads) {
  fmt::print("{}", renderStatsText(s, seconds, threads));
}

// Every frame of `range` of `animation`, each parsed again for its frame, to the numbered
// files.
class FrameSequence {
 public:
  FrameSequence(const Animation& animation, const FrameRange& range, const SceneRequest& request,
                const CommonOptions& common, const std::string& output, RenderRun& run)
      : animation_(animation),
        range_(range),
        request_(request),
        common_(common),
        output_(output),
        run_(run) {}

  // `first`, if it holds a scene, is the range's first frame, already loaded (in
  // `firstLoadSeconds`).
  int render(LoadedScene first, double firstLoadSeconds);

 private:
  // Frame f to its file, or skipped; false when interrupted (said why).
  bool frame(int f, LoadedScene& first, double firstLoadSeconds);
  // Frame f as loaded, or `first` when it is the first frame and loaded.
  LoadedScene load(int f, LoadedScene& first, double firstLoadSeconds, double& loadSeconds,
                   std::chrono::steady_clock::time_point& frameStart);
  // A frame the checkpoint says was written, and whose file is there, is skipped once it
  // is shown to be this scene's frame.
  bool writtenBefore(int f, const LoadedScene& loaded, const std::string& name) const;
  void printTotals() const;

  const Animation& animation_;
  const FrameRange& range_;
  SceneRequest request_;  // its frame set for each
  const CommonOptions& common_;
  const std::string& output_;
  RenderRun& run_;
  int written_ = 0;
  RayStats totalStats_;
  double totalRender_ = 0.0;
};

int FrameSequence::render(LoadedScene first, double firstLoadSeconds) {
  for (int f = range_.first; f <= range_.last; ++f)
    if (!frame(f, first, firstLoadSeconds)) return kRuntimeFailure;
  // Every frame is written: the checkpoint has served.
  if (run_.checkpoint) run_.checkpoint->remove();
  if (run_.options.stats) printTotals();
  return kOk;
}

LoadedScene FrameSequence::load(int f, LoadedScene& first, double firstLoadSeconds,
                                double& loadSeconds,
                                std::chrono::steady_clock::time_point& frameStart) {
  if (f == range_.first && first.scene) {
    loadSeconds = firstLoadSeconds;
    frameStart -= std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(loadSeconds));
    return std::move(first);
  }
  request_.frame = f;
  LoadedScene loaded = loadFrame(request_, common_, animation_);
  loadSeconds = secondsSince(frameStart);
  return loaded;
}

bool FrameSequence::writtenBefore(int f, const LoadedScene& loaded, const std::string& name) const {
  if (!run_.resumed) return false;
  const auto it = run_.resumed->frames.find(f);
  if (it == run_.resumed->frames.end() || !it->second.written || !std::filesystem::exists(name))
    return false;
  const int tileSize = run_.tileSize.value_or(defaultTileSize(loaded.scene->render));
  checkFrameIdentity(run_, it->second.identity, frameIdentity(loaded, f, tileSize));
  if (!run_.options.quiet)
    fmt::print(stderr, "lucent: frame {}: '{}' was written before; skipped\n", f, name);
  return true;
}

bool FrameSequence::frame(int f, LoadedScene& first, double firstLoadSeconds) {
  const std::string name = frameOutputPath(output_, f, animation_.frames);
  if (InterruptCatcher::interrupted()) {
    fmt::print(stderr, "lucent: interrupted; {} of {} frames written, '{}' not started\n", written_,
               range_.count(), name);
    return false;
  }
  auto frameStart = std::chrono::steady_clock::now();
  double loadSeconds = 0.0;
  TileRenderResult result;
  try {
    LoadedScene loaded = load(f, first, firstLoadSeconds, loadSeconds, frameStart);
    if (writtenBefore(f, loaded, name)) {
      ++written_;
      return true;
    }
    SequencePosition position{written_ + 1, range_.count(), f, animation_.frames,
                              secondsSince(run_.start)};
    result = renderToFile(std::move(loaded), name, run_, position, f, loadSeconds);
  } catch (...) {
    // Reported here, so that the frames written are said after the failure.
    const int status = reportFailure(std::current_exception());
    fmt::print(stderr, "lucent: stopped at frame {}; {} of {} frames written\n", f, written_,
               range_.count());
    throw ReportedFailure{status};
  }
  if (result.cancelled) {
    fmt::print(stderr,
               "lucent: interrupted in frame {}; '{}' left unchanged, {} of {} frames written\n", f,
               name, written_, range_.count());
    return false;
  }
  ++written_;
  totalStats_ += result.stats;
  totalRender_ += result.seconds;
  if (run_.options.stats) {
    const double seconds = secondsSince(frameStart);
    fmt::print(
        "frame {:>5}: {:10.4f}  s (load {:.4f} s, render {:.4f} s, write and the rest {:.4f} "
        "s)\n",
        f, seconds, loadSeconds, result.seconds,
        std::max(0.0, seconds - loadSeconds - result.seconds));
  }
  return true;
}

void FrameSequence::printTotals() const {
  printStats(totalStats_, totalRender_, threadsShown(run_.threads));
  const double total = secondsSince(run_.start);
  fmt::print("frames:    {:>14}  in {:.3f} s ({}; {:.3f} s a frame, render {:.3f} s of it)\n",
             written_, total, formatDuration(total), total / written_, totalRender_ / written_);
  // Each file is read once for the run, not once a frame.
  fmt::print("files:     {:>14}  mesh files read, {} image textures loaded, for {} frames\n",
             request_.meshCache->reads(), run_.textures.loads(), written_);
}

}  // namespace

std::string defaultRenderOutput(const std::string& scene) {
  return std::filesystem::path(scene).replace_extension(".png").string();
}

int runRender(const RenderOptions& options, const CommonOptions& common,
              const TileExecutor& executor, LoadObserver* observer) {
  // From the start, so a Ctrl-C during parsing still stops the render at its first row.
  InterruptCatcher interrupts;
  const std::string output =
      options.output.empty() ? defaultRenderOutput(options.scene) : options.output;
  SceneRequest request = renderSceneRequest(options);
  checkOverrides(request);
  std::optional<FrameRange> range;
  if (!options.frames.empty()) {
    range = parseFrameRange(options.frames);
    if (picksOneMoment(common))
      throw UsageError(fmt::format("--frames {} and -D {} both choose what to render; give one",
                                   options.frames,
                                   common.defines.count("frame") ? "frame" : "clock"));
  }
  // Before a long render: an output that can never be written is an error now.
  checkImageOutputPath(output);

  RenderRun run{options, executor};
  setUpRun(run, options, common, output);
  // --threads bounds every parallel step, building the world's BVHs too, not only the
  // tracing: `-t 1` is one thread from start to end.
  std::optional<tbb::global_control> threadLimit;
  if (run.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<size_t>(run.threads));

  request.meshCache = std::make_shared<MeshFileCache>();
  std::set<std::string> printed;  // the first frame's warnings, not repeated per frame
  request.printed = &printed;
  request.observer = observer;
  // Frame 1 (or the moment -D picks) tells how many frames there are.
  LoadedScene loaded = loadScene(request, common);
  const double firstLoadSeconds = secondsSince(run.start);
  const Animation animation = loaded.scene->animation;
  const bool sequence = animation.present && !picksOneMoment(common);
  if (range)
    checkFrameRange(*range, "--frames " + options.frames, sequence ? animation.frames : 1,
                    sequence);
  if (!options.tileCosts.empty() && sequence && (!range || range->count() != 1))
    throw UsageError("--tile-costs records the tiles of one frame: give --frames F or -D frame=F");
  if (sequence) {
    const FrameRange frames = range.value_or(FrameRange{1, animation.frames});
    // The numbered names must be writable too (a '#' run may change the extension's place).
    checkImageOutputPath(frameOutputPath(output, frames.first, animation.frames));
    if (frames.first != 1) loaded = {};
    return FrameSequence(animation, frames, request, common, output, run)
        .render(std::move(loaded), firstLoadSeconds);
  }

  const TileRenderResult result =
      renderToFile(std::move(loaded), output, run, std::nullopt, 1, firstLoadSeconds);
  if (result.cancelled) {
    // The output is left as it was (docs/security.md: a render writes only its output
    // image, that image's temporary file and its checkpoint).
    fmt::print(stderr, "lucent: interrupted; '{}' left unchanged\n", output);
    return kRuntimeFailure;
  }
  if (options.stats) printStats(result.stats, result.seconds, threadsShown(run.threads));
  return kOk;
}

}  // namespace lucent::cli
