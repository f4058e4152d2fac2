// Quadrics and polys (docs/accuracy.md): the quadric's degenerate cases, a cylinder, a
// double cone and a plane written as quadrics (lines along the cylinder's axis, through
// the cone's apex at 1e-16 to 1e-1, grazing the plane), each against the long-double
// quadratic of refQuadric; and polys: a torus written as a quartic against the torus's own
// reference (the tube's distance function, independent of any quartic), tangent rays
// included, the tangle cube (up to eight crossings a line) and an ellipsoid of order 2; above
// order 4, three spheres multiplied (order 6), the rounded cube x⁸ + y⁸ + z⁸ < 1 (order 8) and
// x³⁴ + y³⁴ + z³⁴ < 1 (order 34), each against P evaluated term by term in long double.
#include "accuracy_cases.h"

#include "primitives/poly.h"
#include "primitives/quadric.h"

#include <fmt/format.h>

#include <array>
#include <map>

namespace lucent::accuracy {

namespace {

CaseResult newCase(const std::string& name, double boundRelT, double boundAngle) {
  return makeCase("Quadrics and polys", name, boundRelT, boundAngle);
}

// A ray from 3 to 5 units away towards a point within `reach` of the origin.
Ray randomRay(Rng& rng, double reach) {
  Vec3 o = uniform(rng, 3.0, 5.0) * randomUnit(rng);
  Vec3 target = reach * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  return Ray(o, (target - o) * uniform(rng, 0.5, 2.0));
}

// POV-Ray's order for `order`, from (powers, value) pairs.
std::vector<double> polyCoefficients(
    int order, const std::vector<std::pair<std::array<int, 3>, double>>& terms) {
  std::vector<double> c;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) {
        double v = 0.0;
        for (const auto& [p, value] : terms)
          if (p == std::array<int, 3>{i, j, k}) v = value;
        c.push_back(v);
      }
  return c;
}

}  // namespace

