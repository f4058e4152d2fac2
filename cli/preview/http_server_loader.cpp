// Finds and loads the preview's server plugin (http_server.h says why it is one): beside
// the running program, where the build writes it, else where this build wrote it (for the
// tests, which run from other folders).
#include "http_server.h"

#include "images/plugin_library.h"

#include <fmt/core.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace fs = std::filesystem;

namespace lucent::preview {

namespace {

constexpr const char* kPluginFile = "lucent-preview-server.so";

std::vector<fs::path> candidatePaths() {
#ifdef LUCENT_PREVIEW_SERVER_BUILD_PATH
  return pluginPaths(kPluginFile, LUCENT_PREVIEW_SERVER_BUILD_PATH);
#else
  return pluginPaths(kPluginFile, nullptr);
#endif
}

// The plugin's entry; the library stays loaded for the process's life.
LucentPreviewServerEntry loadEntry() {
  std::string tried;
  if (void* entry = loadPluginEntry(
          candidatePaths(), LUCENT_PREVIEW_SERVER_ENTRY, [](void*) { return true; },
          "not this version's preview server", tried))
    return reinterpret_cast<LucentPreviewServerEntry>(entry);
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
