// Items for testing the BVH against brute force: spheres, boxes and triangles intersected
// here in the test (independent of primitives/), and random rays with awkward directions.
#pragma once

#include "primitives/aabb.h"
#include "primitives/ray.h"

#include <random>
#include <vector>

namespace lucent::testing {

struct TestSphere {
  Vec3 c;
  double r;
  AABB bounds() const { return {c - Vec3(r), c + Vec3(r)}; }
  // Nearest root in (tmin, tmax), or kInf. The roots are taken around the point of the
  // line closest to the centre (Haines et al., "Precision Improvements for Ray/Sphere
  // Intersection", Ray Tracing Gems 2019), so small spheres seen from far stay exact.
  double hit(const Ray& ray) const {
    Vec3 oc = ray.o - c;
    double a = glm::dot(ray.d, ray.d);
    double tc = -glm::dot(oc, ray.d) / a;
    Vec3 l = oc + tc * ray.d;
    double disc = r * r - glm::dot(l, l);
    if (disc < 0) return kInf;
    double h = std::sqrt(disc / a);
    double t0 = tc - h, t1 = tc + h;
    if (t0 > ray.tmin && t0 < ray.tmax) return t0;
    if (t1 > ray.tmin && t1 < ray.tmax) return t1;
    return kInf;
  }
};

struct TestTriangle {
  Vec3 a, b, c;
  AABB bounds() const {
    AABB box;
    box.expand(a);
    box.expand(b);
    box.expand(c);
    return box;
  }
  // Möller–Trumbore in double; edges count as inside.
  double hit(const Ray& ray) const {
    Vec3 e1 = b - a, e2 = c - a, p = glm::cross(ray.d, e2);
    double det = glm::dot(e1, p);
    if (det == 0.0) return kInf;
    Vec3 s = ray.o - a;
    double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return kInf;
    Vec3 q = glm::cross(s, e1);
    double v = glm::dot(ray.d, q) / det;
    if (v < 0.0 || u + v > 1.0) return kInf;
    double t = glm::dot(e2, q) / det;
    return t > ray.tmin && t < ray.tmax ? t : kInf;
  }
};

// A closed box as an item: the entry distance, or the exit one from inside.
struct TestBox {
  AABB box;
  AABB bounds() const { return box; }
  double hit(const Ray& ray) const {
    Interval i = box.slab(Ray(ray.o, ray.d, -kInf, kInf), 1.0 / ray.d);
    if (i.empty()) return kInf;
    if (i.lo > ray.tmin && i.lo < ray.tmax) return i.lo;
    if (i.hi > ray.tmin && i.hi < ray.tmax) return i.hi;
    return kInf;
  }
};

inline Vec3 randomVec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return Vec3(u(rng), u(rng), u(rng));
}

// Random rays through a cube of half-size `extent`: non-unit directions, and about one in
// four with one or two components exactly +0 or -0 (the slab test's special cases).
inline std::vector<Ray> randomRays(std::mt19937_64& rng, size_t n, double extent) {
  std::vector<Ray> rays;
  rays.reserve(n);
  std::uniform_int_distribution<int> pick(0, 15);
  for (size_t i = 0; i < n; ++i) {
    Vec3 o = randomVec(rng, -1.2 * extent, 1.2 * extent);
    Vec3 target = randomVec(rng, -0.8 * extent, 0.8 * extent);
    Vec3 d = (target - o) * std::uniform_real_distribution<double>(0.1, 10.0)(rng);
    int k = pick(rng);
    if (k < 4) {
      d[k % 3] = (k & 1) ? -0.0 : 0.0;
      if (k == 3) d[(k + 1) % 3] = -0.0;
    }
    if (d == Vec3(0.0)) d = Vec3(1.0, 0.0, 0.0);
    rays.emplace_back(o, d);
  }
  return rays;
}

}  // namespace lucent::testing
