// Finds, loads and hands out the OpenImageIO plugin (image_plugin.h says why it is one).
#include "image_plugin.h"

#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include <dlfcn.h>

#include "address_sanitizer.h"
#include "plugin_library.h"

#if defined(LUCENT_ASAN)
// Sanitized builds only. The plugin is loaded with dlopen, so the thread-local variables of
// OpenImageIO and its libraries live in blocks that glibc allocates with malloc. The
// sanitizer runtime of GCC 12 (and LLVM up to 16) takes such a block for a glibc 2.19 one
// when its address is 16 bytes past a page boundary, which happens by chance, and reads a
// length from before it; LeakSanitizer then crashes at exit ("Tracer caught signal 11"),
// now and then (google/sanitizers#1322; one gallery test in one CI run). Not intercepting
// __tls_get_addr avoids the misreading, and the blocks are still scanned for pointers:
// LeakSanitizer counts what the dynamic linker allocates as reachable. ASAN_OPTIONS in
// the environment still overrides this default.
extern "C" __attribute__((visibility("default"), used)) const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
#endif

namespace fs = std::filesystem;

namespace lucent {

namespace {

constexpr const char* kPluginFile = "lucent-oiio.so";

// Where to look: the file named by LUCENT_IMAGE_PLUGIN if it is set (and nothing else);
// otherwise beside the running program, then where this build wrote it.
std::vector<fs::path> candidatePaths() {
  if (const char* chosen = std::getenv("LUCENT_IMAGE_PLUGIN"); chosen && *chosen)
    return {fs::path(chosen)};
#ifdef LUCENT_IMAGE_PLUGIN_BUILD_PATH
  return pluginPaths(kPluginFile, LUCENT_IMAGE_PLUGIN_BUILD_PATH);
#else
  return pluginPaths(kPluginFile, nullptr);
#endif
}

class Loader {
 public:
  const ImagePlugin& get() {
    std::call_once(once_, [this] { load(); });  // other callers wait for the first
    if (!plugin_) throw ImagePluginError(error_);
    return *plugin_;
  }

 private:
  // Never throws: the outcome is kept for every caller. The library is never unloaded
  // (its code may be on the stack of a thread at exit, and leak reports need its symbols).
  void load() {
    std::string tried;
    const ImagePlugin* plugin = nullptr;
    const auto accept = [&plugin](void* symbol) {
      int version = 0;
      plugin = reinterpret_cast<LucentImagePluginEntry>(symbol)(&version);
      return plugin && version == kImagePluginVersion;
    };
    if (loadPluginEntry(candidatePaths(), LUCENT_IMAGE_PLUGIN_ENTRY, accept,
                        fmt::format("not a Lucent image plugin of version {}", kImagePluginVersion),
                        tried)) {
      plugin_ = plugin;
      return;
    }
    const bool chosen = std::getenv("LUCENT_IMAGE_PLUGIN") && *std::getenv("LUCENT_IMAGE_PLUGIN");
    error_ = fmt::format(
        "cannot load the image library ({}, OpenImageIO), which reads and "
        "writes every image; tried:{}\n  ({})",
        kPluginFile, tried,
        chosen ? "the environment variable LUCENT_IMAGE_PLUGIN names it; unset "
                 "it to use the one beside the lucent program"
               : "rebuild Lucent, or keep it beside the lucent program");
  }

  std::once_flag once_;
  const ImagePlugin* plugin_ = nullptr;
  std::string error_;
};

Loader& loader() {
  static Loader instance;
  return instance;
}

}  // namespace

const ImagePlugin& imagePlugin() { return loader().get(); }

}  // namespace lucent
