// The isosurface's hard cases (docs/accuracy.md): a sphere and a torus given as functions,
// random and tangent rays, against the exact shapes' long-double references (refSphere,
// refTorus); a thin spherical shell (a feature a few times the accuracy thick, and one
// thinner than it), against two concentric spheres in long double; a function steeper
// than its declared max-gradient, and the same with a true bound; secondary rays leaving
// the torus.
#include "accuracy_cases.h"

#include "primitives/isosurface.h"
#include "primitives/offset.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace lucent::accuracy {

namespace {

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Isosurfaces", name, boundRelT, boundAngle);
}

class FnField final : public ScalarField {
 public:
  explicit FnField(std::function<double(const Vec3&)> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override { return f_(p); }

 private:
  std::function<double(const Vec3&)> f_;
};

Isosurface make(std::function<double(const Vec3&)> f, IsosurfaceContainer c,
                double maxGradient = 1.1, double accuracy = 0.001) {
  Isosurface::Params p;
  p.field = std::make_shared<FnField>(std::move(f));
  p.container = c;
  p.maxGradient = maxGradient;
  p.accuracy = accuracy;
  return Isosurface(p);
}

IsosurfaceContainer cube(double h) {
  IsosurfaceContainer c;
  c.min = Vec3(-h);
  c.max = Vec3(h);
  return c;
}

// The shell r1 < |p| < r2 about the origin: the four roots of two spheres in long double
// (cancellation-free: the line's closest point to the centre first).
class RefShell final : public RefShape {
 public:
  RefShell(double r1, double r2) : r1_(r1), r2_(r2) {}
  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    const LD a = glm::dot(ray.d, ray.d);
    const LD tc = -glm::dot(ray.o, ray.d) / a;
    const LVec c = ray.at(tc);
    const LD q2 = glm::dot(c, c);
    auto half = [&](LD r) { return r * r > q2 ? std::sqrt((r * r - q2) / a) : LD(-1); };
    const LD h2 = half(r2_), h1 = half(r1_);
    if (h2 < 0) return;
    auto root = [&](LD t, bool outward) {
      LVec p = ray.at(t);
      LVec n = p / std::sqrt(glm::dot(p, p));
      out.push_back({t, outward ? n : -n});
    };
    root(tc - h2, true);
    if (h1 >= 0) {
      root(tc - h1, false);
      root(tc + h1, false);
    }
    root(tc + h2, true);
  }

 private:
  LD r1_, r2_;
};

Ray rayTo(Rng& rng, const Vec3& target, double from) {
  Vec3 o = target + from * randomUnit(rng);
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

}  // namespace

