// lucent check SCENE.xml: parses and validates the scene (no rendering, no primitives),
// prints every error and warning to stderr and a summary to stdout.
// Exit status: 0 valid, 2 invalid scene, 3 the scene file itself cannot be read.
#include "commands.h"

#include "lang/parser.h"
#include "scenegraph/scene_summary.h"

#include <fmt/core.h>

#include <cstdio>

namespace lucent::cli {

int runCheck(const std::string& scenePath, const CommonOptions& common) {
  ParseOptions options;
  options.defines = common.defines;
  options.allowPaths = common.allowPaths;
  ParseResult result = parseSceneFile(scenePath, options);
  for (const Diagnostic& d : result.diagnostics.all()) fmt::print(stderr, "{}\n", d.str());
  if (result.ioFailure) return kRuntimeFailure;
  if (!result.scene) {
    size_t n = result.diagnostics.errorCount();
    fmt::print(stderr, "{}: {} error{}; the scene is invalid\n", scenePath, n, n == 1 ? "" : "s");
    return kInvalidScene;
  }
  fmt::print("{}", sceneSummary(*result.scene));
  return kOk;
}

}  // namespace lucent::cli
