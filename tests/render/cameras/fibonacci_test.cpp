// Fibonacci sphere: pixel k looks along the documented formula's k-th direction; all unit;
// evenly spread (bounded nearest-neighbour spacing ratio); direction -> pixel is the
// nearest point, checked against brute force.
#include "camera_checks.h"

#include "render/camera_frame.h"
#include "render/direction_maps.h"
#include "render/fibonacci.h"

#include <random>
#include <vector>

using namespace lucent;
using namespace lucent::camtest;

namespace {

Vec3 randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 d;
  do d = Vec3(g(rng), g(rng), g(rng));
  while (glm::length(d) < 1e-6);
  return glm::normalize(d);
}

// docs/cameras.md's formula, written out again: y = 1 - (2k+1)/n along camera up,
// phi = 2 pi frac(k (sqrt 5 - 1)/2) from forward towards right.
Vec3 documentedDirection(const CameraFrame& f, long k, long n) {
  double y = 1.0 - (2.0 * k + 1.0) / n;
  double turns = k * (std::sqrt(5.0) - 1.0) / 2.0;
  double phi = 2.0 * kPi * (turns - std::floor(turns));
  double s = std::sqrt(1.0 - y * y);
  return s * std::cos(phi) * f.forward + s * std::sin(phi) * f.right + y * f.up;
}

}  // namespace

TEST_CASE("fibonacci pixel k (row-major) looks along the k-th documented direction",
          "[cameras][fibonacci]") {
  Camera cam = tiltedCamera(CameraType::Fibonacci);
  const CameraFrame f = makeCameraFrame(cam);
  const int w = 30, h = 20;
  auto p = makeProjection(cam, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      long k = long(y) * w + x;
      Vec3 expected = documentedDirection(f, k, w * h);
      for (const Vec2& at : {Vec2(0.5), Vec2(0.0), Vec2(0.99)}) {
        Ray r = rayAt(*p, Vec2(x, y) + at);
        CHECK(glm::length(r.d) == Approx(1.0).epsilon(1e-15));
        CHECK(angleBetween(r.d, expected) < 1e-12);
        CHECK(r.o == f.origin);
      }
    }
  // The first pixel looks nearly straight up, the last nearly straight down.
  CHECK(angleBetween(rayAt(*p, Vec2(0.5)).d, f.up) < 0.1);
  CHECK(angleBetween(rayAt(*p, Vec2(w - 0.5, h - 0.5)).d, -f.up) < 0.1);
}

TEST_CASE("fibonacci directions are unit and evenly spread", "[cameras][fibonacci]") {
  for (uint64_t n : {100u, 1200u, 4096u}) {
    std::vector<Vec3> pts(n);
    for (uint64_t k = 0; k < n; ++k) {
      pts[k] = fibonacciDirection(k, n);
      CHECK(glm::length(pts[k]) == Approx(1.0).epsilon(4e-16));
    }
    double lo = kInf, hi = 0.0;
    for (uint64_t i = 0; i < n; ++i) {
      double nearest = kInf;
      for (uint64_t j = 0; j < n; ++j)
        if (j != i) nearest = std::min(nearest, glm::length(pts[i] - pts[j]));
      lo = std::min(lo, nearest);
      hi = std::max(hi, nearest);
    }
    CAPTURE(n, lo, hi);
    // Measured 1.11 (n = 100) to 1.14 (n = 4096); independent random points give ratios
    // above 10 at these n. No two points closer than 3 / sqrt(n) (a hexagonal packing of n
    // points has nearest neighbours 3.81 / sqrt(n) apart).
    CHECK(hi / lo < 1.2);
    CHECK(lo * std::sqrt(double(n)) > 3.0);
  }
}

TEST_CASE("fibonacci direction -> pixel is the nearest point", "[cameras][fibonacci]") {
  Camera cam = tiltedCamera(CameraType::Fibonacci);
  const int w = 40, h = 30;
  const uint64_t n = w * h;
  auto p = makeProjection(cam, w, h);
  const auto& fib = as<FibonacciProjection>(p);
  CHECK(fib.pointCount() == n);
  // Each pixel's own direction maps back to that pixel.
  for (uint64_t k = 0; k < n; ++k) CHECK(fib.index(fib.direction(k)) == k);
  // Random directions: the same answer as a brute-force search, and the pixel holds it.
  std::mt19937_64 rng(31);
  for (int t = 0; t < 3000; ++t) {
    Vec3 d = randomDirection(rng);
    uint64_t best = 0;
    double bestDistance = kInf;
    for (uint64_t k = 0; k < n; ++k) {
      double dist = glm::length(fib.direction(k) - d);
      if (dist < bestDistance) {
        bestDistance = dist;
        best = k;
      }
    }
    REQUIRE(fib.index(d) == best);
    REQUIRE(fib.pixel(d) == glm::ivec2(int(best % w), int(best / w)));
  }
  // The poles and the directions along the frame's axes have valid pixels.
  const CameraFrame f = makeCameraFrame(cam);
  for (const Vec3& d : {f.up, -f.up, f.forward, -f.forward, f.right, -f.right})
    CHECK(fib.index(d) < n);
  CHECK(fib.index(f.up) == 0);
  CHECK(fib.index(-f.up) == n - 1);
}
