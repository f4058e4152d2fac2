// Thread scaling: primary and shadow rays per second on the million-triangle mesh with
// 1, 2, ... all hardware threads (TBB, chunks of 1024 coherent rays).
//
//   bvh_threads [--triangles N] [--size W] [--tsv FILE]
#include "bench_util.h"

#include "scenegraph/world.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>

using namespace lucent;
using namespace lucent::bench;

int main(int argc, char** argv) {
  size_t triangles = 1000000;
  int size = 1024;
  std::string tsvPath;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") triangles = std::stoul(argv[i + 1]);
    else if (a == "--size") size = std::stoi(argv[i + 1]);
    else if (a == "--tsv") tsvPath = argv[i + 1];
    else throw std::invalid_argument("unknown option " + a);
  }
  const unsigned maxThreads = hardwareThreads();
  auto data = std::make_shared<MeshData>(displacedSphereOf(triangles));
  Scene scene;
  auto node = std::make_unique<Node>();
  node->kind = NodeKind::Shape;
  node->element = "mesh";
  node->shape = MeshSpec{"", SmoothMode::False, data};
  scene.root->children.push_back(std::move(node));
  World world(scene);
  fmt::print("# bvh_threads: {} triangles, {}x{} rays; {} ({} threads), load {}\n",
             data->triangles.size(), size, size, cpuModel(), maxThreads, loadAverage());

  const Vec3 light(4.0, 6.0, 5.0);
  const auto primary = cameraRays(size, size, Vec3(0.6, 0.9, 3.2), Vec3(0.0), 40.0);
  std::vector<Ray> shadow;
  for (const Ray& r : primary) {
    Hit h;
    if (world.intersect(r, h)) shadow.push_back(shadowRay(r.at(h.t), light));
  }

  auto rate = [&](const std::vector<Ray>& rays, bool closest) {
    std::atomic<size_t> sink{0};
    double s = bestOf(3, [&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const auto& r) {
        size_t n = 0;
        for (size_t i = r.begin(); i != r.end(); ++i) {
          Hit h;
          n += closest ? world.intersect(rays[i], h) : world.occluded(rays[i]);
        }
        sink += n;
      });
    });
    return rays.size() / s / 1e6;
  };

  TsvFile tsv(tsvPath);
  fmt::print("\n| threads | primary Mrays/s | speed-up | shadow Mrays/s | speed-up |\n");
  fmt::print("|---|---|---|---|---|\n");
  double base1 = 0, base2 = 0;
  for (unsigned t = 1; t <= maxThreads; ++t) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, t);
    double p = rate(primary, true), s = rate(shadow, false);
    if (t == 1) base1 = p, base2 = s;
    fmt::print("| {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n", t, p, p / base1, s, s / base2);
    tsv.row("{}\t{:.4f}\t{:.4f}\t{:.4f}\t{:.4f}", t, p, p / base1, s, s / base2);
  }
  return 0;
}
