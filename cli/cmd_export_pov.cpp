// lucent export-pov SCENE -o OUT.pov: writes an equivalent POV-Ray 3.7 scene.
//
// Exit statuses: 1 wrong usage (also an unknown --camera); 2 an invalid scene, or one with
// constructs POV-Ray cannot express (each is an error naming the element; no file is
// written); 3 the scene or the output file cannot be read or written. Warnings (what is
// only approximated) are printed and the file is written.
#include "commands.h"

#include "lang/parser.h"
#include "povray/pov_export.h"

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace lucent::cli {

namespace {

// Writes through a temporary file in the same folder renamed over `path`, so an existing
// file is replaced only by a complete one (the contract's rule for outputs).
bool writeAtomically(const std::string& path, const std::string& text, std::string& error) {
  namespace fs = std::filesystem;
  fs::path target(path);
  fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = fmt::format("cannot write '{}'", tmp.string());
      return false;
    }
    out << text;
    out.flush();
    if (!out) {
      error = fmt::format("cannot write '{}'", tmp.string());
      std::error_code ignored;
      fs::remove(tmp, ignored);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    error = fmt::format("cannot write '{}': {}", path, ec.message());
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

}  // namespace

int runExportPov(const ExportPovOptions& options, const CommonOptions& common) {
  for (auto [value, name] : {std::pair{options.width, "--width"},
                             std::pair{options.height, "--height"},
                             std::pair{options.maxDepth, "--max-depth"}}) {
    if (auto e = overrideProblem(name, value)) {
      fmt::print(stderr, "lucent: error: {}\n", *e);
      return kUsage;
    }
  }
  if (std::filesystem::is_directory(options.output)) {
    fmt::print(stderr, "lucent: error: '{}' is a folder, not a .pov file\n", options.output);
    return kRuntimeFailure;
  }

  ParseOptions parseOptions;
  parseOptions.defines = common.defines;
  parseOptions.allowPaths = common.allowPaths;
  ParseResult parsed = parseSceneFile(options.scene, parseOptions);
  for (const Diagnostic& d : parsed.diagnostics.all()) fmt::print(stderr, "{}\n", d.str());
  if (parsed.ioFailure) return kRuntimeFailure;
  if (!parsed.scene) return kInvalidScene;
  Scene& scene = *parsed.scene;
  if (options.width) scene.render.width = *options.width;
  if (options.height) scene.render.height = *options.height;
  if (options.maxDepth) scene.render.maxDepth = *options.maxDepth;
  if (!options.camera.empty() && !scene.findCamera(options.camera)) {
    fmt::print(stderr, "lucent: error: --camera {}: no camera of that name in '{}'\n",
               options.camera, options.scene);
    return kUsage;
  }

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
  std::string error;
  if (!writeAtomically(options.output, exported.text, error)) {
    fmt::print(stderr, "lucent: error: {}\n", error);
    return kRuntimeFailure;
  }
  return kOk;
}

}  // namespace lucent::cli
