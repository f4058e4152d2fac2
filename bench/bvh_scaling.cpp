// Time per ray as the number of primitives grows from 10^2 to 10^6: spheres scattered over
// the unit sphere (each an instance in the world's top-level BVH) and one displaced-sphere
// mesh (the mesh's own BVH), traced with the same camera on one thread. Both keep the
// picture the same as n grows, so a BVH makes the time grow with log n.
//
//   bvh_scaling [--max N] [--size W] [--tsv FILE]
#include "bench_util.h"
#include "scenegraph/shape_registry.h"

#include "scenegraph/world.h"

#include <tbb/global_control.h>

#include <random>

using namespace lucent;
using namespace lucent::bench;

namespace {

std::unique_ptr<Node> shapeNode(ShapeSpec spec) {
  auto n = std::make_unique<Node>();
  n->kind = NodeKind::Shape;
  n->element = shapeElementName(spec);
  n->shape = std::move(spec);
  return n;
}

// Nanoseconds per closest-hit query over the rays (best of three runs, on the thread's
// CPU clock: the machine is shared), and the share of rays that hit.
std::pair<double, double> timePerRay(const World& world, const std::vector<Ray>& rays) {
  size_t hits = 0;
  double s = bestOfCpu(3, [&] {
    hits = 0;
    for (const Ray& r : rays) {
      Hit h;
      hits += world.intersect(r, h);
    }
  });
  return {s / rays.size() * 1e9, double(hits) / rays.size()};
}

}  // namespace

int main(int argc, char** argv) {
  size_t maxN = 1000000;
  int size = 256;
  std::string tsvPath;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--max") maxN = std::stoul(argv[i + 1]);
    else if (a == "--size") size = std::stoi(argv[i + 1]);
    else if (a == "--tsv") tsvPath = argv[i + 1];
    else throw std::invalid_argument("unknown option " + a);
  }
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  fmt::print("# bvh_scaling: {}x{} camera rays, one thread (its CPU time); {}, load {}\n", size,
             size, cpuModel(), loadAverage());
  const auto rays = cameraRays(size, size, Vec3(0.6, 0.9, 3.2), Vec3(0.0), 40.0);

  TsvFile tsv(tsvPath);
  fmt::print("\n| primitives | spheres ns/ray | (hit) | triangles ns/ray | (hit) |\n");
  fmt::print("|---|---|---|---|---|\n");
  for (size_t n = 100; n <= maxN; n *= 10) {
    // Spheres scattered over the unit sphere, their radius shrinking as 1/sqrt(n) so they
    // cover it about once whatever their number: the same depth complexity as the mesh.
    Scene spheres;
    std::mt19937_64 rng(n);
    std::normal_distribution<double> g(0.0, 1.0);
    double radius = 2.0 / std::sqrt(double(n));
    for (size_t i = 0; i < n; ++i) {
      Vec3 c = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
      spheres.root->children.push_back(shapeNode(SphereSpec{c, radius}));
    }
    double sphereNs, sphereHit;
    {
      World world(spheres);
      std::tie(sphereNs, sphereHit) = timePerRay(world, rays);
    }

    Scene mesh;
    auto data = std::make_shared<MeshData>(displacedSphereOf(n));
    size_t triangles = data->triangles.size();
    mesh.root->children.push_back(shapeNode(MeshSpec{"", SmoothMode::False, data}));
    World meshWorld(mesh);
    auto [meshNs, meshHit] = timePerRay(meshWorld, rays);

    fmt::print("| {} ({} triangles) | {:.0f} | {:.0f}% | {:.0f} | {:.0f}% |\n", n, triangles,
               sphereNs, 100 * sphereHit, meshNs, 100 * meshHit);
    std::fflush(stdout);
    tsv.row("{}\t{:.2f}\t{:.2f}\t{}", n, sphereNs, meshNs, triangles);
  }
  return 0;
}
