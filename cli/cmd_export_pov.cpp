// lucent export-pov SCENE -o OUT.pov: writes an equivalent POV-Ray 3.7 scene.
//
// Exit statuses: 1 wrong usage (also an unknown --camera); 2 an invalid scene, or one with
// constructs POV-Ray cannot express (each is an error naming the element; no file is
// written); 3 the scene or the output file cannot be read or written. Warnings (what is
// only approximated) are printed and the file is written.
#include "commands.h"

#include "frame_loading.h"
#include "load_scene.h"
#include "output_file.h"

#include "povray/pov_export.h"

#include <fmt/core.h>

#include <cstdio>

namespace lucent::cli {

int runExportPov(const ExportPovOptions& options, const CommonOptions& common) {
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  checkOverrides(request);
  checkOutputPath(options.output, "a .pov file");

  LoadedScene loaded = loadOneFrame(request, common, options.frame);
  const Scene& scene = *loaded.scene;
  PovExport exported = exportPov(scene, PovExportOptions{options.camera});
  size_t errors = 0;
  for (const PovIssue& issue : exported.issues) {
    fmt::print(stderr, "{}\n", issue.str());
    if (issue.error) ++errors;
  }
  if (!exported.ok()) {
    fmt::print(stderr, "{}: {} construct{} without a POV-Ray equivalent; nothing written\n",
               options.scene, errors, errors == 1 ? "" : "s");
    return kInvalidScene;
  }
  writeAtomically(options.output, exported.text);
  return kOk;
}

}  // namespace lucent::cli
