// What the BVH among a CSG node's children saves: a box minus 1,000 small spheres, the
// same fixed set of camera rays traced through the node twice in one run, once searching
// the children through the node's BVH (what scenes use) and once testing every child
// (CsgSearch::EveryChild, which exists for this measurement only). Both must find the
// same hits; the program prints both times and their ratio (the aim is at least 10x).
//
//   csg_children [--spheres N] [--width W] [--height H] [--repeat R]
#include "bench_util.h"

#include "csg/csg_node.h"
#include "primitives/instance.h"
#include "scenegraph/shape_registry.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

using namespace lucent;

namespace {

// A unit box minus n spheres of radius 0.05 whose centres lie on the box's surface, so
// every sphere carves a dimple that the camera sees. Seeded: the same scene every run.
std::unique_ptr<CsgNode> boxMinusSpheres(int n, CsgSearch search) {
  std::vector<std::unique_ptr<Shape>> kids;
  kids.push_back(std::make_unique<Instance>(makeShape(BoxSpec{Vec3(-1), Vec3(1)}), Transform(), 0));
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> face(0, 5);
  for (int i = 0; i < n; ++i) {
    Vec3 c(u(rng), u(rng), u(rng));
    int f = face(rng);
    c[f / 2] = f % 2 ? 1.0 : -1.0;
    kids.push_back(std::make_unique<Instance>(makeShape(SphereSpec{c, 0.05}), Transform(), 1));
  }
  return std::make_unique<CsgNode>(CsgOp::Difference, std::move(kids), search);
}

// Primary rays of a pinhole camera at (2.2, 2.6, 3.4) looking at the origin.
std::vector<Ray> cameraRays(int w, int h) {
  Vec3 eye(2.2, 2.6, 3.4);
  Vec3 fwd = glm::normalize(-eye);
  Vec3 right = glm::normalize(glm::cross(fwd, Vec3(0, 1, 0)));
  Vec3 up = glm::cross(right, fwd);
  double half = std::tan(glm::radians(22.5));
  std::vector<Ray> rays;
  rays.reserve(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sx = (2.0 * (x + 0.5) / w - 1.0) * half;
      double sy = (1.0 - 2.0 * (y + 0.5) / h) * half * h / w;
      rays.emplace_back(eye, fwd + sx * right + sy * up);
    }
  return rays;
}

struct Pass {
  double seconds = 1e300;  // best of the repeats
  std::vector<Hit> hits;
};

// Timed on the thread's CPU clock (bench_util.h): time spent waiting for a core on the
// shared machine is not counted.
void traceOnce(const CsgNode& node, const std::vector<Ray>& rays, Pass& p) {
  p.hits.resize(rays.size());
  double t0 = bench::threadCpuSeconds();
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit h;
    node.intersect(rays[i], h);
    p.hits[i] = h;
  }
  p.seconds = std::min(p.seconds, bench::threadCpuSeconds() - t0);
}

}  // namespace

int main(int argc, char** argv) {
  int spheres = 1000, width = 320, height = 240, repeat = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    int v = std::atoi(argv[i + 1]);
    if (a == "--spheres") spheres = v;
    else if (a == "--width") width = v;
    else if (a == "--height") height = v;
    else if (a == "--repeat") repeat = v;
    else {
      fmt::print(stderr,
                 "usage: csg_children [--spheres N] [--width W] [--height H] [--repeat R]\n");
      return 1;
    }
  }
  auto tree = boxMinusSpheres(spheres, CsgSearch::Tree);
  auto every = boxMinusSpheres(spheres, CsgSearch::EveryChild);
  std::vector<Ray> rays = cameraRays(width, height);

  // Interleaved, so a change of the machine's load during the run hits both alike.
  Pass a, b;
  for (int r = 0; r < repeat; ++r) {
    traceOnce(*tree, rays, a);
    traceOnce(*every, rays, b);
  }

  // Same answer both ways, or the ratio means nothing. Shapes differ between the two
  // nodes, so compare by distance, by hit/miss and by which child was hit.
  size_t hits = 0, carved = 0, differ = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit &x = a.hits[i], &y = b.hits[i];
    if (x.found() != y.found() || (x.found() && (x.t != y.t || x.flip != y.flip))) ++differ;
    if (x.found()) ++hits;
    if (x.found() && x.flip) ++carved;
  }
  fmt::print(
      "box minus {} spheres, {} camera rays ({}x{}), one thread, CPU time, "
      "best of {} (interleaved)\n",
      spheres, rays.size(), width, height, repeat);
  fmt::print("hits {} (on a carved sphere surface {}), rays that differ {}\n", hits, carved,
             differ);
  fmt::print("{:<24} {:>10} {:>14}\n", "children searched by", "CPU s", "Mrays/s");
  fmt::print("{:<24} {:>10.4f} {:>14.3f}\n", "BVH", a.seconds, rays.size() / a.seconds * 1e-6);
  fmt::print("{:<24} {:>10.4f} {:>14.3f}\n", "every child", b.seconds,
             rays.size() / b.seconds * 1e-6);
  fmt::print("speed-up of the BVH: {:.1f}x\n", b.seconds / a.seconds);
  return differ == 0 ? 0 : 3;
}
