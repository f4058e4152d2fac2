// Finding and loading a plugin (a shared library loaded only by the commands that need it:
// the image library, the preview's web server): where to look, and the first file there
// that loads and holds the entry wanted.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lucent {

// Beside the running program (the build puts plugins beside `lucent`), then `builtPath`
// when given (where this build wrote it, for the tests and benchmarks in other folders).
std::vector<std::filesystem::path> pluginPaths(const char* file, const char* builtPath);

// The symbol `entry` of the first of `paths` that exists, loads and whose entry `accept`s;
// null if none, with `tried` telling what each path gave (`rejected` for one not accepted).
// A library loaded stays loaded for the process's life.
void* loadPluginEntry(const std::vector<std::filesystem::path>& paths, const char* entry,
                      const std::function<bool(void*)>& accept, const std::string& rejected,
                      std::string& tried);

}  // namespace lucent
