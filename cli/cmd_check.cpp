// lucent check SCENE.xml: parses and validates the scene (no rendering, no shapes built),
// prints every error and warning to stderr and a summary to stdout. It runs render's
// checks too (loadScene): transforms beyond range, the camera at the image size, the
// headers of image textures. Exit status: 0 valid, 1 wrong usage, 2 invalid scene, 3 the
// scene file or an image it names cannot be read.
#include "commands.h"

#include "load_scene.h"

#include "scenegraph/scene_summary.h"

#include <fmt/core.h>

namespace lucent::cli {

int runCheck(const CheckOptions& options, const CommonOptions& common) {
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.samples = options.samples;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  LoadedScene loaded = loadScene(request, common);
  fmt::print("{}", sceneSummary(*loaded.scene));
  return kOk;
}

}  // namespace lucent::cli
