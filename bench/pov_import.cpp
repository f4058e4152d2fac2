// Imports POV-Ray scenes through sdl/ several times in one process and prints, per scene,
// the CPU time of the first import (the process's first touch of the importer's code and
// data included) and the least of the later ones (warm): the two figures separate what the
// importer does from what a fresh process pays once (docs/povray-import.md, "Speed").
// Usage: pov_import [--runs N] SCENE.pov...
#include "sdl/scene_reader.h"

#include <fmt/core.h>

#include <algorithm>
#include <ctime>
#include <string>
#include <vector>

using namespace lucent;

namespace {

class QuietOutput : public sdl::Output {
 public:
  void debug(const std::string&) override {}
  void warning(const SourceLoc&, const std::string&) override {}
};

double importSeconds(const std::string& scene, bool& ok) {
  QuietOutput quiet;
  sdl::Options options;
  options.imageWidth = 800;
  options.imageHeight = 600;
  options.output = &quiet;
  const std::clock_t start = std::clock();
  sdl::SceneLoad load = sdl::loadScene(scene, options);
  const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  ok = load.scene != nullptr;
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 20;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::max(2, std::stoi(argv[++i]));
    } else {
      scenes.push_back(a);
    }
  }
  if (scenes.empty()) {
    fmt::print(stderr, "usage: pov_import [--runs N] SCENE.pov...\n");
    return 1;
  }
  fmt::print("{:<50} {:>10} {:>10}\n", "scene", "first ms", "warm ms");
  for (const std::string& scene : scenes) {
    bool ok = false;
    const double first = importSeconds(scene, ok);
    double warm = 1e30;
    for (int r = 1; r < runs; ++r) warm = std::min(warm, importSeconds(scene, ok));
    fmt::print("{:<50} {:>10.3f} {:>10.3f}{}\n", scene, 1e3 * first, 1e3 * warm,
               ok ? "" : "  (not imported)");
  }
  return 0;
}
