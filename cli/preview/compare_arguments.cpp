#include "compare_arguments.h"

namespace lucent::preview {

std::vector<std::string> compareArguments(const cli::PreviewOptions& options,
                                          const cli::CommonOptions& common, int width, int height) {
  std::vector<std::string> a{options.scene, "-w", std::to_string(width), "-h",
                             std::to_string(height)};
  auto number = [&](const char* name, const std::optional<int>& value) {
    if (value) a.insert(a.end(), {name, std::to_string(*value)});
  };
  number("-s", options.samples);
  number("-t", options.threads);
  number("--max-depth", options.maxDepth);
  if (!options.camera.empty()) a.insert(a.end(), {"--camera", options.camera});
  for (const auto& [name, value] : common.defines) a.insert(a.end(), {"-D", name + "=" + value});
  for (const std::string& path : common.allowPaths) a.insert(a.end(), {"--allow-path", path});
  if (!common.format.empty()) a.insert(a.end(), {"--format", common.format});
  for (const std::string& path : common.povLibrary) a.insert(a.end(), {"--pov-library", path});
  if (!common.povIni.empty()) a.insert(a.end(), {"--pov-ini", common.povIni});
  if (common.skipUnsupported) a.push_back("--skip-unsupported");
  for (const std::string& path : common.allowWrite) a.insert(a.end(), {"--allow-write", path});
  if (common.povMaxTokens)
    a.insert(a.end(), {"--pov-max-tokens", std::to_string(*common.povMaxTokens)});
  return a;
}

}  // namespace lucent::preview
