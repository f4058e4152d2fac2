// Hard cases for the quadric shapes: a unit sphere 1e5 from the camera, and scenes scaled
// by 1e-4 and 1e4, directly and through an Instance. Each reported t is compared with the
// root of the shape's implicit function polished by Newton in long double (64-bit
// significand) from it. Set LUCENT_PRINT_ACCURACY=1 to print the worst relative errors
// (docs/accuracy.md quotes them).
#include "primitives/box.h"
#include "primitives/cone.h"
#include "primitives/cylinder.h"
#include "primitives/instance.h"
#include "primitives/sphere.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>

using namespace lucent;

namespace {

using LD = long double;
struct LVec {
  LD x, y, z;
};
LVec at(const Ray& r, LD t) { return {r.o.x + t * r.d.x, r.o.y + t * r.d.y, r.o.z + t * r.d.z}; }
LVec sub(const LVec& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
LD dot(const LVec& a, const LVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
LVec lv(const Vec3& v) { return {v.x, v.y, v.z}; }

// Newton on f along the ray in long double, from t (a root of f within rounding).
LD polish(const std::function<LD(LD)>& f, LD t) {
  for (int i = 0; i < 8; ++i) {
    LD h = 1e-7L * (std::abs(t) + 1e-30L);
    LD df = (f(t + h) - f(t - h)) / (2 * h);
    if (df == 0) break;
    LD next = t - f(t) / df;
    if (next == t) break;
    t = next;
  }
  return t;
}

// The worst relative error over hits at least 6° from grazing (|cos| >= 0.1 between the
// ray and the normal), and separately over all hits: near a tangent the root itself is
// ill-conditioned (a relative change ε of the ray's data moves it by ~ε/cos²), whatever
// the method.
struct Worst {
  double rel = 0.0, relAll = 0.0;
  int samples = 0;
  void add(double t, LD ref, double cosine = 1.0) {
    double e = double(std::abs((t - ref) / ref));
    relAll = std::max(relAll, e);
    if (std::abs(cosine) >= 0.1) rel = std::max(rel, e);
    ++samples;
  }
  void add(const Shape& s, const Ray& ray, const Hit& h, LD ref) {
    Vec3 n = s.surface(ray, h).ng;
    add(h.t, ref, glm::dot(n, glm::normalize(ray.d)));
  }
};

void report(const char* what, const Worst& w) {
  if (std::getenv("LUCENT_PRINT_ACCURACY"))
    std::printf("%s: max relative t error %.3g (%.3g with grazing hits) over %d hits\n", what,
                w.rel, w.relAll, w.samples);
}

// Random rays from a sphere of radius `dist` around c towards points within `size` of c.
Ray aimedRay(std::mt19937_64& rng, const Vec3& c, double size, double dist) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3 dir = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
  Vec3 target = c + size * Vec3(u(rng), u(rng), u(rng));
  return Ray(target - dist * dir, dir * (1.0 + 0.5 * std::abs(u(rng))));
}

}  // namespace

TEST_CASE("accuracy: a unit sphere 1e5 from the camera", "[numeric][sphere]") {
  const Vec3 c(1e5, 3e4, -2e4);
  Sphere s(c, 1.0);
  Instance moved(std::make_shared<Sphere>(Vec3(0.0), 1.0),
                 *Transform::fromMatrix(glm::translate(Mat4(1.0), c)), 0);
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Worst direct, instanced;
  for (int i = 0; i < 20000; ++i) {
    Ray ray(Vec3(0.0), c + 0.9 * Vec3(u(rng), u(rng), u(rng)) / std::sqrt(3.0));
    auto f = [&](LD t) {
      LVec p = sub(at(ray, t), c);
      return dot(p, p) - 1;
    };
    Hit h;
    REQUIRE(s.intersect(ray, h));
    direct.add(s, ray, h, polish(f, h.t));
    REQUIRE(moved.intersect(ray, h));
    instanced.add(moved, ray, h, polish(f, h.t));
  }
  report("sphere r=1 at 1e5, object space", direct);
  report("sphere r=1 at 1e5, through a translation", instanced);
  // The hit point's coordinates are ~1e5: their rounding alone is 1e5·ε absolute, ~ε of t.
  CHECK(direct.relAll < 2e-15);
  // The instance first subtracts 1e5 from the origin in double: also a few ε.
  CHECK(instanced.relAll < 4e-15);
}

TEST_CASE("accuracy: sphere, cylinder, cone and box scaled by 1e-4 and 1e4",
          "[numeric][sphere][cylinder][cone][box]") {
  std::mt19937_64 rng(23);
  for (double k : {1e-4, 1e4}) {
    const Vec3 c = k * Vec3(0.3, -0.2, 0.1);
    Sphere sphere(c, k);
    const Vec3 base = c - k * Vec3(0.2, 0.8, 0.1), cap = c + k * Vec3(0.1, 0.9, 0.3);
    Cylinder cyl(base, cap, 0.5 * k, false);
    Cone cone(base, 0.7 * k, cap, 0.1 * k, false);
    Box box(c - k * Vec3(1, 0.5, 0.25), c + k * Vec3(0.5, 1, 0.75));
    Worst ws, wc, wk, wb, wi;
    // The axis frame of the cylinder and cone, in long double, for the references.
    LVec ax = sub(lv(cap), base);
    LD H = std::sqrt(dot(ax, ax));
    ax = {ax.x / H, ax.y / H, ax.z / H};
    auto axial = [&](const LVec& p) {  // (squared distance from the axis, height)
      LVec q = sub(p, base);
      LD s = dot(q, ax);
      return std::make_pair(dot(q, q) - s * s, s);
    };
    // Through an instance too: the unit sphere at the origin scaled and moved there.
    Instance inst(std::make_shared<Sphere>(Vec3(0.0), 1.0),
                  *Transform::fromMatrix(glm::translate(Mat4(1.0), c) *
                                         glm::scale(Mat4(1.0), Vec3(k))),
                  0);
    for (int i = 0; i < 5000; ++i) {
      Ray ray = aimedRay(rng, c, 0.8 * k, 4.0 * k);
      Hit h;
      if (sphere.intersect(ray, h)) {
        auto f = [&](LD t) {
          LVec p = sub(at(ray, t), c);
          return dot(p, p) - (LD)k * k;
        };
        ws.add(sphere, ray, h, polish(f, h.t));
        REQUIRE(inst.intersect(ray, h));
        wi.add(inst, ray, h, polish(f, h.t));
      }
      if (cyl.intersect(ray, h)) {
        auto f = [&](LD t) {
          auto [d2, s] = axial(at(ray, t));
          return h.part == 0 ? d2 - (LD)0.25 * k * k : h.part == 1 ? s : s - H;
        };
        wc.add(cyl, ray, h, polish(f, h.t));
      }
      if (cone.intersect(ray, h)) {
        auto f = [&](LD t) {
          auto [d2, s] = axial(at(ray, t));
          LD r = 0.7L * k + (0.1L * k - 0.7L * k) * s / H;
          return h.part == 0 ? d2 - r * r : h.part == 1 ? s : s - H;
        };
        wk.add(cone, ray, h, polish(f, h.t));
      }
      if (box.intersect(ray, h)) {
        int axis = int(h.part / 2);
        double plane = (h.part & 1) ? box.bounds().hi[axis] : box.bounds().lo[axis];
        LD ref = ((LD)plane - ray.o[axis]) / (LD)ray.d[axis];
        wb.add(box, ray, h, ref);
      }
    }
    const char* tag = k < 1 ? "1e-4" : "1e4";
    report((std::string("sphere scaled ") + tag).c_str(), ws);
    report((std::string("sphere scaled ") + tag + " through an instance").c_str(), wi);
    report((std::string("cylinder scaled ") + tag).c_str(), wc);
    report((std::string("cone scaled ") + tag).c_str(), wk);
    report((std::string("box scaled ") + tag).c_str(), wb);
    CHECK(ws.samples > 1000);
    CHECK(wc.samples > 1000);
    CHECK(wk.samples > 1000);
    CHECK(wb.samples > 1000);
    CHECK(ws.rel < 4e-15);
    CHECK(wi.rel < 4e-15);
    CHECK(wc.rel < 4e-15);
    CHECK(wk.rel < 4e-15);
    CHECK(wb.rel < 4e-15);
    // Grazing hits included: bounded by the conditioning, not by the method.
    for (const Worst* w : {&ws, &wi, &wc, &wk, &wb}) CHECK(w->relAll < 1e-11);
  }
}
