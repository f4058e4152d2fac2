// The blob's hard cases (docs/accuracy.md): a lone sphere component and a capsule, random
// and tangent rays; components whose strength only just exceeds the threshold (a tiny
// solid at their centre); two spheres whose fields just merge (the threshold within 1e-6
// to 1e-12 of the field at the saddle between them) with rays through the neck; a negative
// component carving a hole, grazed at its rim; rays leaving the surface. Each against
// refBlob (long double: the field sampled on the pieces between the components' radii,
// extrema refined, sign changes bisected).
#include "accuracy_cases.h"

#include "primitives/blob.h"
#include "primitives/offset.h"

#include <fmt/format.h>

namespace lucent::accuracy {

namespace {

using C = BlobComponent;

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Blobs", name, boundRelT, boundAngle);
}

// The surface point on the segment from an inside point to an outside one (bisection of
// the double field; only to build rays, never to judge them) and its outward normal.
struct SurfacePoint {
  Vec3 p, n;
  bool ok = false;
};
SurfacePoint surfaceBetween(const Blob& b, Vec3 in, Vec3 out) {
  if (!b.inside(in) || b.inside(out)) return {};
  for (int i = 0; i < 200; ++i) {
    Vec3 m = 0.5 * (in + out);
    if (m == in || m == out) break;
    (b.inside(m) ? in : out) = m;
  }
  Vec3 g = b.gradient(in);
  if (!(glm::dot(g, g) > 0.0)) return {};
  return {in, -glm::normalize(g), true};
}

// A line tangent at sp, moved off along the normal by ±δ, δ log-uniform in [1e-16, 1e-1].
Ray grazingRay(Rng& rng, const SurfacePoint& sp) {
  Vec3 w = randomPerpendicular(rng, sp.n);
  double side = rng() % 2 ? 1.0 : -1.0;
  Vec3 q = sp.p + side * logUniform(rng, -16.0, -1.0) * sp.n;
  return Ray(q - uniform(rng, 2.0, 5.0) * w, w * uniform(rng, 0.5, 2.0));
}

Ray randomRayTo(Rng& rng, const AABB& box) {
  Vec3 c = box.center();
  double r = 0.5 * glm::length(box.extent());
  Vec3 o = c + 3.0 * r * randomUnit(rng);
  Vec3 target(uniform(rng, box.lo.x, box.hi.x), uniform(rng, box.lo.y, box.hi.y),
              uniform(rng, box.lo.z, box.hi.z));
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

struct Setting {
  std::string name;
  double threshold;
  std::vector<C> components;
  Vec3 core;  // a point inside, to find surface points from
};

}  // namespace

std::vector<CaseResult> blobCases(double effort) {
  // Bounds: as the other shapes' at unit scale, 1e-14 for t and 1e-12 for the normal.
  const double kT = 1e-14, kN = 1e-12;
  const int n = rayCount(300, effort);
  std::vector<CaseResult> out;

  const std::vector<Setting> settings = {
      {"one sphere component",
       1.0,
       {{C::Sphere, Vec3(0.2, -0.1, 0.3), Vec3(0.0), 1.0, 2.0}},
       Vec3(0.2, -0.1, 0.3)},
      {"a capsule (one cylinder component)",
       0.5,
       {{C::Cylinder, Vec3(-1, 0, 0), Vec3(1, 0.5, 0.2), 0.6, 1.5}},
       Vec3(0.0, 0.25, 0.1)},
      {"three spheres and a cylinder merged",
       0.5,
       {{C::Sphere, Vec3(-0.5, 0, 0), Vec3(0.0), 1.0, 1.0},
        {C::Sphere, Vec3(0.5, 0, 0), Vec3(0.0), 1.0, 1.0},
        {C::Sphere, Vec3(0, 0.8, 0), Vec3(0.0), 0.8, 1.0},
        {C::Cylinder, Vec3(0, -1, -0.5), Vec3(0, -1, 0.5), 0.5, 1.5}},
       Vec3(0.0)},
      {"a negative sphere carving a hole",
       0.5,
       {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.2, 2.0},
        {C::Sphere, Vec3(0.0, 0.7, 0.0), Vec3(0.0), 0.6, -3.0}},
       Vec3(0.0, -0.3, 0.0)},
  };
  for (size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    Blob b(s.threshold, s.components);
    auto ref = refBlob(s.threshold, s.components);
    const double size = glm::length(b.bounds().extent());
    Rng rng(1801 + k);
    CaseResult r = newCase(s.name + ": random rays, and tangent at random points", kT, kN);
    for (int i = 0; i < n / 2; ++i) {
      measureRay(r, b, *ref, randomRayTo(rng, b.bounds()), size);
      SurfacePoint sp = surfaceBetween(b, s.core, s.core + 3.0 * size * randomUnit(rng));
      if (sp.ok) measureRay(r, b, *ref, grazingRay(rng, sp), size);
    }
    out.push_back(std::move(r));
  }
  {
    // A component of strength s = T·(1 + δ): a solid of radius about R·√(δ/2) at its
    // centre, δ from 1e-12 to 1e-2 (radii 1e-6 to 0.07). Rays aimed at random points near it.
    Rng rng(1811);
    // Bounds from the conditioning, not the method: the field's slope at the surface is
    // 4·s·r/R² with r down to 1e-6, so the double field's rounding (1e-16) moves the root by
    // 1e-16/(4r) ≈ 4e-11 and turns the normal of a solid that small by about 1e-10/r.
    CaseResult r = newCase(
        "strength just above the threshold (1 + 1e-12 to 1 + 1e-2): a tiny solid", 1e-9, 1e-3);
    for (int i = 0; i < n; ++i) {
      double delta = logUniform(rng, -12.0, -2.0);
      std::vector<C> cs = {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.0, 1.0 + delta}};
      Blob b(1.0, cs);
      auto ref = refBlob(1.0, cs);
      double rad = std::sqrt(1.0 - std::sqrt(1.0 / (1.0 + delta)));
      Vec3 target = uniform(rng, 0.0, 1.5 * rad) * randomUnit(rng);
      Vec3 o = 3.0 * randomUnit(rng);
      measureRay(r, b, *ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), 2.0);
    }
    out.push_back(std::move(r));
  }
  {
    // Two spheres at ±d (R 1, strength 1): the field at the saddle between them is
    // 2(1 − d²)²; the threshold within 1e-12 to 1e-6 of it, above (two blobs about to
    // merge) or below (a thin neck). Rays through points near the saddle.
    Rng rng(1812);
    // Bounds from the conditioning: near the saddle the field's gradient vanishes (the
    // neck's radius is about √(relative gap) of the size), so the same rounding moves the
    // root by 1e-16 over a slope down to 1e-6 and the neck's normal with it.
    CaseResult r = newCase(
        "two spheres whose fields just merge (threshold 1e-12 to 1e-6 from the saddle's field)",
        1e-9, 1e-3);
    for (int i = 0; i < n; ++i) {
      double d = uniform(rng, 0.3, 0.8);
      double saddle = 2.0 * (1.0 - d * d) * (1.0 - d * d);
      double T = saddle * (1.0 + (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -12.0, -6.0));
      std::vector<C> cs = {{C::Sphere, Vec3(-d, 0, 0), Vec3(0.0), 1.0, 1.0},
                           {C::Sphere, Vec3(d, 0, 0), Vec3(0.0), 1.0, 1.0}};
      Blob b(T, cs);
      auto ref = refBlob(T, cs);
      Vec3 target = logUniform(rng, -8.0, -2.0) * randomUnit(rng);
      Vec3 o = 3.0 * randomUnit(rng);
      measureRay(r, b, *ref, Ray(o, (target - o) * uniform(rng, 0.5, 2.0)), 4.0);
    }
    out.push_back(std::move(r));
  }
  {
    // Rays leaving the surface from offsetRayOrigin, out of the solid and into it: any
    // crossing the reference does not list is a re-hit. No bounds (a chord just ahead of
    // the origin has a t of any smallness).
    Rng rng(1813);
    CaseResult r =
        newCase("secondary rays leaving merged spheres, a capsule and a carved hole", 0.0, 0.0);
    for (size_t k = 1; k < settings.size(); ++k) {
      const Setting& s = settings[k];
      Blob b(s.threshold, s.components);
      auto ref = refBlob(s.threshold, s.components);
      const double size = glm::length(b.bounds().extent());
      for (int i = 0, tries = 0; i < n / 3 && tries < 20 * n; ++tries) {
        Ray primary = randomRayTo(rng, b.bounds());
        Hit h;
        if (!b.intersect(primary, h)) continue;
        ++i;
        SurfaceInfo si = b.surface(primary, h);
        for (double side : {1.0, -1.0}) {
          double c = uniform(rng, 0.01, 1.0);
          Vec3 w = side * c * si.ng + std::sqrt(1.0 - c * c) * randomPerpendicular(rng, si.ng);
          Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w * uniform(rng, 0.5, 2.0));
          measureRay(r, b, *ref, ray, size, Perturb::DirectionOnly);
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
