// BVH build speed on the million-triangle mesh, and the quality of the tree it makes.
// One thread is timed on the thread's CPU clock (waiting for a core on a shared machine
// is not counted); all threads on the wall clock. Quality is the tree's SAH cost (node
// visits + triangle tests expected per random ray that hits the root box; a figure of
// the tree alone, independent of the machine's load) and the rate of camera rays on one
// thread (CPU clock).
//
//   bvh_build [--triangles N] [--repeat R]
#include "bench_util.h"

#include "primitives/bvh.h"
#include "primitives/hit.h"
#include "primitives/triangle_mesh.h"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

using namespace lucent;
using namespace lucent::bench;

namespace {

double halfArea(const AABB& b) {
  Vec3 e = b.hi - b.lo;
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The SAH cost (Goldsmith and Salmon 1987; MacDonald and Booth 1990) with both costs 1:
// for every child entry, the chance that a ray through the root box enters it (its
// area over the root's) times one node test, or times its item count for a leaf.
double sahCost(const Bvh& bvh) {
  const BvhNodes& nodes = bvh.nodes();
  double root = halfArea(bvh.bounds()), cost = 1.0;
  for (const BvhNode& n : nodes)
    for (int c = 0; c < BvhNode::kWidth; ++c) {
      if (n.isEmpty(c)) continue;
      double p = halfArea(n.bounds(c)) / root;
      cost += p * (n.isLeaf(c) ? double(n.count[c]) : 1.0);
    }
  return cost;
}

}  // namespace

int main(int argc, char** argv) {
  size_t triangles = 1000000;
  int repeat = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") triangles = std::stoul(argv[i + 1]);
    else if (a == "--repeat") repeat = std::stoi(argv[i + 1]);
    else throw std::invalid_argument("unknown option " + a);
  }
  auto mesh = std::make_shared<MeshData>(displacedSphereOf(triangles));
  const double T = double(mesh->triangles.size());
  const unsigned threads = hardwareThreads();
  fmt::print("# bvh_build: {} triangles; {} ({} threads), load {}\n", mesh->triangles.size(),
             cpuModel(), threads, loadAverage());

  std::shared_ptr<TriangleMesh> shape;
  double one;
  {
    tbb::task_arena arena(1);
    arena.execute([&] {
      one = bestOfCpu(repeat, [&] { shape = std::make_shared<TriangleMesh>(mesh, false); });
    });
  }
  double all = bestOf(repeat, [&] { shape = std::make_shared<TriangleMesh>(mesh, false); });

  // The bare BVH over the triangles' boxes (no mesh bookkeeping), one thread.
  std::vector<AABB> boxes(mesh->triangles.size());
  for (size_t i = 0; i < boxes.size(); ++i)
    for (uint32_t v : mesh->triangles[i]) boxes[i].expand(mesh->positions[v]);
  Bvh bvh;
  double bare = bestOfCpu(repeat, [&] {
    BvhOptions o;
    o.parallel = false;
    o.minLeafSize = 2;
    bvh = Bvh(boxes, o);
  });

  const auto rays = cameraRays(1024, 1024, Vec3(0.6, 0.9, 3.2), Vec3(0.0), 40.0);
  size_t hits = 0;
  double trace = bestOfCpu(3, [&] {
    hits = 0;
    for (const Ray& r : rays) {
      Hit h;
      hits += shape->intersect(r, h);
    }
  });

  fmt::print("| measure | value |\n|---|---|\n");
  fmt::print("| mesh build, 1 thread (CPU time) | {:.2f} Mtris/s |\n", T / one / 1e6);
  fmt::print("| mesh build, {} threads (wall) | {:.2f} Mtris/s |\n", threads, T / all / 1e6);
  fmt::print("| bare BVH build, 1 thread (CPU time) | {:.2f} Mtris/s |\n", T / bare / 1e6);
  fmt::print("| SAH cost of the bare BVH | {:.3f} |\n", sahCost(bvh));
  fmt::print("| nodes of the bare BVH | {} |\n", bvh.nodes().size());
  fmt::print("| primary rays, 1 thread (CPU time) | {:.3f} Mrays/s ({} hits) |\n",
             rays.size() / trace / 1e6, hits);
}
