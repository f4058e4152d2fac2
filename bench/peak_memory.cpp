// Peak memory of a whole `lucent render` run: writes a scene with one displaced-sphere
// mesh of about N triangles (a binary PLY file beside it), runs the given lucent binary on
// it and reports the child's peak resident memory (getrusage's ru_maxrss) and its time,
// beside the same figures for `lucent --version`: what the process costs before any scene.
//
//   peak_memory LUCENT_BINARY WORK_DIR [--triangles N] [--size W]
#include "bench_scenes.h"
#include "child_process.h"

using namespace lucent;
using namespace lucent::bench;

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: peak_memory LUCENT_BINARY WORK_DIR [--triangles N] [--size W]\n");
    return 2;
  }
  std::string lucent = argv[1], dir = argv[2];
  size_t triangles = 1000000;
  int size = 640;
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") triangles = std::stoul(argv[i + 1]);
    else if (a == "--size") size = std::stoi(argv[i + 1]);
    else throw std::invalid_argument("unknown option " + a);
  }

  size_t written = writeMeshScene(dir, triangles, size);

  // The process alone (`lucent --version`: its shared libraries and static data), then
  // the render.
  auto run = [&](std::vector<std::string> args) { return runChild(lucent, args); };
  ChildRun base = run({"--version"});
  ChildRun render = run({"render", dir + "/bumpy.xml", "-o", dir + "/bumpy.png", "-q"});
  fmt::print("# peak_memory: lucent render of {} triangles at {}x{}; {}, load {}\n", written, size,
             size, cpuModel(), loadAverage());
  fmt::print("\n| run | exit | wall time | peak memory |\n|---|---|---|---|\n");
  fmt::print("| `lucent --version` (the process alone) | {} | {:.1f} s | {:.0f} MB |\n",
             base.ok ? "0" : "FAILED", base.seconds, base.peakMB);
  fmt::print("| `lucent render`, {} triangles, {}x{} | {} | {:.1f} s | {:.0f} MB |\n", written,
             size, size, render.ok ? "0" : "FAILED", render.seconds, render.peakMB);
  fmt::print("| the scene's share (difference) | | | {:.0f} MB |\n", render.peakMB - base.peakMB);
  bool ok = render.ok;
  return ok ? 0 : 1;
}