std::vector<CaseResult> quadricCases(double effort) {
  // Bounds as the other analytic shapes' at unit scale: 1e-14 for t, 1e-12 for the normal.
  const double kT = 1e-14, kN = 1e-12;
  const int n = rayCount(400, effort);
  std::vector<CaseResult> out;
  {
    // x² + z² < 1: random rays, lines nearly along the axis (1e-12 to 1e-1 off parallel),
    // and lines tangent to it.
    const Quadric q({Vec3(1, 0, 1), Vec3(0), Vec3(0), -1});
    auto ref = refQuadric(Vec3(1, 0, 1), Vec3(0), Vec3(0), -1);
    // Origins at least 0.3 from the surface: the cylinder is unbounded, and a ray starting
    // on it has a t of any smallness, whose relative error says nothing.
    CaseResult r =
        newCase("cylinder x² + z² − 1: random, near the axis direction, tangent", kT, kN);
    Rng rng(2201);
    for (int i = 0; i < n; ++i) {
      const double th = uniform(rng, 0.0, 2.0 * kPi);
      const Vec3 from = uniform(rng, 3.0, 5.0) * Vec3(std::cos(th), 0.0, std::sin(th)) +
                        Vec3(0.0, uniform(rng, -3.0, 3.0), 0.0);
      const Vec3 target = 1.2 * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
      measureRay(r, q, *ref, Ray(from, (target - from) * uniform(rng, 0.5, 2.0)), 2.0);
      const double tilt = logUniform(rng, -12.0, -1.0);
      const double phi = uniform(rng, 0.0, 2.0 * kPi), psi = uniform(rng, 0.0, 2.0 * kPi);
      const Vec3 d = glm::normalize(Vec3(tilt * std::cos(phi), 1.0, tilt * std::sin(phi)));
      const double r0 = i % 2 ? uniform(rng, 0.0, 0.7) : uniform(rng, 1.3, 1.6);
      const Vec3 o(r0 * std::cos(psi), -4.0, r0 * std::sin(psi));
      measureRay(r, q, *ref, Ray(o, d * uniform(rng, 0.5, 2.0)), 2.0);
      // Tangent at (cos a, y, sin a), moved off by 1e-16 to 1e-1 to either side.
      const double a = uniform(rng, 0.0, 2.0 * kPi);
      const Vec3 nrm(std::cos(a), 0.0, std::sin(a));
      const double off = (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -16.0, -1.0);
      const Vec3 w = glm::normalize(Vec3(-nrm.z, uniform(rng, -1.0, 1.0), nrm.x));
      const Vec3 p = (1.0 + off) * nrm + Vec3(0.0, uniform(rng, -1.0, 1.0), 0.0);
      measureRay(r, q, *ref, Ray(p - 3.0 * w, w), 2.0);
    }
    out.push_back(std::move(r));
  }
  {
    // The double cone x² − y² + z² < 0 (inside around the y axis): lines passing its apex
    // at a distance δ in a random direction. Its gradient vanishes at the apex, so near it
    // a root's t is ill-conditioned (δ-relative); the bound is asserted on the far rows.
    const Quadric q({Vec3(1, -1, 1), Vec3(0), Vec3(0), 0});
    auto ref = refQuadric(Vec3(1, -1, 1), Vec3(0), Vec3(0), 0);
    CaseResult far =
        newCase("double cone x² − y² + z²: lines passing the apex 1e-7 to 1e-1 away", 1e-13, 0.0);
    CaseResult near =
        newCase("double cone x² − y² + z²: lines passing the apex 1e-16 to 1e-7 away", 0.0, 0.0);
    Rng rng(2202);
    for (int i = 0; i < n; ++i) {
      const bool isFar = i % 2 == 0;
      const Vec3 w = randomUnit(rng);
      const double delta = logUniform(rng, isFar ? -7.0 : -16.0, isFar ? -1.0 : -7.0);
      const Vec3 p = delta * randomPerpendicular(rng, w);
      measureRay(isFar ? far : near, q, *ref, Ray(p - 3.0 * w, w * uniform(rng, 0.5, 2.0)), 2.0);
    }
    out.push_back(std::move(far));
    out.push_back(std::move(near));
  }
  {
    // The plane y < 0.5 as a quadric (only a linear term): lines at 1e-16 to 1e-1 radians
    // to it, and lines exactly parallel inside and outside.
    const Quadric q({Vec3(0), Vec3(0), Vec3(0, 1, 0), -0.5});
    auto ref = refQuadric(Vec3(0), Vec3(0), Vec3(0, 1, 0), -0.5);
    CaseResult r =
        newCase("plane y − 0.5 as a quadric: random, grazing and parallel lines", kT, kN);
    Rng rng(2203);
    for (int i = 0; i < n; ++i) {
      measureRay(r, q, *ref, randomRay(rng, 1.0), 2.0);
      const double phi = uniform(rng, 0.0, 2.0 * kPi);
      const double slope =
          i % 4 == 0 ? 0.0 : (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -16.0, -1.0);
      const Vec3 d(std::cos(phi), slope, std::sin(phi));
      const Vec3 o(uniform(rng, -2, 2), 0.5 + uniform(rng, -0.1, 0.1), uniform(rng, -2, 2));
      measureRay(r, q, *ref, Ray(o - 3.0 * d, d * uniform(rng, 0.5, 2.0)), 2.0);
    }
    out.push_back(std::move(r));
  }
  {
    // The torus R = 1, r = 0.3 written as a quartic, against the torus's own reference:
    // random rays, lines tangent to the tube at random points (1e-12 to 1e-1 off), and
    // lines through the hole along the axis.
    const double R = 1.0, rr = 0.3, a = R * R - rr * rr;
    const Poly p(4, polyCoefficients(4, {{{4, 0, 0}, 1},
                                         {{0, 4, 0}, 1},
                                         {{0, 0, 4}, 1},
                                         {{2, 2, 0}, 2},
                                         {{2, 0, 2}, 2},
                                         {{0, 2, 2}, 2},
                                         {{2, 0, 0}, 2 * a - 4 * R * R},
                                         {{0, 2, 0}, 2 * a},
                                         {{0, 0, 2}, 2 * a - 4 * R * R},
                                         {{0, 0, 0}, a * a}}));
    auto ref = refTorus(R, rr);
    CaseResult r =
        newCase("torus as a quartic poly: random, tangent to the tube, through the hole", kT, kN);
    Rng rng(2204);
    for (int i = 0; i < n; ++i) {
      measureRay(r, p, *ref, randomRay(rng, 1.3), 2.6);
      const double th = uniform(rng, 0.0, 2.0 * kPi), ph = uniform(rng, 0.0, 2.0 * kPi);
      const Vec3 c(R * std::cos(th), 0.0, R * std::sin(th));
      const Vec3 nrm(std::cos(ph) * std::cos(th), std::sin(ph), std::cos(ph) * std::sin(th));
      const double off = (rng() % 2 ? 1.0 : -1.0) * logUniform(rng, -12.0, -1.0);
      const Vec3 w = randomPerpendicular(rng, nrm);
      measureRay(r, p, *ref, Ray(c + (rr + off) * nrm - 3.0 * w, w), 2.6);
      const Vec3 o(uniform(rng, -0.5, 0.5), 3.0, uniform(rng, -0.5, 0.5));
      measureRay(r, p, *ref, Ray(o, Vec3(uniform(rng, -0.1, 0.1), -1.0, uniform(rng, -0.1, 0.1))),
                 2.6);
    }
    out.push_back(std::move(r));
  }
  {
    // The tangle cube x⁴ − 5x² + y⁴ − 5y² + z⁴ − 5z² + 11.8 < 0: six lobes and holes, up to
    // eight crossings a line; and an ellipsoid of order 2 against the quadric reference.
    const auto tangle = polyCoefficients(4, {{{4, 0, 0}, 1},
                                             {{2, 0, 0}, -5},
                                             {{0, 4, 0}, 1},
                                             {{0, 2, 0}, -5},
                                             {{0, 0, 4}, 1},
                                             {{0, 0, 2}, -5},
                                             {{0, 0, 0}, 11.8}});
    const Poly p(4, tangle);
    auto ref = refPoly(4, tangle, 3.6);  // its lobes reach 3.47 from the centre
    CaseResult r = newCase("tangle cube (quartic poly): random rays", kT, kN);
    Rng rng(2205);
    for (int i = 0; i < n; ++i) measureRay(r, p, *ref, randomRay(rng, 2.0), 7.0);
    out.push_back(std::move(r));
    const auto ellipsoid = polyCoefficients(2, {{{2, 0, 0}, 0.25},
                                                {{1, 1, 0}, 0.3},
                                                {{0, 2, 0}, 1},
                                                {{0, 0, 2}, 2},
                                                {{0, 0, 1}, 0.2},
                                                {{0, 0, 0}, -1}});
    const Poly e(2, ellipsoid);
    auto refE = refQuadric(Vec3(0.25, 1, 2), Vec3(0.3, 0, 0), Vec3(0, 0, 0.2), -1);
    CaseResult re = newCase("ellipsoid as a poly of order 2: random rays", kT, kN);
    for (int i = 0; i < n; ++i) measureRay(re, e, *refE, randomRay(rng, 1.5), 4.0);
    out.push_back(std::move(re));
  }
  {
    // Above order 4: three disjoint spheres multiplied (the surface is theirs: P < 0 inside
    // exactly one), expanded into 84 coefficients with cancelling terms; and two rounded
    // cubes, whose high powers make the line polynomial's terms span many magnitudes.
    std::map<std::array<int, 3>, double> product = {{{0, 0, 0}, 1.0}};
    const std::array<std::pair<Vec3, double>, 3> balls = {
        {{Vec3(-1.2, 0, 0), 0.7}, {Vec3(0.4, 0.5, 0.2), 0.6}, {Vec3(0.6, -0.9, -0.3), 0.5}}};
    for (const auto& [c, radius] : balls) {
      const std::map<std::array<int, 3>, double> sphere = {
          {{2, 0, 0}, 1.0},
          {{0, 2, 0}, 1.0},
          {{0, 0, 2}, 1.0},
          {{1, 0, 0}, -2.0 * c.x},
          {{0, 1, 0}, -2.0 * c.y},
          {{0, 0, 1}, -2.0 * c.z},
          {{0, 0, 0}, glm::dot(c, c) - radius * radius}};
      std::map<std::array<int, 3>, double> next;
      for (const auto& [pa, ca] : product)
        for (const auto& [pb, cb] : sphere)
          next[{pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]}] += ca * cb;
      product = std::move(next);
    }
    const auto spheres = polyCoefficients(
        6, std::vector<std::pair<std::array<int, 3>, double>>(product.begin(), product.end()));
    const Poly p6(6, spheres);
    auto ref6 = refPoly(6, spheres, 2.0);
    CaseResult r6 = newCase("three spheres multiplied (order 6 poly): random rays", kT, kN);
    Rng rng(2206);
    for (int i = 0; i < n; ++i) measureRay(r6, p6, *ref6, randomRay(rng, 1.5), 7.0);
    out.push_back(std::move(r6));
    for (int order : {8, 34}) {
      const auto cube = polyCoefficients(
          order, {{{order, 0, 0}, 1}, {{0, order, 0}, 1}, {{0, 0, order}, 1}, {{0, 0, 0}, -1}});
      const Poly p(order, cube);
      auto ref = refPoly(order, cube, 1.8);  // the corners reach 3^(1/2 − 1/order)
      CaseResult r = newCase(
          fmt::format("x^{0} + y^{0} + z^{0} < 1 (order {0} poly): random rays", order), kT, kN);
      for (int i = 0; i < n; ++i) measureRay(r, p, *ref, randomRay(rng, 1.2), 7.0);
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace lucent::accuracy
