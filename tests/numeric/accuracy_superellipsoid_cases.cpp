// The superellipsoid's hard cases (docs/accuracy.md): nearly a box (e = n = 0.1 and 0.05),
// whose rounded edges are sharp and whose faces are flat to within rounding, rays grazing
// those edges and corners and running along the faces; tangent rays at random points of
// convex and pinched shapes (whose creases give the gauge an infinite slope); and rays
// leaving the surface. Each against refSuperellipsoid (long double, dense sampling and
// bisection on the pieces between the coordinate planes).
#include "accuracy_cases.h"

#include "primitives/offset.h"
#include "primitives/superellipsoid.h"

#include <fmt/format.h>

namespace lucent::accuracy {

namespace {

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Superellipsoids", name, boundRelT, boundAngle);
}

// The surface point in direction u from the centre (N is 1-homogeneous: u / N(u)) and its
// outward normal (Lucent's gradient: only to build rays, never to judge them).
struct SurfacePoint {
  Vec3 p, n;
};
SurfacePoint pointToward(const Superellipsoid& s, const Vec3& u) {
  Vec3 p = u / s.gauge(u);
  Vec3 g = s.gradient(p);
  if (!isFinite(g) || glm::dot(g, g) == 0.0) g = p;
  return {p, glm::normalize(g)};
}

// A line tangent at sp, moved off along the normal by side·δ, δ log-uniform in
// [10^minExponent, 1e-1]; the origin 2 to 5 units back.
Ray grazingRay(Rng& rng, const SurfacePoint& sp, double minExponent = -16.0) {
  Vec3 w = randomPerpendicular(rng, sp.n);
  double side = rng() % 2 ? 1.0 : -1.0;
  Vec3 q = sp.p + side * logUniform(rng, minExponent, -1.0) * sp.n;
  return Ray(q - uniform(rng, 2.0, 5.0) * w, w * uniform(rng, 0.5, 2.0));
}

// A random ray from 3 units away towards a point of the cube.
Ray randomRay(Rng& rng) {
  Vec3 o = 3.0 * randomUnit(rng);
  Vec3 target(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

// Near an edge (two coordinates at ±1, the third anywhere) or a corner of the cube.
Vec3 edgeOrCornerDirection(Rng& rng, bool corner) {
  auto sign = [&] { return rng() % 2 ? 1.0 : -1.0; };
  Vec3 u(sign(), sign(), corner ? sign() : uniform(rng, -0.9, 0.9));
  for (int i = 0; i < 3; ++i) u[i] += uniform(rng, -0.05, 0.05);
  int axis = int(rng() % 3);  // the edge along a random axis
  std::swap(u[axis], u[2]);
  return u;
}

}  // namespace

std::vector<CaseResult> superellipsoidCases(double effort) {
  // Bounds: as the other shapes' at unit scale, 1e-14 for t and 1e-12 for the normal (the
  // largest clear normal error measured with 4x the tests' rays is 5e-14, at the rounded
  // edges of e = n = 0.1, whose curvature reaches about 1e2).
  const double kT = 1e-14, kN = 1e-12;
  const int n = rayCount(300, effort);
  std::vector<CaseResult> out;
  const Superellipsoid box(0.1, 0.1), boxier(0.05, 0.05);
  auto refBox = refSuperellipsoid(0.1, 0.1), refBoxier = refSuperellipsoid(0.05, 0.05);
  const double size = 2.0 * std::sqrt(3.0);
  {
    Rng rng(1701);
    CaseResult r = newCase("e = n = 0.1 (nearly a cube): random rays", kT, kN);
    for (int i = 0; i < n; ++i) measureRay(r, box, *refBox, randomRay(rng), size);
    out.push_back(std::move(r));
  }
  {
    Rng rng(1702);
    CaseResult r = newCase("e = n = 0.1: tangent at the rounded edges and corners", kT, kN);
    for (int i = 0; i < n; ++i)
      measureRay(r, box, *refBox,
                 grazingRay(rng, pointToward(box, edgeOrCornerDirection(rng, i % 3 == 0))), size);
    out.push_back(std::move(r));
  }
  {
    // In the plane z = ±c or x = ±c, c = 1 ∓ δ: the faces are flat to within δ = 1e-30
    // over most of their extent, so these rays cut long shallow chords or just miss. Half
    // exactly parallel to the face, half tilted by 1e-9.
    Rng rng(1703);
    CaseResult r01 =
        newCase("e = n = 0.1: along the flat faces, 1e-16 to 1e-1 inside or outside", kT, kN);
    CaseResult r005 =
        newCase("e = n = 0.05: along the flat faces, 1e-16 to 1e-1 inside or outside", kT, kN);
    for (int i = 0; i < 2 * n; ++i) {
      const bool first = i % 2 == 0;
      double delta = logUniform(rng, -16.0, -1.0);
      double c = (rng() % 2 ? 1.0 - delta : 1.0 + delta) * (rng() % 2 ? 1.0 : -1.0);
      int axis = rng() % 2 ? 2 : 0;
      Vec3 o(uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5));
      double phi = uniform(rng, 0.0, 2.0 * kPi);
      Vec3 d(std::cos(phi), std::sin(phi), 0.0);
      if ((i / 2) % 2) d.z = 1e-9 * (rng() % 2 ? 1.0 : -1.0);
      if (axis == 0) {
        std::swap(d.x, d.z);
      }
      o[axis] = c;
      o -= 3.0 * d;
      measureRay(first ? r01 : r005, first ? box : boxier, first ? *refBox : *refBoxier,
                 Ray(o, d * uniform(rng, 0.5, 2.0)), size);
    }
    out.push_back(std::move(r01));
    out.push_back(std::move(r005));
  }
  {
    // Convex (0.5, 1.5), the octahedron (2, 2) with its straight edges, pinched (3, 3) and
    // mixed (0.3, 3): tangent lines at random points.
    Rng rng(1704);
    const std::pair<double, double> exps[] = {{0.5, 1.5}, {2.0, 2.0}, {3.0, 3.0}, {0.3, 3.0}};
    for (auto [e, nn] : exps) {
      Superellipsoid s(e, nn);
      auto ref = refSuperellipsoid(e, nn);
      CaseResult r = newCase(
          fmt::format("e = {}, n = {}: tangent at random points, and random rays", e, nn), kT, kN);
      for (int i = 0; i < n / 2; ++i) {
        // The octahedron's faces are flat: a line within rounding of one lies on it over a
        // whole stretch, and where along it the crossing falls is rounding's choice (the
        // decision itself is then within rounding). Its tangent lines keep off by 1e-13.
        measureRay(r, s, *ref,
                   grazingRay(rng, pointToward(s, randomUnit(rng)), e == 2.0 ? -13.0 : -16.0),
                   size);
        measureRay(r, s, *ref, randomRay(rng), size);
      }
      out.push_back(std::move(r));
    }
  }
  {
    // Rays leaving the surface from offsetRayOrigin, out of the solid and into it: any
    // crossing the reference does not list is a re-hit (Perturb::DirectionOnly). No
    // bounds: a chord just ahead of the origin has a t of any smallness.
    Rng rng(1705);
    CaseResult r = newCase("secondary rays leaving e = n = 0.1, (2, 2) and (3, 3)", 0.0, 0.0);
    const std::pair<double, double> exps[] = {{0.1, 0.1}, {2.0, 2.0}, {3.0, 3.0}};
    for (auto [e, nn] : exps) {
      Superellipsoid s(e, nn);
      auto ref = refSuperellipsoid(e, nn);
      for (int i = 0, tries = 0; i < n / 3 && tries < 20 * n; ++tries) {
        Ray primary = randomRay(rng);
        Hit h;
        if (!s.intersect(primary, h)) continue;
        ++i;
        SurfaceInfo si = s.surface(primary, h);
        for (double side : {1.0, -1.0}) {
          double c = uniform(rng, 0.01, 1.0);
          Vec3 w = side * c * si.ng + std::sqrt(1.0 - c * c) * randomPerpendicular(rng, si.ng);
          Ray ray(offsetRayOrigin(si.p, si.pError, si.ng, w), w * uniform(rng, 0.5, 2.0));
          measureRay(r, s, *ref, ray, size, Perturb::DirectionOnly);
        }
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace lucent::accuracy
