// Parallel speed-up of the renderer: one scene rendered with 1, 2, ... all threads in the
// same run, wall time each and the ratio to one thread. The images must be identical
// (the renderer promises bit-identical output for any thread count); this checks it too.
//
//   render_threads [SCENE.xml] [--repeat N]     (default: examples/five-shapes.xml, run from
//                                                the source folder)
#include "lang/parser.h"
#include "render/renderer.h"
#include "scenegraph/world.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

using namespace lucent;

int main(int argc, char** argv) {
  std::string path = "examples/five-shapes.xml";
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else path = argv[i];
  }
  ParseResult parsed = parseSceneFile(path);
  if (!parsed.scene) {
    for (const auto& d : parsed.diagnostics.all()) fmt::print(stderr, "{}\n", d.str());
    return 2;
  }
  World world(*parsed.scene);
  Renderer renderer(world, *parsed.scene->findCamera(""));
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  fmt::print("# render_threads: {} ({}x{}), best of {} runs per thread count\n", path,
             parsed.scene->render.width, parsed.scene->render.height, repeat);
  fmt::print("| threads | seconds | speed-up |\n| --- | --- | --- |\n");
  double single = 0.0;
  Image first;
  for (int threads = 1; threads <= cores; ++threads) {
    double best = 1e300;
    for (int r = 0; r < repeat; ++r) {
      RenderControl control;
      control.threads = threads;
      auto t0 = std::chrono::steady_clock::now();
      RenderResult result = renderer.render(control);
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = std::min(best, s);
      if (first.pixels.empty()) first = result.image;
      else if (result.image.pixels != first.pixels) {
        fmt::print(stderr, "error: the image with {} threads differs from 1 thread\n", threads);
        return 3;
      }
    }
    if (threads == 1) single = best;
    fmt::print("| {} | {:.3f} | {:.2f}x |\n", threads, best, single / best);
  }
  return 0;
}
