// The ovus's cases (docs/accuracy.md): POV-Ray's two forms (bottom radius larger, and top
// larger), random rays and rays tangent to the surface moved off by 1e-16 to 1e-1, and rays
// through the seams where the arc meets the spheres. Each against OvusReference (long
// double: POV-Ray's parser's parameters, each piece's convex gauge minimised by
// golden-section search and its roots bisected to the last bit), which shares nothing
// with Lucent's method (the spheres' quadratics, Newton on the lemon).
#include "accuracy_cases.h"

#include "../support/ovus_reference.h"
#include "primitives/ovus.h"

#include <cmath>

namespace lucent::accuracy {

namespace {

class RefOvus final : public RefShape {
 public:
  RefOvus(double rb, double rt) : ref_(rb, rt) {}

  void lineRoots(const LRay& ray, std::vector<LRoot>& out) const override {
    LD tIn = 0, tOut = 0;
    int pIn = 0, pOut = 0;
    if (!ref_.span(ray.o, ray.d, tIn, tOut, pIn, pOut)) return;
    out.push_back({tIn, ref_.normal(pIn, ray.at(tIn)), true});
    out.push_back({tOut, ref_.normal(pOut, ray.at(tOut)), true});
  }

 private:
  test::OvusReference ref_;
};

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Ovuses", name, boundRelT, boundAngle);
}

}  // namespace

std::vector<CaseResult> ovusCases(double effort) {
  const int n = rayCount(200, effort);
  // Bounds: measured maxima with a margin (docs/accuracy.md).
  const double kT = 1e-14, kN = 1e-13;
  std::vector<CaseResult> out;
  const struct {
    double rb, rt;
    const char* name;
  } kinds[] = {{1.0, 0.6, "bottom 1, top 0.6"}, {0.8, 1.3, "bottom 0.8, top 1.3"}};
  uint64_t seed = 4700;
  for (const auto& kind : kinds) {
    const Ovus shape(kind.rb, kind.rt);
    const RefOvus ref(kind.rb, kind.rt);
    const AABB b = shape.bounds();
    const double size = glm::length(b.extent());
    {
      Rng rng(seed++);
      CaseResult r = newCase(std::string(kind.name) + ": random rays", kT, kN);
      for (int i = 0; i < n; ++i) {
        const Vec3 target(uniform(rng, b.lo.x, b.hi.x), uniform(rng, b.lo.y, b.hi.y),
                          uniform(rng, b.lo.z, b.hi.z));
        const Vec3 o = b.center() + 2.0 * size * randomUnit(rng);
        measureRay(r, shape, ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), size);
      }
      out.push_back(std::move(r));
    }
    {
      // At a surface point Lucent finds, along a direction across its normal, moved off
      // along the normal (the reference judges the ray, whatever built it).
      Rng rng(seed++);
      CaseResult r = newCase(
          std::string(kind.name) + ": tangent to the surface, 1e-16 to 1e-1 inside or outside", kT,
          kN);
      for (int i = 0; i < n;) {
        const Vec3 target(uniform(rng, b.lo.x, b.hi.x), uniform(rng, b.lo.y, b.hi.y),
                          uniform(rng, b.lo.z, b.hi.z));
        const Vec3 o = b.center() + 2.0 * size * randomUnit(rng);
        const Ray probe(o, target - o);
        Hit h;
        if (!shape.intersect(probe, h)) continue;
        const SurfaceInfo si = shape.surface(probe, h);
        const Vec3 w = randomPerpendicular(rng, si.ng);
        const double side = rng() % 2 ? 1.0 : -1.0;
        const Vec3 q = si.p + side * logUniform(rng, -16.0, -1.0) * si.ng;
        measureRay(r, shape, ref, Ray(q - uniform(rng, 2.0, 4.0) * size * w, w), size);
        ++i;
      }
      out.push_back(std::move(r));
    }
    {
      // Through the seams' circles (where a sphere and the arc meet), from any side.
      Rng rng(seed++);
      CaseResult r = newCase(std::string(kind.name) + ": through the seams", kT, kN);
      const Ovus::Geometry& g = shape.geometry();
      for (int i = 0; i < n; ++i) {
        const bool top = rng() % 2;
        const double y = top ? g.topSeam : g.bottomSeam;
        const double cy = top ? kind.rb : 0.0, rad = top ? kind.rt : kind.rb;
        const double rho = std::sqrt(std::max(0.0, rad * rad - (y - cy) * (y - cy)));
        const double phi = uniform(rng, 0.0, 2.0 * kPi);
        const Vec3 seam(rho * std::cos(phi), y, rho * std::sin(phi));
        const Vec3 o = seam + 2.0 * size * randomUnit(rng);
        measureRay(r, shape, ref, Ray(o, seam - o), size);
      }
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace lucent::accuracy
