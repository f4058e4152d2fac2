// lucent convert SCENE -o OUT.xml: writes the scene as read (every repeat, expression and
// parameterised use expanded) as an equivalent Lucent XML scene (lang/scene_writer.h).
//
// Exit statuses: 1 wrong usage; 2 an invalid scene, or one with a construct the writer
// cannot write yet (an error naming it at its source location; no file is written); 3 the
// scene or the output file cannot be read or written.
#include "commands.h"

#include "frame_loading.h"
#include "load_scene.h"
#include "output_file.h"

#include "lang/scene_writer.h"

#include <filesystem>

namespace lucent::cli {

int runConvert(const ConvertOptions& options, const CommonOptions& common) {
  SceneRequest request;
  request.scene = options.scene;
  checkOverrides(request);
  checkOutputPath(options.output, "an .xml file");

  LoadedScene loaded = loadOneFrame(request, common, options.frame);
  WriteOptions write;
  write.folder = std::filesystem::path(options.output).parent_path().string();
  writeAtomically(options.output, writeSceneXml(*loaded.scene, write));
  return kOk;
}

}  // namespace lucent::cli
