#include "plugin_library.h"

#include <fmt/core.h>

#include <dlfcn.h>

namespace fs = std::filesystem;

namespace lucent {

std::vector<fs::path> pluginPaths(const char* file, const char* builtPath) {
  std::vector<fs::path> paths;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back(self.parent_path() / file);
  if (builtPath) {
    const fs::path built(builtPath);
    if (paths.empty() || built != paths.front()) paths.push_back(built);
  }
  return paths;
}

void* loadPluginEntry(const std::vector<fs::path>& paths, const char* entry,
                      const std::function<bool(void*)>& accept, const std::string& rejected,
                      std::string& tried) {
  for (const fs::path& path : paths) {
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
    if (void* symbol = ::dlsym(handle, entry); symbol && accept(symbol)) return symbol;
    tried += fmt::format("\n  {}: {}", path.string(), rejected);
  }
  return nullptr;
}

}  // namespace lucent
