// Lucent against Embree 3 on one mesh of about a million triangles: the same rays, on the
// same machine, in the same run. Primary (camera) rays and shadow rays, one thread and all
// threads; BVH build speed and memory per triangle for both.
//
//   mesh_embree [--triangles N] [--size W] [--tsv FILE] [--only primary|shadow]
//               [--passes P]
//
// --only measures one kind of ray on one thread and nothing else (no build rates, no
// memory, no agreement check), P passes of Lucent's and Embree's in turn (default 5), on
// the thread's CPU clock: for profiling one traversal with perf and comparing builds.
//
// Lucent traces through its World (an instance of the mesh shape: what the renderer
// calls); Embree through rtcIntersect1/rtcOccluded1, its single-ray interface. Both are
// given the same double-precision rays (Embree's rounded to float). Each figure is the
// best of several passes, Lucent's and Embree's taken in turn.
#include "bench_util.h"

#include "primitives/triangle_mesh.h"
#include "primitives/watertight.h"
#include "scenegraph/world.h"

#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstring>

using namespace lucent;
using namespace lucent::bench;

namespace {

struct Options {
  size_t triangles = 1000000;
  int size = 1024;
  std::string tsv;
  std::string only;  // "", "primary" or "shadow"
  int passes = 5;
};

Options parseArgs(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--triangles") o.triangles = std::stoul(argv[i + 1]);
    else if (a == "--size") o.size = std::stoi(argv[i + 1]);
    else if (a == "--tsv") o.tsv = argv[i + 1];
    else if (a == "--only") o.only = argv[i + 1];
    else if (a == "--passes") o.passes = std::stoi(argv[i + 1]);
    else throw std::invalid_argument("unknown option " + a);
  }
  if (!o.only.empty() && o.only != "primary" && o.only != "shadow")
    throw std::invalid_argument("--only takes primary or shadow");
  return o;
}

// Embree's memory monitor: bytes allocated by the device (its BVH and triangle copies).
std::atomic<long long> embreeBytes{0};
bool monitor(void*, ssize_t bytes, bool) {
  embreeBytes += bytes;
  return true;
}

struct EmbreeScene {
  RTCDevice device;
  RTCScene scene;

  EmbreeScene(const MeshData& m, unsigned threads) {
    std::string config = fmt::format("threads={}", threads);
    device = rtcNewDevice(config.c_str());
    rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
    scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.positions.size()));
    for (size_t i = 0; i < m.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = float(m.positions[i][k]);
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.triangles.size()));
    std::memcpy(idx, m.triangles.data(), m.triangles.size() * 3 * sizeof(unsigned));
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  void commit() { rtcCommitScene(scene); }
};

