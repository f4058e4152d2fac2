// The subcommands of `lucent`, each in its own file; main.cpp parses options and dispatches.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lucent::cli {

// The contract's exit statuses.
enum ExitCode { kOk = 0, kUsage = 1, kInvalidScene = 2, kRuntimeFailure = 3 };

// The problem with a numeric override (-w, -h, -s, -t, --max-depth) named `name`, if any:
// below 1, or above the limit the scene's <render> has too (render_settings.h).
std::optional<std::string> overrideProblem(const std::string& name, const std::optional<int>& value);

// Options every command accepts.
struct CommonOptions {
  std::map<std::string, std::string> defines;  // -D name=value
  std::vector<std::string> allowPaths;         // --allow-path DIR
};

struct RenderOptions {
  std::string scene;
  std::string output;
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;
  bool quiet = false;
  bool stats = false;
};

int runRender(const RenderOptions& options, const CommonOptions& common);
int runCheck(const std::string& scene, const CommonOptions& common);
// The XML Schema of the scene language, to stdout or to `output`.
int runSchema(const std::string& output);

struct ExportPovOptions {
  std::string scene;
  std::string output;
  std::optional<int> width, height, maxDepth;  // the image the .pov file is written for
  std::string camera;
};
int runExportPov(const ExportPovOptions& options, const CommonOptions& common);

struct CompareOptions {
  std::string scene;
  std::string outputDir;
  std::string povFile;  // --pov: a hand-written POV-Ray scene instead of the export
  std::optional<int> width, height, samples, threads, maxDepth;
  std::string camera;
};
int runCompare(const CompareOptions& options, const CommonOptions& common);

}  // namespace lucent::cli
