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

#include "frame_loading.h"
#include "frame_names.h"
#include "frame_range.h"
#include "interrupt_catcher.h"
#include "load_scene.h"

#include "meshes/mesh_file_cache.h"
#include "scenegraph/gradient_report.h"
#include "scenegraph/shape_registry.h"
#include "memory/system_memory.h"
#include "render/image_io.h"
#include "render/image_map_cache.h"
#include "render/progress_bar.h"
#include "render/renderer.h"

#include <fmt/core.h>
#include <tbb/global_control.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <thread>

#include <malloc.h>
#include <unistd.h>

namespace lucent::cli {

namespace {

// The image in memory: the renderer's linear float pixels, the encoded copy handed to the
// writer (at most float RGB), and the copy read back to prove the file complete.
constexpr std::uintmax_t kImageBytesPerPixel = 3 * sizeof(Color);

// An image too large for the memory left is refused before the render, not after hours.
std::optional<std::string> imageMemoryProblem(const RenderSettings& r) {
  const std::uintmax_t need = std::uintmax_t(r.width) * std::uintmax_t(r.height) * kImageBytesPerPixel;
  const std::optional<std::uintmax_t> available = availableMemoryBytes();
  if (!available || need <= *available) return std::nullopt;
  return fmt::format("a {}x{} image needs about {} of memory, more than the {} available", r.width,
                     r.height, formatBytes(need), formatBytes(*available));
}

void printStats(const RenderResult& r, int threads) {
  const RayStats& s = r.stats;
  fmt::print("rays:      {:>14}  (primary {}, shadow {}, reflected {}, refracted {})\n", s.rays(),
             s.primary, s.shadow, s.reflected, s.refracted);
  fmt::print("searches:  {:>14}  (closest-hit and any-hit queries of the world)\n", s.queries);
  fmt::print("cache hits:{:>14}  (shadow rays blocked by the object that blocked the light's "
             "previous one, tested first)\n",
             s.shadowCacheHits);
  // Intersection tests by kind, the kinds the scene has only.
  uint64_t tests = 0;
  std::string byKind;
  for (size_t k = 0; k < kTestSlots; ++k) {
    const uint64_t n = s.tests[k];
    if (n == 0) continue;
    tests += n;
    byKind += fmt::format("{}{} {}", byKind.empty() ? "" : ", ", testSlotName(k), n);
  }
  fmt::print("tests:     {:>14}  ({})\n", tests, byKind.empty() ? "none" : byKind);
  fmt::print("time:      {:>14.3f}  s ({})\n", r.seconds, formatDuration(r.seconds));
  fmt::print("speed:     {:>14.3f}  Mrays/s on {} threads\n",
             r.seconds > 0.0 ? s.rays() / r.seconds * 1e-6 : 0.0, threads);
}


double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What the run keeps from one frame to the next.
struct RenderRun {
  const RenderOptions& options;
  int threads = 0;  // 0: every core
  ImageMapCache textures;
  std::set<std::string> printed;  // after-render warnings, each once for all the frames
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

// Renders the loaded scene and writes it to `output`. The scene is freed before the
// image is written. `cancelled` in the result: nothing was written.
RenderResult renderToFile(LoadedScene loaded, const std::string& output, RenderRun& run,
                          const std::optional<SequencePosition>& position) {
  Scene& scene = *loaded.scene;
  if (auto problem = imageMemoryProblem(scene.render)) throw IoFailure(*problem);
  RenderResult result;
  {
    World world(scene);
    Renderer renderer(world, *loaded.camera, &run.textures);

    RenderProgress progress;
    RenderControl control;
    control.threads = run.threads;
    control.cancel = &InterruptCatcher::flag();
    control.progress = &progress;
    std::optional<ProgressBar> bar;
    if (!run.options.quiet && ::isatty(STDERR_FILENO)) bar.emplace(progress, stderr, position);
    result = renderer.render(control);
  }
  if (result.cancelled) return result;
  // Printed even with -q, like every warning.
  for (const std::string& w : gradientWarnings(scene))
    if (run.printed.insert(w).second) fmt::print(stderr, "{}\n", w);

  // The world is gone and the scene goes too before the image is written: writing an EXR,
  // TIFF, HDR or JPEG loads OpenImageIO (images/image_plugin.h, 130 MB of libraries), and
  // the two need not be in memory at once. (PNG and PPM are written without it.)
  const int width = scene.render.width, height = scene.render.height;
  loaded.scene.reset();
  // glibc keeps freed blocks for reuse (in each thread's arena, and below the top of
  // the heap); hand them back to the system, or they would count twice.
  ::malloc_trim(0);
  writeImageFile(result.image, output);
  if (!run.options.quiet) {
    const std::string frame =
        position ? fmt::format("frame {}/{}, ", position->frame, position->frames) : "";
    fmt::print(stderr, "lucent: wrote '{}' ({}{}x{}, {})\n", output, frame, width, height,
               formatDuration(result.seconds));
  }
  return result;
}

int threadsShown(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
}

// Every frame of `range` of `animation`, each parsed again for its frame, to the numbered
// files. `first`, if it holds a scene, is the range's first frame, already loaded (in
// `firstLoadSeconds`).
int renderFrames(LoadedScene first, double firstLoadSeconds, const Animation& animation,
                 const FrameRange& range,
                 const SceneRequest& request, const CommonOptions& common,
                 const std::string& output, RenderRun& run) {
  SceneRequest frameRequest = request;
  RayStats totalStats;
  double totalRender = 0.0;
  int written = 0;
  for (int f = range.first; f <= range.last; ++f) {
    const std::string name = frameOutputPath(output, f, animation.frames);
    if (InterruptCatcher::interrupted()) {
      fmt::print(stderr, "lucent: interrupted; {} of {} frames written, '{}' not started\n", written,
                 range.count(), name);
      return kRuntimeFailure;
    }
    auto frameStart = std::chrono::steady_clock::now();
    double loadSeconds = 0.0;
    RenderResult result;
    try {
      LoadedScene loaded;
      if (f == range.first && first.scene) {
        loaded = std::move(first);
        loadSeconds = firstLoadSeconds;
        frameStart -= std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(loadSeconds));
      } else {
        frameRequest.frame = f;
        loaded = loadFrame(frameRequest, common, animation);
        loadSeconds = secondsSince(frameStart);
      }
      SequencePosition position{written + 1, range.count(), f, animation.frames, secondsSince(run.start)};
      result = renderToFile(std::move(loaded), name, run, position);
    } catch (...) {
      // Reported here, so that the frames written are said after the failure.
      const int status = reportFailure(std::current_exception());
      fmt::print(stderr, "lucent: stopped at frame {}; {} of {} frames written\n", f, written, range.count());
      throw ReportedFailure{status};
    }
    if (result.cancelled) {
      fmt::print(stderr, "lucent: interrupted in frame {}; '{}' left unchanged, {} of {} frames written\n",
                 f, name, written, range.count());
      return kRuntimeFailure;
    }
    ++written;
    totalStats += result.stats;
    totalRender += result.seconds;
    if (run.options.stats) {
      const double seconds = secondsSince(frameStart);
      fmt::print("frame {:>5}: {:10.4f}  s (load {:.4f} s, render {:.4f} s, write and the rest {:.4f} s)\n",
                 f, seconds, loadSeconds, result.seconds,
                 std::max(0.0, seconds - loadSeconds - result.seconds));
    }
  }
  if (run.options.stats) {
    RenderResult sum;
    sum.stats = totalStats;
    sum.seconds = totalRender;
    printStats(sum, threadsShown(run.threads));
    const double total = secondsSince(run.start);
    fmt::print("frames:    {:>14}  in {:.3f} s ({}; {:.3f} s a frame, render {:.3f} s of it)\n", written,
               total, formatDuration(total), total / written, totalRender / written);
    // Each file is read once for the run, not once a frame.
    fmt::print("files:     {:>14}  mesh files read, {} image textures loaded, for {} frames\n",
               request.meshCache->reads(), run.textures.loads(), written);
  }
  return kOk;
}

}  // namespace

std::string defaultRenderOutput(const std::string& scene) {
  return std::filesystem::path(scene).replace_extension(".png").string();
}

int runRender(const RenderOptions& options, const CommonOptions& common) {
  // From the start, so a Ctrl-C during parsing still stops the render at its first row.
  InterruptCatcher interrupts;
  const std::string output = options.output.empty() ? defaultRenderOutput(options.scene) : options.output;
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.samples = options.samples;
  request.threads = options.threads;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  checkOverrides(request);
  std::optional<FrameRange> range;
  if (!options.frames.empty()) {
    range = parseFrameRange(options.frames);
    if (picksOneMoment(common))
      throw UsageError(fmt::format("--frames {} and -D {} both choose what to render; give one",
                                   options.frames, common.defines.count("frame") ? "frame" : "clock"));
  }
  // Before a long render: an output that can never be written is an error now.
  checkImageOutputPath(output);

  RenderRun run{options};
  run.threads = options.threads.value_or(0);
  // --threads bounds every parallel step, building the world's BVHs too, not only the
  // tracing: `-t 1` is one thread from start to end.
  std::optional<tbb::global_control> threadLimit;
  if (run.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(run.threads));

  request.meshCache = std::make_shared<MeshFileCache>();
  std::set<std::string> printed;  // the first frame's warnings, not repeated per frame
  request.printed = &printed;
  // Frame 1 (or the moment -D picks) tells how many frames there are.
  LoadedScene loaded = loadScene(request, common);
  const double firstLoadSeconds = secondsSince(run.start);
  const Animation animation = loaded.scene->animation;
  const bool sequence = animation.present && !picksOneMoment(common);
  if (range) checkFrameRange(*range, "--frames " + options.frames, sequence ? animation.frames : 1, sequence);
  if (sequence) {
    const FrameRange frames = range.value_or(FrameRange{1, animation.frames});
    // The numbered names must be writable too (a '#' run may change the extension's place).
    checkImageOutputPath(frameOutputPath(output, frames.first, animation.frames));
    if (frames.first != 1) loaded = {};
    return renderFrames(std::move(loaded), firstLoadSeconds, animation, frames, request, common,
                        output, run);
  }

  RenderResult result = renderToFile(std::move(loaded), output, run, std::nullopt);
  if (result.cancelled) {
    // The output is left as it was, and nothing else is written (docs/security.md: a
    // render writes only its output image and that image's temporary file).
    fmt::print(stderr, "lucent: interrupted; '{}' left unchanged\n", output);
    return kRuntimeFailure;
  }
  if (options.stats) printStats(result, threadsShown(run.threads));
  return kOk;
}

}  // namespace lucent::cli