std::vector<CaseResult> isosurfaceCases(double effort) {
  // Bounds: the function's own rounding (a few ulps of values of size 1) moves a root by a
  // few ulps relative, and false position narrows to that: 1e-13 for t. Normals are
  // central differences with h = 1e-5 of the container: O(h²) truncation and O(ulp/h)
  // rounding, about 1e-10: bounded at 1e-8.
  const double kT = 1e-13, kN = 1e-8;
  const int n = rayCount(300, effort);
  std::vector<CaseResult> out;
  const Vec3 c(0.1, -0.2, 0.05);
  {
    Isosurface iso = make([c](const Vec3& p) { return glm::length(p - c) - 0.7; }, cube(1.0));
    auto ref = refSphere(c, 0.7);
    Rng rng(2101);
    CaseResult r =
        newCase("a sphere function in a box: random rays, and tangent at random points", kT, kN);
    for (int i = 0; i < n; ++i) {
      measureRay(r, iso, *ref, rayTo(rng, c + uniform(rng, 0.0, 0.7) * randomUnit(rng), 3.0), 2.0);
      // A line tangent at a random surface point, moved off by ±δ (1e-16 to 1e-1).
      Vec3 nrm = randomUnit(rng), w = randomPerpendicular(rng, nrm);
      Vec3 q = c + (0.7 + (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -16.0, -1.0)) * nrm;
      measureRay(r, iso, *ref, Ray(q - uniform(rng, 2.0, 4.0) * w, w * uniform(rng, 0.5, 2.0)),
                 2.0);
    }
    // A graze whose chord is shorter than the accuracy may be missed as a pair: a stated
    // limitation (the method's, and POV-Ray's), so the tests leave decisions to the table.
    r.decisionsAsserted = false;
    out.push_back(std::move(r));
  }
  IsosurfaceContainer ball;
  ball.kind = IsosurfaceContainer::Sphere;
  ball.radius = 1.2;
  auto torusF = [](const Vec3& p) { return std::hypot(std::hypot(p.x, p.z) - 0.8, p.y) - 0.3; };
  {
    Isosurface iso = make(torusF, ball);
    auto ref = refTorus(0.8, 0.3);
    Rng rng(2102);
    CaseResult r = newCase("a torus function in a sphere: random rays", kT, kN);
    for (int i = 0; i < n; ++i) {
      Vec3 target(uniform(rng, -1.1, 1.1), uniform(rng, -0.3, 0.3), uniform(rng, -1.1, 1.1));
      measureRay(r, iso, *ref, rayTo(rng, target, 3.5), 2.2);
    }
    r.decisionsAsserted = false;  // grazes under the accuracy, as above
    out.push_back(std::move(r));
  }
  for (double thickness : {0.005, 0.0005}) {
    // A spherical shell 0.7 < |p| < 0.7 + thickness: 5 times the default accuracy, and half
    // of it. Rays aimed inside the inner sphere cross the shell twice at a steep angle.
    const double r1 = 0.7, r2 = 0.7 + thickness, mid = 0.5 * (r1 + r2);
    Isosurface iso = make(
        [=](const Vec3& p) { return std::abs(glm::length(p) - mid) - 0.5 * thickness; }, cube(1.0));
    RefShell ref(r1, r2);
    Rng rng(2103);
    CaseResult r = newCase(thickness > 0.001
                               ? "a shell 5 times the accuracy thick (0.005)"
                               : "a shell half the accuracy thick (0.0005): crossings may be lost",
                           kT, kN);
    for (int i = 0; i < n; ++i)
      measureRay(r, iso, ref, rayTo(rng, uniform(rng, 0.0, 0.5) * randomUnit(rng), 3.0), 2.0);
    r.decisionsAsserted = thickness > 0.001;
    out.push_back(std::move(r));
  }
  for (double declared : {1.1, 5.5}) {
    // |grad f| = 5: with max-gradient 1.1 the search skips pieces that do hold crossings
    // (the render warns); with 5.5 it is exact again.
    Isosurface iso =
        make([c](const Vec3& p) { return 5.0 * (glm::length(p - c) - 0.7); }, cube(1.0), declared);
    auto ref = refSphere(c, 0.7);
    Rng rng(2104);
    CaseResult r =
        newCase(declared < 5.0 ? "gradient 5, declared max-gradient 1.1: crossings are skipped"
                               : "gradient 5, declared max-gradient 5.5",
                declared > 5.0 ? kT : 0.0, declared > 5.0 ? kN : 0.0);
    for (int i = 0; i < n; ++i)
      measureRay(r, iso, *ref, rayTo(rng, c + uniform(rng, 0.0, 0.6) * randomUnit(rng), 3.0), 2.0);
    r.decisionsAsserted = declared > 5.0;
    out.push_back(std::move(r));
  }
  {
    // Rays leaving the torus from offsetRayOrigin, out of the solid and into it: a crossing
    // the reference does not list is a re-hit. No bounds (a chord just ahead of the origin
    // has a t of any smallness).
    Isosurface iso = make(torusF, ball);
    auto ref = refTorus(0.8, 0.3);
    Rng rng(2105);
    CaseResult r = newCase("secondary rays leaving the torus function", 0.0, 0.0);
    for (int i = 0, tries = 0; i < n && tries < 20 * n; ++tries) {
      Vec3 target(uniform(rng, -1.1, 1.1), uniform(rng, -0.3, 0.3), uniform(rng, -1.1, 1.1));
      Ray primary = rayTo(rng, target, 3.5);
      Hit h;
      if (!iso.intersect(primary, h)) continue;
      ++i;
      SurfaceInfo si = iso.surface(primary, h);
      for (double side : {1.0, -1.0}) {
        double cs = uniform(rng, 0.01, 1.0);
        Vec3 w = side * cs * si.ng + std::sqrt(1.0 - cs * cs) * randomPerpendicular(rng, si.ng);
        Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w * uniform(rng, 0.5, 2.0));
        measureRay(r, iso, *ref, ray, 2.2, Perturb::DirectionOnly);
      }
    }
    r.decisionsAsserted = false;  // a secondary ray may graze the tube under the accuracy
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
