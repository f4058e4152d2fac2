// lucent export-pov SCENE -o OUT.pov: writes an equivalent POV-Ray 3.7 scene.
//
// Exit statuses: 1 wrong usage (also an unknown --camera); 2 an invalid scene, or one with
// constructs POV-Ray cannot express (each is an error naming the element; no file is
// written); 3 the scene or the output file cannot be read or written. Warnings (what is
// only approximated) are printed and the file is written.
#include "commands.h"

#include "frame_loading.h"
#include "load_scene.h"

#include "povray/pov_export.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lucent::cli {

namespace {

// Writes through a temporary file in the same folder renamed over `path`, so an existing
// file is replaced only by a complete one (the contract's rule for outputs). Messages name
// `path` and its folder, never the temporary file, which the user did not ask for.
namespace fs = std::filesystem;

fs::path folderOf(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

// Before the scene is read: an output that can never be written is an error now.
void checkPovOutputPath(const std::string& path) {
  if (fs::is_directory(path))
    throw IoFailure(fmt::format("'{}' is a folder, not a .pov file", path));
  const fs::path folder = folderOf(path);
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (status.type() == fs::file_type::not_found)
    throw IoFailure(
        fmt::format("cannot write '{}': folder '{}' does not exist", path, folder.string()));
  if (!ec && status.type() != fs::file_type::directory)
    throw IoFailure(fmt::format("cannot write '{}': '{}' is not a folder", path, folder.string()));
}

void writeAtomically(const std::string& path, const std::string& text) {
  fs::path target(path);
  fs::path folder = folderOf(target);
  std::error_code ec;
  fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  auto failed = [&](const std::string& reason) {
    fs::remove(tmp, ec);
    return IoFailure(fmt::format("cannot write '{}': {}", path, reason));
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw failed(fmt::format("cannot create a file in folder '{}': {}", folder.string(),
                               std::strerror(errno)));
    out << text;
    out.flush();
    if (!out) throw failed(std::strerror(errno));
  }
  fs::rename(tmp, target, ec);
  if (ec) throw failed(ec.message());
}

}  // namespace

int runExportPov(const ExportPovOptions& options, const CommonOptions& common) {
  SceneRequest request;
  request.scene = options.scene;
  request.width = options.width;
  request.height = options.height;
  request.maxDepth = options.maxDepth;
  request.camera = options.camera;
  checkOverrides(request);
  checkPovOutputPath(options.output);

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
