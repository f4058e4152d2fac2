// Shared by the benchmark programs: the meshes they trace (made here, never downloaded),
// the rays, the clocks and the tables they print.
#pragma once

#include "primitives/mesh_data.h"
#include "primitives/ray.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace lucent::bench {

// A sphere tessellated as a latitude-longitude grid (a vertex at each pole, rings-1 rings
// of `segments` vertices) and displaced along its normal by a sum of sines: a bumpy,
// closed, outward-oriented solid of 2·segments·(rings-1) triangles.
inline MeshData displacedSphere(int rings, int segments, double radius = 1.0) {
  MeshData m;
  auto point = [&](double th, double ph) {
    double bump = 1.0 + 0.05 * std::sin(20 * th) * std::cos(17 * ph) +
                  0.02 * std::sin(53 * th + 1.0) * std::sin(61 * ph);
    return radius * bump *
           Vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
  };
  m.positions.reserve(size_t(rings - 1) * segments + 2);
  m.positions.push_back(point(0.0, 0.0));
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m.positions.push_back(point(M_PI * i / rings, 2.0 * M_PI * j / segments));
  m.positions.push_back(point(M_PI, 0.0));
  const uint32_t north = 0, south = uint32_t(m.positions.size() - 1);
  auto id = [&](int i, int j) { return uint32_t(1 + (i - 1) * segments + (j % segments)); };
  m.triangles.reserve(size_t(2) * segments * (rings - 1));
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back({north, id(1, j + 1), id(1, j)});
    m.triangles.push_back({south, id(rings - 1, j), id(rings - 1, j + 1)});
  }
  // Counter-clockwise seen from outside: (+phi) x (+theta) points outward.
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      m.triangles.push_back({id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  m.closed = true;
  return m;
}

// The displaced sphere with about n triangles.
inline MeshData displacedSphereOf(size_t n) {
  int rings = std::max(2, int(std::lround(std::sqrt(double(n) / 4.0))) + 1);
  return displacedSphere(rings, 2 * (rings - 1));
}

// Camera rays through a w×h image, in 8×8 tiles as a renderer traces them (coherent).
// The camera looks from `eye` at `target` with a vertical field of view of fovDeg.
inline std::vector<Ray> cameraRays(int w, int h, Vec3 eye, Vec3 target, double fovDeg) {
  Vec3 fwd = glm::normalize(target - eye);
  Vec3 right = glm::normalize(glm::cross(fwd, Vec3(0, 1, 0)));
  Vec3 up = glm::cross(right, fwd);
  double half = std::tan(fovDeg * M_PI / 360.0);
  std::vector<Ray> rays;
  rays.reserve(size_t(w) * h);
  for (int ty = 0; ty < h; ty += 8)
    for (int tx = 0; tx < w; tx += 8)
      for (int y = ty; y < std::min(h, ty + 8); ++y)
        for (int x = tx; x < std::min(w, tx + 8); ++x) {
          double u = (2.0 * (x + 0.5) / w - 1.0) * half * w / h;
          double v = (1.0 - 2.0 * (y + 0.5) / h) * half;
          rays.emplace_back(eye, fwd + u * right + v * up);
        }
  return rays;
}

// Shadow rays from hit points towards a point light: the segment (eps, 1 - eps) of
// p + t·(light - p), as a renderer's shadow test asks.
inline Ray shadowRay(const Vec3& p, const Vec3& light) {
  return Ray(p, light - p, 1e-4, 1.0 - 1e-4);
}

using Clock = std::chrono::steady_clock;
inline double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The best of `reps` runs of f (seconds): the least disturbed by the rest of the machine.
template <class F>
double bestOf(int reps, F&& f) {
  double best = 1e300;
  for (int i = 0; i < reps; ++i) {
    auto t0 = Clock::now();
    f();
    best = std::min(best, secondsSince(t0));
  }
  return best;
}

// The best of `reps` runs of each of a and b, run in turn (a, b, a, b, ...): on this
// shared machine the speed drifts over seconds, and a slow spell then falls on both
// instead of on whichever was measured during it, so their ratio is fairer.
template <class A, class B>
std::pair<double, double> bestOfAlternating(int reps, A&& a, B&& b) {
  double bestA = 1e300, bestB = 1e300;
  for (int i = 0; i < reps; ++i) {
    bestA = std::min(bestA, bestOf(1, a));
    bestB = std::min(bestB, bestOf(1, b));
  }
  return {bestA, bestB};
}

// The CPU time of the calling thread (seconds): unlike the wall clock it does not count
// the time the thread waits for a core, so one-thread figures survive a busy machine
// (the caches it shares with other work still slow it down).
inline double threadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The best of `reps` runs of f on this thread's CPU clock (seconds).
template <class F>
double bestOfCpu(int reps, F&& f) {
  double best = 1e300;
  for (int i = 0; i < reps; ++i) {
    double t0 = threadCpuSeconds();
    f();
    best = std::min(best, threadCpuSeconds() - t0);
  }
  return best;
}

inline std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

inline std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double a = 0;
  in >> a;
  return fmt::format("{:.2f}", a);
}

inline unsigned hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Peak resident memory of this process so far (MB), from /proc/self/status.
inline double peakRssMB() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

// Writes rows of tab-separated values (for gnuplot) when a path is given.
class TsvFile {
 public:
  explicit TsvFile(const std::string& path) {
    if (!path.empty()) out_ = std::fopen(path.c_str(), "w");
  }
  ~TsvFile() {
    if (out_) std::fclose(out_);
  }
  template <class... Args>
  void row(fmt::format_string<Args...> f, Args&&... args) {
    if (out_) fmt::print(out_, "{}\n", fmt::format(f, std::forward<Args>(args)...));
  }

 private:
  std::FILE* out_ = nullptr;
};

}  // namespace lucent::bench