RTCRayHit embreeRay(const Ray& r) {
  RTCRayHit rh;
  rh.ray.org_x = float(r.o.x);
  rh.ray.org_y = float(r.o.y);
  rh.ray.org_z = float(r.o.z);
  rh.ray.dir_x = float(r.d.x);
  rh.ray.dir_y = float(r.d.y);
  rh.ray.dir_z = float(r.d.z);
  rh.ray.tnear = float(r.tmin);
  rh.ray.tfar = std::isinf(r.tmax) ? INFINITY : float(r.tmax);
  rh.ray.mask = 0xffffffffu;
  rh.ray.flags = 0;
  rh.ray.time = 0.0f;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// Runs body(i) for every ray: on this thread, or spread over TBB's threads in chunks.
template <class Body>
void forRays(size_t n, bool parallel, Body&& body) {
  if (!parallel) {
    for (size_t i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const auto& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
}

// The closest hit by testing every triangle (the check of Lucent's answer where the two
// renderers disagree).
double bruteForce(const MeshData& m, const Ray& ray) {
  ShearedRay sr(ray);
  double best = kInf;
  for (const auto& tri : m.triangles) {
    const Vec3 &p0 = m.positions[tri[0]], &p1 = m.positions[tri[1]], &p2 = m.positions[tri[2]];
    TriangleIntersection ti;
    if (!isDegenerateTriangle(p0, p1, p2) && intersectTriangle(sr, p0, p1, p2, ti) &&
        ray.tmin < ti.t && ti.t < best)
      best = ti.t;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt = parseArgs(argc, argv);
  const unsigned threads = hardwareThreads();
  auto mesh = std::make_shared<MeshData>(displacedSphereOf(opt.triangles));
  const size_t T = mesh->triangles.size();
  fmt::print("# mesh_embree: {} triangles, {} vertices, {}x{} rays; {} ({} threads), load {}\n", T,
             mesh->positions.size(), opt.size, opt.size, cpuModel(), threads, loadAverage());

  // Build: Lucent's mesh shape (its BVH and bookkeeping) and Embree's scene commit (its
  // vertex and index buffers are filled before), in turn (bestOfAlternating).
  std::shared_ptr<TriangleMesh> shape;
  auto buildRates = [&](unsigned n) {
    auto lucentBuild = [&] {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, n);
      shape.reset();  // freeing the last one is not part of the build
      auto t0 = Clock::now();
      shape = std::make_shared<TriangleMesh>(mesh, false);
      return secondsSince(t0);
    };
    auto embreeBuild = [&] {
      EmbreeScene e(*mesh, n);
      auto t0 = Clock::now();
      e.commit();
      return secondsSince(t0);
    };
    double l = 1e300, e = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
      l = std::min(l, lucentBuild());
      e = std::min(e, embreeBuild());
    }
    return std::make_pair(l, e);
  };
  const bool only = !opt.only.empty();
  if (only) shape = std::make_shared<TriangleMesh>(mesh, false);
  auto [lucentBuild1, embreeBuild1] = only ? std::make_pair(0.0, 0.0) : buildRates(1);
  auto [lucentBuildN, embreeBuildN] = only ? std::make_pair(0.0, 0.0) : buildRates(threads);

  // Memory per triangle: the mesh data Lucent keeps (double positions and indices) plus
  // its BVH; Embree's device allocations (its BVH and the triangle data it copies).
  double meshBytes = double(mesh->positions.capacity() * sizeof(Vec3) +
                            mesh->triangles.capacity() * sizeof(mesh->triangles[0]));
  double lucentBvhBytes = double(shape->bvh().memoryBytes());
  EmbreeScene embree(*mesh, threads);
  embreeBytes = 0;
  embree.commit();
  double embreeBvhBytes = double(embreeBytes.load());
  double embreeBufferBytes = double(mesh->positions.size() * 12 + T * 12);

  // The world the renderer would trace: one instance of the mesh.
  Scene scene;
  auto node = std::make_unique<Node>();
  node->kind = NodeKind::Shape;
  node->element = "mesh";
  node->shape = MeshSpec{"", SmoothMode::False, mesh};
  scene.root->children.push_back(std::move(node));
  World world(scene, [&](const ShapeSpec&) { return shape; });

  const Vec3 eye(0.6, 0.9, 3.2), light(4.0, 6.0, 5.0);
  std::vector<Ray> primary = cameraRays(opt.size, opt.size, eye, Vec3(0.0), 40.0);
  const size_t R = primary.size();

  // Lucent's primary hits give the shadow rays both renderers trace.
  std::vector<double> tLucent(R, kInf);
  forRays(R, true, [&](size_t i) {
    Hit h;
    if (world.intersect(primary[i], h)) tLucent[i] = h.t;
  });
  std::vector<Ray> shadow;
  for (size_t i = 0; i < R; ++i)
    if (tLucent[i] < kInf) shadow.push_back(shadowRay(primary[i].at(tLucent[i]), light));

  // Agreement: hit or miss, and the distance where both hit. Where they disagree (by more
  // than float rounding), Lucent's answer is checked against every triangle.
  size_t disagree = 0, farApart = 0, checked = 0, lucentRight = 0;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  for (size_t i = 0; i < (only ? 0 : R); ++i) {
    RTCRayHit rh = embreeRay(primary[i]);
    rtcIntersect1(embree.scene, &ctx, &rh);
    bool eh = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    bool differ = eh != (tLucent[i] < kInf);
    if (differ) ++disagree;
    if (!differ && eh && std::abs(rh.ray.tfar - tLucent[i]) > 1e-4 * tLucent[i]) {
      ++farApart;
      differ = true;
    }
    if (differ && checked < 20) {
      ++checked;
      lucentRight += bruteForce(*mesh, primary[i]) == tLucent[i];
    }
  }
  struct Rate {
    double lucent, embree;
  };
  // Each figure is the best of five passes over the rays, Lucent's and Embree's passes
  // in turn (bestOfAlternating).
  auto measure = [&](bool parallel) {
    Rate pri{}, sha{};
    std::atomic<size_t> sink{0};
    const int passes = opt.passes;
    const bool doPrimary = opt.only != "shadow", doShadow = opt.only != "primary";
    // With --only (one thread), on this thread's CPU clock: waits for a core on a busy
    // machine are not counted.
    auto bestOfAlternating = [&](int reps, auto&& a, auto&& b) {
      if (!only) return bench::bestOfAlternating(reps, a, b);
      double bestA = 1e300, bestB = 1e300;
      for (int i = 0; i < reps; ++i) {
        bestA = std::min(bestA, bestOfCpu(1, a));
        bestB = std::min(bestB, bestOfCpu(1, b));
      }
      return std::make_pair(bestA, bestB);
    };
    auto [lp, ep] = bestOfAlternating(
        doPrimary ? passes : 0,
        [&] {
          forRays(R, parallel, [&](size_t i) {
            Hit h;
            if (world.intersect(primary[i], h)) sink.fetch_add(1, std::memory_order_relaxed);
          });
        },
        [&] {
          forRays(R, parallel, [&](size_t i) {
            RTCIntersectContext c;
            rtcInitIntersectContext(&c);
            RTCRayHit rh = embreeRay(primary[i]);
            rtcIntersect1(embree.scene, &c, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
              sink.fetch_add(1, std::memory_order_relaxed);
          });
        });
    auto [ls, es] = bestOfAlternating(
        doShadow ? passes : 0,
        [&] {
          forRays(shadow.size(), parallel, [&](size_t i) {
            if (world.occluded(shadow[i])) sink.fetch_add(1, std::memory_order_relaxed);
          });
        },
        [&] {
          forRays(shadow.size(), parallel, [&](size_t i) {
            RTCIntersectContext c;
            rtcInitIntersectContext(&c);
            RTCRay r = embreeRay(shadow[i]).ray;
            rtcOccluded1(embree.scene, &c, &r);
            if (r.tfar < 0.0f) sink.fetch_add(1, std::memory_order_relaxed);
          });
        });
    pri = {R / lp, R / ep};
    sha = {shadow.size() / ls, shadow.size() / es};
    return std::make_pair(pri, sha);
  };
  std::pair<Rate, Rate> one, all;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = measure(false);
  }
  if (only) {
    fmt::print("\n| rays | threads | Lucent Mrays/s | Embree Mrays/s | Lucent/Embree |\n");
    fmt::print("|---|---|---|---|---|\n");
    const Rate& r = opt.only == "primary" ? one.first : one.second;
    fmt::print("| {} | 1 | {:.2f} | {:.2f} | {:.2f} |\n", opt.only, r.lucent / 1e6, r.embree / 1e6,
               r.lucent / r.embree);
    return 0;
  }
  all = measure(true);

  TsvFile tsv(opt.tsv);
  auto line = [&](const char* what, const char* thr, double l, double e) {
    fmt::print("| {} | {} | {:.2f} | {:.2f} | {:.2f} |\n", what, thr, l / 1e6, e / 1e6, l / e);
    tsv.row("{}\t{}\t{:.4f}\t{:.4f}\t{:.4f}", what, thr, l / 1e6, e / 1e6, l / e);
  };
  fmt::print("\n| rays | threads | Lucent Mrays/s | Embree Mrays/s | Lucent/Embree |\n");
  fmt::print("|---|---|---|---|---|\n");
  line("primary", "1", one.first.lucent, one.first.embree);
  line("shadow", "1", one.second.lucent, one.second.embree);
  std::string n = std::to_string(threads);
  line("primary", n.c_str(), all.first.lucent, all.first.embree);
  line("shadow", n.c_str(), all.second.lucent, all.second.embree);

  fmt::print("\n| build | threads | Lucent Mtris/s | Embree Mtris/s |\n|---|---|---|---|\n");
  fmt::print("| BVH | 1 | {:.2f} | {:.2f} |\n", T / lucentBuild1 / 1e6, T / embreeBuild1 / 1e6);
  fmt::print("| BVH | {} | {:.2f} | {:.2f} |\n", threads, T / lucentBuildN / 1e6,
             T / embreeBuildN / 1e6);
  tsv.row("build\t1\t{:.4f}\t{:.4f}\t{:.4f}", T / lucentBuild1 / 1e6, T / embreeBuild1 / 1e6,
          embreeBuild1 / lucentBuild1);
  tsv.row("build\t{}\t{:.4f}\t{:.4f}\t{:.4f}", threads, T / lucentBuildN / 1e6,
          T / embreeBuildN / 1e6, embreeBuildN / lucentBuildN);

  fmt::print("\n| memory per triangle | Lucent | Embree |\n|---|---|---|\n");
  fmt::print("| vertices and indices | {:.1f} B | {:.1f} B (its float copy) |\n", meshBytes / T,
             embreeBufferBytes / T);
  fmt::print("| BVH | {:.1f} B | {:.1f} B |\n", lucentBvhBytes / T, embreeBvhBytes / T);
  fmt::print("| total | {:.1f} B | {:.1f} B |\n", (meshBytes + lucentBvhBytes) / T,
             (embreeBufferBytes + embreeBvhBytes) / T);
  tsv.row("memory\tall\t{:.2f}\t{:.2f}\t{:.2f}", (meshBytes + lucentBvhBytes) / T,
          (embreeBufferBytes + embreeBvhBytes) / T, lucentBvhBytes / T);

  fmt::print(
      "\nagreement: of {} primary rays, {} hit in one renderer and miss in the other, "
      "{} hit both more than 1e-4 apart (relative); Lucent's answer equals the "
      "brute-force closest hit over all triangles for {} of the {} of these checked\n",
      R, disagree, farApart, lucentRight, checked);
  tsv.row("agreement\t-\t{}\t{}\t{}", disagree, farApart, R);
  return 0;
}
