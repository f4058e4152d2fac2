// The cost of one shape's intersection, per ray: each scene (bench/shapes/NAME.xml holds
// one kind of shape alone) is loaded, and its camera's primary rays, one per pixel centre,
// are traced through the world on one thread, as a closest-hit search and as an any-hit
// (shadow) search. The world adds its instance transform and its top-level box to the
// shape's own test, as it does in a render. bench/shape_speed.sh prints these next to the
// whole process against POV-Ray.
//
//   shape_rays SCENE.xml... [--passes N]
#include "lang/parser.h"
#include "render/projection.h"
#include "scenegraph/world.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>

using namespace lucent;

namespace {

// Nanoseconds per ray of f over the rays, the best of `passes` passes.
template <class F>
double nanoseconds(const std::vector<Ray>& rays, int passes, F&& f) {
  double best = 1e300;
  volatile size_t sink = 0;
  for (int p = 0; p < passes; ++p) {
    const auto t0 = std::chrono::steady_clock::now();
    size_t count = 0;
    for (const Ray& r : rays) count += f(r);
    const auto t1 = std::chrono::steady_clock::now();
    sink = sink + count;
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / rays.size());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes;
  int passes = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--passes") == 0 && i + 1 < argc)
      passes = std::max(1, std::atoi(argv[++i]));
    else scenes.push_back(argv[i]);
  }
  if (scenes.empty()) {
    fmt::print(stderr, "usage: shape_rays SCENE.xml... [--passes N]\n");
    return 2;
  }
  fmt::print("scene\trays\thit_fraction\tclosest_ns\tany_ns\n");
  for (const std::string& path : scenes) {
    ParseResult parsed = parseSceneFile(path);
    if (!parsed.scene) {
      for (const auto& d : parsed.diagnostics.all()) fmt::print(stderr, "{}\n", d.str());
      return 2;
    }
    World world(*parsed.scene);
    const int w = parsed.scene->render.width, h = parsed.scene->render.height;
    auto projection = makeProjection(*parsed.scene->findCamera(""), w, h);
    std::vector<Ray> rays;
    rays.reserve(size_t(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        Ray r;
        if (projection->generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), r)) rays.push_back(r);
      }
    size_t hits = 0;
    for (const Ray& r : rays) {
      Hit hit;
      hits += world.intersect(r, hit);
    }
    const double closest = nanoseconds(rays, passes, [&](const Ray& r) {
      Hit hit;
      return world.intersect(r, hit) ? 1 : 0;
    });
    const double any =
        nanoseconds(rays, passes, [&](const Ray& r) { return world.occluded(r) ? 1 : 0; });
    fmt::print("{}\t{}\t{:.3f}\t{:.0f}\t{:.0f}\n", std::filesystem::path(path).stem().string(),
               rays.size(), double(hits) / rays.size(), closest, any);
  }
  return 0;
}
