// Imports POV-Ray scenes through sdl/ several times in one process and prints, per scene,
// the CPU time of the first import (the process's first touch of the importer's code and
// data included) and the least of the later ones (warm): the two figures separate what the
// importer does from what a fresh process pays once (docs/povray-import.md, "Speed").
// The minor page faults of each are printed beside it.
// Usage: pov_import [--runs N] SCENE.pov...
#include "sdl/scene_reader.h"

#include <fmt/core.h>

#include <sys/resource.h>

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

long minorFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

double importSeconds(const std::string& scene, bool& ok, long& faults) {
  QuietOutput quiet;
  sdl::Options options;
  options.imageWidth = 800;
  options.imageHeight = 600;
  options.output = &quiet;
  const long faultsBefore = minorFaults();
  const std::clock_t start = std::clock();
  sdl::SceneLoad load = sdl::loadScene(scene, options);
  const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  faults = minorFaults() - faultsBefore;
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
  fmt::print("{:<40} {:>9} {:>7} {:>9} {:>7}\n", "scene", "first ms", "faults", "warm ms",
             "faults");
  for (const std::string& scene : scenes) {
    bool ok = false;
    long firstFaults = 0, warmFaults = 0, faults = 0;
    const double first = importSeconds(scene, ok, firstFaults);
    double warm = 1e30;
    for (int r = 1; r < runs; ++r) {
      const double s = importSeconds(scene, ok, faults);
      if (s < warm) warm = s, warmFaults = faults;
    }
    fmt::print("{:<40} {:>9.3f} {:>7} {:>9.3f} {:>7}{}\n", scene, 1e3 * first, firstFaults,
               1e3 * warm, warmFaults, ok ? "" : "  (not imported)");
  }
  return 0;
}
