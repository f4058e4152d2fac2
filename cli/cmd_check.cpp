// lucent check SCENE.xml: parses and validates the scene (no rendering, no shapes built),
// prints every error and warning to stderr and a summary to stdout. It runs render's
// checks too (loadScene): transforms beyond range, the camera at the image size, the
// headers of image textures. An animated scene is checked frame by frame, each parsed for
// its frame as render would; the first frame that fails is named with its clock, and the
// summary (of frame 1) says how many frames were checked. Exit status: 0 valid, 1 wrong
// usage, 2 invalid scene, 3 the scene file or an image it names cannot be read.
#include "commands.h"

#include "frame_loading.h"
#include "load_scene.h"

#include "meshes/mesh_file_cache.h"
#include "scenegraph/scene_summary.h"

#include <fmt/core.h>

#include <chrono>
#include <ctime>
#include <set>

namespace lucent::cli {

namespace {

std::string animationSummary(const Scene& scene, bool oneMoment) {
  const Animation& a = scene.animation;
  if (oneMoment)
    return fmt::format("animation: {} frames; checked frame {} (clock {}), as -D chose\n", a.frames,
                       scene.frame, scene.clock);
  return fmt::format("animation: {} frame{}, clock {} to {}{}; every frame checked\n", a.frames,
                     a.frames == 1 ? "" : "s", a.clockFrom, a.clockTo, a.cyclic ? " (cyclic)" : "");
}

}  // namespace

int runCheck(const CheckOptions& options, const CommonOptions& common) {
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.samples = options.samples;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  request.meshCache = std::make_shared<MeshFileCache>();
  std::set<std::string> printed;  // a warning every frame has is printed once
  request.printed = &printed;
  // The CPU time of reading the scene (parsing or evaluating it, building the scene and
  // checking it), for comparisons such as POV-Ray's "Parse Time" (bench/pov_samples.sh).
  // Wall time too: POV-Ray reports its parse in wall-clock milliseconds.
  const std::clock_t start = std::clock();
  const auto wallStart = std::chrono::steady_clock::now();
  LoadedScene loaded = loadScene(request, common);
  const double readSeconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  const double readWall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  const Animation animation = loaded.scene->animation;
  const bool oneMoment = picksOneMoment(common);
  std::string summary = sceneSummary(*loaded.scene);
  if (options.stats)
    summary += fmt::format("read in: {:.4f} s of CPU time, {:.4f} s of wall time{}\n", readSeconds,
                           readWall, animation.present ? " (the first frame)" : "");
  if (animation.present) summary += animationSummary(*loaded.scene, oneMoment);
  if (animation.present && !oneMoment) {
    loaded = {};  // one frame in memory at a time
    for (int f = 2; f <= animation.frames; ++f) {
      request.frame = f;
      loadFrame(request, common, animation);
    }
  }
  fmt::print("{}", summary);
  return kOk;
}

}  // namespace lucent::cli
