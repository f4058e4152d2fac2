// lucent render SCENE [-o OUT]: load the scene (load_scene.h: parse, overrides, the
// checks `check` makes too), build the world, render over every core, write the image
// atomically; without -o the image is SCENE.png beside the scene.
//
// Exit statuses (the contract's): 1 for wrong usage, which includes option values out of
// range and a --camera name the scene does not define (the scene itself is valid, the
// request is not; the message lists the scene's camera names); 2 for an invalid scene
// (parse errors, a camera that cannot form an image); 3 for input/output and runtime
// failures (unwritable output, unknown output extension, unreadable texture, Ctrl-C).
#include "commands.h"

#include "load_scene.h"

#include "scenegraph/shape_registry.h"
#include "memory/system_memory.h"
#include "render/image_io.h"
#include "render/progress_bar.h"
#include "render/renderer.h"
#include "render/texture.h"

#include <fmt/core.h>
#include <tbb/global_control.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <optional>
#include <thread>

#include <malloc.h>
#include <unistd.h>

namespace lucent::cli {

namespace {

// Set by SIGINT (Ctrl-C) or SIGTERM (kill, a batch system's stop), polled by the renderer
// before every row of every tile.
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int signal) {
  gInterrupted.store(true, std::memory_order_relaxed);
  // A second one ends the process at once, as users expect when a stop hangs.
  std::signal(signal, SIG_DFL);
}

// Catches SIGINT and SIGTERM while it lives (even where the shell started us with SIGINT
// ignored, as it does for background jobs); restores the previous dispositions after.
class InterruptCatcher {
 public:
  InterruptCatcher() {
    gInterrupted.store(false);
    struct sigaction sa {};
    sa.sa_handler = onInterrupt;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < 2; ++i) installed_[i] = sigaction(kSignals[i], &sa, &previous_[i]) == 0;
  }
  ~InterruptCatcher() {
    for (int i = 0; i < 2; ++i)
      if (installed_[i]) sigaction(kSignals[i], &previous_[i], nullptr);
  }
  InterruptCatcher(const InterruptCatcher&) = delete;
  InterruptCatcher& operator=(const InterruptCatcher&) = delete;

 private:
  static constexpr int kSignals[2] = {SIGINT, SIGTERM};
  struct sigaction previous_[2] {};
  bool installed_[2] = {false, false};
};

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
  // Before a long render: an output that can never be written is an error now.
  checkImageOutputPath(output);

  LoadedScene loaded = loadScene(request, common);
  Scene& scene = *loaded.scene;
  if (auto problem = imageMemoryProblem(scene.render)) throw IoFailure(*problem);

  RenderResult result;
  const int threads = options.threads.value_or(0);
  // --threads bounds every parallel step, building the world's BVHs too, not only the
  // tracing: `-t 1` is one thread from start to end.
  std::optional<tbb::global_control> threadLimit;
  if (threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  {
    World world(scene);
    Renderer renderer(world, *loaded.camera);

    RenderProgress progress;
    RenderControl control;
    control.threads = threads;
    control.cancel = &gInterrupted;
    control.progress = &progress;
    std::optional<ProgressBar> bar;
    if (!options.quiet && ::isatty(STDERR_FILENO)) bar.emplace(progress, stderr);
    result = renderer.render(control);
  }

  if (result.cancelled) {
    // The output is left as it was, and nothing else is written (docs/security.md: a
    // render writes only its output image and that image's temporary file).
    fmt::print(stderr, "lucent: interrupted; '{}' left unchanged\n", output);
    return kRuntimeFailure;
  }

  // The world is gone and the scene goes too before the image is written: writing an EXR,
  // TIFF, HDR or JPEG loads OpenImageIO (images/image_plugin.h, 130 MB of libraries), and
  // the two need not be in memory at once. (PNG and PPM are written without it.)
  const int width = scene.render.width, height = scene.render.height;
  loaded.scene.reset();
  // glibc keeps freed blocks for reuse (in each thread's arena, and below the top of
  // the heap); hand them back to the system, or they would count twice.
  ::malloc_trim(0);
  writeImageFile(result.image, output);
  if (!options.quiet)
    fmt::print(stderr, "lucent: wrote '{}' ({}x{}, {})\n", output, width, height,
               formatDuration(result.seconds));
  if (options.stats)
    printStats(result, threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()));
  return kOk;
}

}  // namespace lucent::cli
