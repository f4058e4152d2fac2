// Finds and loads the preview's server plugin (http_server.h says why it is one): beside
// the running program, where the build writes it, else where this build wrote it (for the
// tests, which run from other folders).
#include "http_server.h"

#include <fmt/core.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

#include <dlfcn.h>

namespace fs = std::filesystem;

namespace lucent::preview {

namespace {

constexpr const char* kPluginFile = "lucent-preview-server.so";

std::vector<fs::path> candidatePaths() {
  std::vector<fs::path> paths;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back(self.parent_path() / kPluginFile);
#ifdef LUCENT_PREVIEW_SERVER_BUILD_PATH
  const fs::path built(LUCENT_PREVIEW_SERVER_BUILD_PATH);
  if (paths.empty() || built != paths.front()) paths.push_back(built);
#endif
  return paths;
}

// The plugin's entry; the library stays loaded for the process's life.
LucentPreviewServerEntry loadEntry() {
  std::string tried;
  for (const fs::path& path : candidatePaths()) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      tried += fmt::format("\n  {}: no such file", path.string());
      continue;
    }
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      tried += fmt::format("\n  {}: {}", path.string(), why ? why : "cannot be loaded");
      continue;
    }
    if (auto entry = reinterpret_cast<LucentPreviewServerEntry>(
            ::dlsym(handle, LUCENT_PREVIEW_SERVER_ENTRY)))
      return entry;
    tried += fmt::format("\n  {}: not this version's preview server", path.string());
  }
  throw std::runtime_error(fmt::format(
      "cannot load the preview's web server ({}); tried:{}\n  (rebuild Lucent, or keep it "
      "beside the lucent program)",
      kPluginFile, tried));
}

}  // namespace

std::unique_ptr<HttpServer> startHttpServer(const HttpServerSetup& setup) {
  static const LucentPreviewServerEntry entry = loadEntry();
  std::string error;
  std::unique_ptr<HttpServer> server(entry(setup, error));
  if (!server) throw std::runtime_error(error);
  return server;
}

}  // namespace lucent::preview
