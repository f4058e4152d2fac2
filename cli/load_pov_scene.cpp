#include "load_pov_scene.h"

#include "lang/file_access.h"
#include "sdl/scene_reader.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace lucent::cli {

namespace fs = std::filesystem;

bool isPovScene(const std::string& scene, const std::string& format) {
  if (!format.empty()) return format == "pov";
  std::string ext = fs::path(scene).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".pov" || ext == ".inc";
}

ParseResult parsePovScene(const SceneRequest& request, const CommonOptions& common) {
  ParseResult result;
  if (!std::ifstream(request.scene) || fs::is_directory(request.scene)) {
    result.diagnostics.error(SourceLoc{request.scene, 0, 0}, "cannot read the scene file");
    result.ioFailure = true;
    return result;
  }
  const fs::path folder = fs::path(request.scene).parent_path();
  FileAccess access(folder.empty() ? fs::path(".") : folder, common.allowPaths);
  sdl::Options options;
  options.access = &access;
  options.imageWidth = request.width.value_or(800);  // POV-Ray's own default size
  options.imageHeight = request.height.value_or(600);
  for (const auto& [name, value] : common.defines) {
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size())
      throw UsageError(fmt::format(
          "-D {}={}: a POV-Ray scene is given numbers (as POV-Ray's Declare=), not '{}'", name,
          value, value));
    options.declared[name] = v;
  }
  sdl::SceneLoad load = sdl::loadScene(request.scene, options);
  result.scene = std::move(load.scene);
  result.diagnostics = std::move(load.diagnostics);
  result.sources.push_back(canonicalPath(request.scene));
  for (const fs::path& f : access.granted())
    if (std::find(result.sources.begin(), result.sources.end(), f) == result.sources.end())
      result.sources.push_back(f);
  return result;
}

}  // namespace lucent::cli
