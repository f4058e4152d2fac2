// lucent render SCENE -o OUT: parse, apply the command-line overrides, build the world,
// render over every core, write the image atomically.
//
// Exit statuses (the contract's): 1 for wrong usage, which includes option values out of
// range and a --camera name the scene does not define (the scene itself is valid, the
// request is not; the message lists the scene's camera names); 2 for an invalid scene
// (parse errors, a camera that cannot form an image); 3 for input/output and runtime
// failures (unwritable output, unknown output extension, unreadable texture, Ctrl-C).
#include "commands.h"

#include "lang/parser.h"
#include "render/camera_frame.h"
#include "render/image_io.h"
#include "render/progress_bar.h"
#include "render/renderer.h"
#include "render/texture.h"

#include <fmt/core.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <optional>
#include <thread>

#include <unistd.h>

namespace lucent::cli {

namespace {

// Set by SIGINT, polled by the renderer before every row of every tile.
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int) {
  gInterrupted.store(true, std::memory_order_relaxed);
  // A second Ctrl-C ends the process at once, as users expect when a stop hangs.
  std::signal(SIGINT, SIG_DFL);
}

// Catches SIGINT while it lives (even where the shell started us with SIGINT ignored, as
// it does for background jobs); restores the previous disposition after.
class InterruptCatcher {
 public:
  InterruptCatcher() {
    gInterrupted.store(false);
    struct sigaction sa {};
    sa.sa_handler = onInterrupt;
    sigemptyset(&sa.sa_mask);
    installed_ = sigaction(SIGINT, &sa, &previous_) == 0;
  }
  ~InterruptCatcher() {
    if (installed_) sigaction(SIGINT, &previous_, nullptr);
  }
  InterruptCatcher(const InterruptCatcher&) = delete;
  InterruptCatcher& operator=(const InterruptCatcher&) = delete;

 private:
  struct sigaction previous_ {};
  bool installed_ = false;
};

int usageError(const std::string& message) {
  fmt::print(stderr, "lucent: error: {}\n", message);
  return kUsage;
}

// Option values the contract calls out of range; nullopt when all are fine.
std::optional<std::string> checkOverrides(const RenderOptions& o) {
  auto atLeastOne = [](const std::optional<int>& v, const char* name) -> std::optional<std::string> {
    if (v && *v < 1) return fmt::format("{} must be at least 1 (got {})", name, *v);
    return std::nullopt;
  };
  for (auto e : {atLeastOne(o.width, "--width"), atLeastOne(o.height, "--height"),
                 atLeastOne(o.samples, "--samples"), atLeastOne(o.threads, "--threads"),
                 atLeastOne(o.maxDepth, "--max-depth")})
    if (e) return e;
  return std::nullopt;
}

void applyOverrides(const RenderOptions& o, RenderSettings& r) {
  if (o.width) r.width = *o.width;
  if (o.height) r.height = *o.height;
  if (o.samples) r.samples = *o.samples;
  if (o.maxDepth) r.maxDepth = *o.maxDepth;
}

std::string cameraNames(const Scene& scene) {
  std::string names;
  for (const Camera& c : scene.cameras) {
    if (c.name.empty()) continue;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  return names.empty() ? "the scene's cameras have no names" : "cameras: " + names;
}

// OUT.png -> OUT.partial.png, beside it.
std::string partialPath(const std::string& output) {
  std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

void printStats(const RenderResult& r, int threads) {
  const RayStats& s = r.stats;
  fmt::print("rays:      {:>14}  (primary {}, shadow {}, reflected {}, refracted {})\n", s.rays(),
             s.primary, s.shadow, s.reflected, s.refracted);
  fmt::print("searches:  {:>14}  (closest-hit and any-hit queries of the world)\n", s.queries);
  fmt::print("time:      {:>14.3f}  s ({})\n", r.seconds, formatDuration(r.seconds));
  fmt::print("speed:     {:>14.3f}  Mrays/s on {} threads\n",
             r.seconds > 0.0 ? s.rays() / r.seconds * 1e-6 : 0.0, threads);
}

}  // namespace

int runRender(const RenderOptions& options, const CommonOptions& common) {
  // From the start, so a Ctrl-C during parsing still stops the render at its first row.
  InterruptCatcher interrupts;
  if (auto problem = checkOverrides(options)) return usageError(*problem);
  try {
    // Before a long render: an output that can never be written is an error now.
    checkImageOutputPath(options.output);
  } catch (const ImageIOError& e) {
    fmt::print(stderr, "lucent: error: {}\n", e.what());
    return kRuntimeFailure;
  }

  ParseOptions parseOptions;
  parseOptions.defines = common.defines;
  parseOptions.allowPaths = common.allowPaths;
  ParseResult parsed;
  try {
    parsed = parseSceneFile(options.scene, parseOptions);
  } catch (const std::exception& e) {
    fmt::print(stderr, "lucent: error: {}: {}\n", options.scene, e.what());
    return kRuntimeFailure;
  }
  for (const Diagnostic& d : parsed.diagnostics.all())
    if (d.severity == Severity::Error || !options.quiet) fmt::print(stderr, "{}\n", d.str());
  if (parsed.ioFailure) return kRuntimeFailure;  // the scene file itself is unreadable
  if (parsed.diagnostics.hasErrors() || !parsed.scene) return kInvalidScene;
  Scene& scene = *parsed.scene;

  applyOverrides(options, scene.render);
  const Camera* camera = scene.findCamera(options.camera);
  if (!camera) {
    if (scene.cameras.empty()) {
      fmt::print(stderr, "{}: error: the scene has no <camera>\n", options.scene);
      return kInvalidScene;
    }
    return usageError(fmt::format("--camera {}: no camera of that name in '{}' ({})",
                                  options.camera, options.scene, cameraNames(scene)));
  }

  try {
    World world(scene);
    Renderer renderer(world, *camera);

    RenderProgress progress;
    RenderControl control;
    control.threads = options.threads.value_or(0);
    control.cancel = &gInterrupted;
    control.progress = &progress;
    RenderResult result;
    {
      std::optional<ProgressBar> bar;
      if (!options.quiet && ::isatty(STDERR_FILENO)) bar.emplace(progress, stderr);
      result = renderer.render(control);
    }

    if (result.cancelled) {
      // The output is left as it was; what was rendered goes beside it, clearly named.
      if (progress.workDone.load() == 0) {
        fmt::print(stderr, "lucent: interrupted; '{}' left unchanged\n", options.output);
        return kRuntimeFailure;
      }
      std::string partial = partialPath(options.output);
      try {
        writeImageFile(result.image, partial);
        fmt::print(stderr, "lucent: interrupted; '{}' left unchanged, partial image in '{}'\n",
                   options.output, partial);
      } catch (const ImageIOError& e) {
        fmt::print(stderr, "lucent: interrupted; '{}' left unchanged ({})\n", options.output,
                   e.what());
      }
      return kRuntimeFailure;
    }

    writeImageFile(result.image, options.output);
    if (!options.quiet)
      fmt::print(stderr, "lucent: wrote '{}' ({}x{}, {})\n", options.output, scene.render.width,
                 scene.render.height, formatDuration(result.seconds));
    if (options.stats) {
      int threads = control.threads > 0 ? control.threads : static_cast<int>(std::thread::hardware_concurrency());
      printStats(result, threads);
    }
    return kOk;
  } catch (const CameraError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScene;
  } catch (const TextureError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kRuntimeFailure;
  } catch (const std::exception& e) {
    fmt::print(stderr, "lucent: error: {}\n", e.what());
    return kRuntimeFailure;
  }
}

}  // namespace lucent::cli
