#include "shape_checks.h"

#include "primitives/blob.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;

namespace {

using LD = long double;
using C = BlobComponent;

// The field in long double, straight from POV-Ray's definition (primitives/blob.h).
LD fieldL(const std::vector<C>& cs, const Vec3& p) {
  LD f = 0;
  for (const C& c : cs) {
    LD px = p.x, py = p.y, pz = p.z, r2 = 0;
    if (c.kind == C::Sphere) {
      LD dx = px - c.a.x, dy = py - c.a.y, dz = pz - c.a.z;
      r2 = dx * dx + dy * dy + dz * dz;
    } else {
      LD ax = (LD)c.b.x - c.a.x, ay = (LD)c.b.y - c.a.y, az = (LD)c.b.z - c.a.z;
      LD len2 = ax * ax + ay * ay + az * az;
      LD wx = px - c.a.x, wy = py - c.a.y, wz = pz - c.a.z;
      LD z = std::clamp((wx * ax + wy * ay + wz * az) / len2, (LD)0, (LD)1);
      LD dx = wx - z * ax, dy = wy - z * ay, dz = wz - z * az;
      r2 = dx * dx + dy * dy + dz * dz;
    }
    LD R2 = (LD)c.radius * c.radius;
    if (r2 < R2) {
      LD g = 1 - r2 / R2;
      f += c.strength * g * g;
    }
  }
  return f;
}

struct Case {
  const char* name;
  double threshold;
  std::vector<C> components;
};

const std::vector<Case> kCases = {
    {"one sphere", 1.0, {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.0, 2.0}}},
    {"two merging spheres",
     0.6,
     {{C::Sphere, Vec3(-0.5, 0, 0), Vec3(0.0), 1.0, 1.0},
      {C::Sphere, Vec3(0.5, 0, 0), Vec3(0.0), 1.0, 1.0}}},
    {"negative hole",
     0.5,
     {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.2, 2.0},
      {C::Sphere, Vec3(0.0, 0.7, 0.0), Vec3(0.0), 0.6, -3.0}}},
    {"cylinder", 1.0, {{C::Cylinder, Vec3(0.0), Vec3(0.0, 2.0, 0.0), 1.0, 2.0}}},
    {"cylinder and spheres",
     0.5,
     {{C::Cylinder, Vec3(-1, 0, 0), Vec3(1, 0.5, 0.2), 0.6, 1.5},
      {C::Sphere, Vec3(1, 0.5, 0.2), Vec3(0.0), 0.8, 1.0},
      {C::Sphere, Vec3(0, 0.3, 0.1), Vec3(0.0), 0.5, -1.0},
      {C::Cylinder, Vec3(0, -1, 0), Vec3(0, 1, 0), 0.4, 1.0}}},
};

double angle(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The surface radius of one component of strength s at threshold T: s(1 − r²/R²)² = T.
double surfaceRadius(double s, double T, double R) { return R * std::sqrt(1.0 - std::sqrt(T / s)); }

}  // namespace

TEST_CASE("blob: one sphere component is a sphere of the closed-form radius",
          "[primitives][blob]") {
  Blob b(1.0, {{C::Sphere, Vec3(1, 2, 3), Vec3(0.0), 1.5, 2.0}});
  double r = surfaceRadius(2.0, 1.0, 1.5);
  Ray ray(Vec3(1, 2, -10), Vec3(0, 0, 2));
  Hit h;
  REQUIRE(b.intersect(ray, h));
  CHECK(h.t == Approx((13.0 - r) / 2.0).epsilon(1e-15));
  SurfaceInfo s = b.surface(ray, h);
  CHECK(s.ng.z == Approx(-1.0).epsilon(1e-15));
  CrossingList cl;
  b.crossings(ray, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_FALSE(cl.startsInside);
  CHECK(cl.items[1].hit.t == Approx((13.0 + r) / 2.0).epsilon(1e-15));
  CHECK_FALSE(cl.items[1].entering);
  CHECK(b.inside(Vec3(1, 2, 3)));
  CHECK_FALSE(b.inside(Vec3(1, 2, 3 + r + 1e-9)));
  CHECK(b.inside(Vec3(1, 2, 3 + r - 1e-9)));
  // A ray starting inside.
  Ray from(Vec3(1, 2, 3), Vec3(1, 0, 0));
  CrossingList c2;
  b.crossings(from, c2);
  CHECK(c2.startsInside);
  REQUIRE(c2.items.size() == 1);
  CHECK(c2.items[0].hit.t == Approx(r).epsilon(1e-15));
}

TEST_CASE("blob: a cylinder component is a capsule of the closed-form radius",
          "[primitives][blob]") {
  Blob b(1.0, {{C::Cylinder, Vec3(0.0), Vec3(0.0, 2.0, 0.0), 1.0, 2.0}});
  double r = surfaceRadius(2.0, 1.0, 1.0);
  Hit h;
  Ray side(Vec3(-5, 1.3, 0), Vec3(1, 0, 0));
  REQUIRE(b.intersect(side, h));
  CHECK(h.t == Approx(5.0 - r).epsilon(1e-15));
  CHECK(b.surface(side, h).ng.x == Approx(-1.0).epsilon(1e-15));
  Ray axis(Vec3(0, -5, 0), Vec3(0, 1, 0));
  CrossingList cl;
  b.crossings(axis, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].hit.t == Approx(5.0 - r).epsilon(1e-15));
  CHECK(cl.items[1].hit.t == Approx(7.0 + r).epsilon(1e-15));
  // The hemispherical end: a ray along the diagonal of the end ball.
  Vec3 dir = glm::normalize(Vec3(1, 1, 0));
  Ray end(Vec3(0, 2, 0) + 5.0 * dir, -dir);
  REQUIRE(b.intersect(end, h));
  CHECK(h.t == Approx(5.0 - r).epsilon(1e-14));
  CHECK(angle(b.surface(end, h).ng, dir) < 1e-13);
}

TEST_CASE(
    "blob: crossings alternate, lie on the surface and agree with inside() (long-double field)",
    "[primitives][blob]") {
  Rng rng(71);
  for (const Case& cs : kCases) {
    INFO(cs.name);
    Blob b(cs.threshold, cs.components);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
      Ray ray = randomRayAt(rng, b.bounds(), uniform(rng, 0.2, 2.0));
      CrossingList cl;
      b.crossings(ray, cl);
      REQUIRE(crossingsViolation(b, ray, cl).empty());
      REQUIRE(intersectAgreesWithCrossings(b, ray).empty());
      CHECK(cl.startsInside == b.inside(ray.o));
      // Each crossing within a few ulps of the true surface: |F − T| over the gradient.
      for (const Crossing& c : cl.items) {
        Vec3 p = ray.at(c.hit.t);
        LD f = fieldL(cs.components, p) - cs.threshold;
        double g = glm::length(b.gradient(p));
        if (g > 1e-3) CHECK(std::abs((double)f) / g < 1e-13);
        ++hits;
      }
      // Between the crossings the long-double field keeps one side (no root missed).
      bool in = cl.startsInside;
      double last = ray.tmin;
      auto sample = [&](double a, double z) {
        for (int k = 1; k < 64; ++k) {
          double t = a + (z - a) * k / 64.0;
          LD f = fieldL(cs.components, ray.at(t)) - cs.threshold;
          if (std::abs((double)f) < 1e-9) continue;
          REQUIRE((f > 0) == in);
        }
      };
      for (const Crossing& c : cl.items) {
        sample(last, c.hit.t);
        in = c.entering;
        last = c.hit.t;
      }
      Interval box = b.bounds().slab(ray, Vec3(1.0) / ray.d);
      if (!box.empty() && box.hi > last) sample(last, box.hi);
    }
    CHECK(hits > 100);
  }
}

namespace {

// Calls visit(case, blob, ray, surface) for the hits of 300 random rays about each case.
template <class Visit>
void forEachHit(Rng& rng, Visit&& visit) {
  for (const Case& cs : kCases) {
    INFO(cs.name);
    Blob b(cs.threshold, cs.components);
    for (int i = 0; i < 300; ++i) {
      Ray ray = randomRayAt(rng, b.bounds());
      Hit h;
      if (b.intersect(ray, h)) visit(cs, b, ray, b.surface(ray, h));
    }
  }
}

}  // namespace

TEST_CASE("blob: normals are the field's falling gradient", "[primitives][blob]") {
  Rng rng(72);
  forEachHit(rng, [&](const Case& cs, const Blob&, const Ray& ray, const SurfaceInfo& s) {
    // A central difference of the long-double field.
    const double e = 1e-6;
    LD g[3];
    for (int k = 0; k < 3; ++k) {
      Vec3 dp(0.0);
      dp[k] = e;
      g[k] = (fieldL(cs.components, s.p + dp) - fieldL(cs.components, s.p - dp)) / (2 * e);
    }
    Vec3 expect = -glm::normalize(Vec3(double(g[0]), double(g[1]), double(g[2])));
    CHECK(angle(s.ng, expect) < 1e-6);
    CHECK(glm::dot(s.ng, ray.d) <= 0.0);
  });
}

TEST_CASE("blob: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][blob]") {
  Rng rng(73);
  forEachHit(rng, [&](const Case&, const Blob& b, const Ray&, const SurfaceInfo& s) {
    double off = glm::dot(glm::abs(s.ng), s.pError) * 2.0;
    CHECK_FALSE(b.inside(s.p + s.ng * off));
    CHECK(b.inside(s.p - s.ng * off));
    Ray out(s.p + s.ng * off, s.ng + 0.3 * randomUnit(rng));
    if (glm::dot(out.d, s.ng) <= 0.1) return;
    Hit h2;
    if (b.intersect(out, h2)) CHECK(h2.t * glm::length(out.d) > 1e-6);
  });
}

TEST_CASE("blob: invalid parameters are refused", "[primitives][blob]") {
  CHECK_THROWS_AS(Blob(0.0, {{C::Sphere, Vec3(0.0), Vec3(0.0), 1.0, 1.0}}), std::invalid_argument);
  CHECK_THROWS_AS(Blob(1.0, {}), std::invalid_argument);
  CHECK_THROWS_AS(Blob(1.0, {{C::Sphere, Vec3(0.0), Vec3(0.0), 0.0, 1.0}}), std::invalid_argument);
  CHECK_THROWS_AS(Blob(1.0, {{C::Sphere, Vec3(0.0), Vec3(0.0), std::nan(""), 1.0}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(Blob(1.0, {{C::Cylinder, Vec3(1.0), Vec3(1.0), 1.0, 1.0}}),
                  std::invalid_argument);
}

TEST_CASE("blob: a sphere component scaled unevenly is the ellipsoid of the closed-form axes",
          "[primitives][blob]") {
  // One component of strength 2, radius 1.5, threshold 1: in its own space a sphere of
  // radius r; scaled by (2, 0.5, 1.25), turned 30 degrees about z and moved, the ellipsoid
  // of semi-axes r·(2, 0.5, 1.25) there. Hits and normals against that ellipsoid, solved in
  // long double.
  const double r = surfaceRadius(2.0, 1.0, 1.5);
  const Vec3 axes(2.0, 0.5, 1.25), centre(0.3, -0.2, 0.7);
  const Mat4 transform = glm::translate(Mat4(1.0), centre) *
                         glm::rotate(Mat4(1.0), glm::radians(30.0), Vec3(0, 0, 1)) *
                         glm::scale(Mat4(1.0), axes);
  C c{C::Sphere, Vec3(0.0), Vec3(0.0), 1.5, 2.0};
  c.transform = transform;
  Blob b(1.0, {c});
  const Mat4 toLocal = glm::inverse(transform);
  std::vector<Vec3> dirs = {Vec3(1, 0.1, 0.05), Vec3(-0.3, 1, 0.2), Vec3(0.2, -0.4, -1),
                            Vec3(1, 1, 1)};
  int checked = 0;
  for (const Vec3& d0 : dirs) {
    const Vec3 d = glm::normalize(d0);
    const Ray ray(centre - 6.0 * d + Vec3(0.05, 0.02, -0.03), d);
    // The ellipsoid's unit sphere of radius r in local space: |o' + t d'|² = r².
    const Vec3 o = Vec3(toLocal * Vec4(ray.o, 1.0)), dl = Vec3(toLocal * Vec4(ray.d, 0.0));
    const LD A = (LD)glm::dot(dl, dl), B = 2 * (LD)glm::dot(o, dl),
             Cc = (LD)glm::dot(o, o) - (LD)r * r;
    const LD disc = B * B - 4 * A * Cc;
    REQUIRE(disc > 0);
    const LD tNear = (-B - std::sqrt(disc)) / (2 * A), tFar = (-B + std::sqrt(disc)) / (2 * A);
    CrossingList cl;
    b.crossings(ray, cl);
    REQUIRE(cl.items.size() == 2);
    CHECK(cl.items[0].hit.t == Approx((double)tNear).epsilon(1e-13));
    CHECK(cl.items[1].hit.t == Approx((double)tFar).epsilon(1e-13));
    // The normal: the inverse-transpose of the local sphere's normal.
    const Vec3 pLocal = o + (double)tNear * dl;
    const Vec3 expected = glm::normalize(glm::transpose(Mat3(toLocal)) * pLocal);
    Hit h;
    REQUIRE(b.intersect(ray, h));
    CHECK(angle(b.surface(ray, h).ng, expected) < 1e-12);
    ++checked;
  }
  CHECK(checked == 4);
  // Inside: the centre, and points just within and beyond the long axis's end.
  const Vec3 longAxis = Vec3(transform * Vec4(1, 0, 0, 0));
  CHECK(b.inside(centre));
  CHECK(b.inside(centre + (r * (1 - 1e-9)) * longAxis));
  CHECK_FALSE(b.inside(centre + (r * (1 + 1e-9)) * longAxis));
  // The bounds hold the support (the local radius 1.5, placed).
  const AABB box = b.bounds();
  CHECK(box.hi.x >= centre.x + 1.5 * 2.0 * std::cos(glm::radians(30.0)) - 1e-12);
}

TEST_CASE("blob: transformed components merge with plain ones on a continuous field",
          "[primitives][blob]") {
  // A sheared cylinder and a flattened sphere beside a plain sphere: every crossing lies on
  // the surface of the long-double field evaluated through each component's inverse.
  C cyl{C::Cylinder, Vec3(-1, 0, 0), Vec3(1, 0, 0), 0.6, 1.5};
  cyl.transform = Mat4(1.0);
  cyl.transform[1][0] = 0.4;  // x += 0.4 y
  C flat{C::Sphere, Vec3(0.8, 0.3, 0), Vec3(0.0), 0.8, 1.0};
  flat.transform = glm::scale(Mat4(1.0), Vec3(1.0, 0.4, 1.0));
  C plain{C::Sphere, Vec3(-0.9, 0.1, 0.2), Vec3(0.0), 0.7, 1.2};
  const std::vector<C> cs = {cyl, flat, plain};
  Blob b(0.5, cs);
  auto fieldAt = [&](const Vec3& p) {
    LD f = 0;
    for (const C& c : cs) {
      const Vec3 q = Vec3(glm::inverse(c.transform) * Vec4(p, 1.0));
      C own = c;
      own.transform = Mat4(1.0);
      f += fieldL({own}, q);
    }
    return f;
  };
  int crossings = 0;
  for (int i = 0; i < 40; ++i) {
    const double a = 0.157 * i;
    const Vec3 d = glm::normalize(Vec3(std::cos(a), 0.3 * std::sin(3 * a), std::sin(a)));
    const Ray ray(Vec3(0.1, 0.15, 0.05) - 5.0 * d, d);
    CrossingList cl;
    b.crossings(ray, cl);
    for (const Crossing& x : cl.items) {
      const Vec3 p = ray.at(x.hit.t);
      CHECK(std::abs((double)(fieldAt(p) - 0.5)) < 1e-10);
      // The normal is the falling gradient, by central differences of the field.
      const double e = 1e-6;
      Vec3 g((double)(fieldAt(p + Vec3(e, 0, 0)) - fieldAt(p - Vec3(e, 0, 0))),
             (double)(fieldAt(p + Vec3(0, e, 0)) - fieldAt(p - Vec3(0, e, 0))),
             (double)(fieldAt(p + Vec3(0, 0, e)) - fieldAt(p - Vec3(0, 0, e))));
      Hit h = x.hit;
      CHECK(angle(b.surface(ray, h).ng, -glm::normalize(g)) < 1e-5);
      ++crossings;
    }
  }
  CHECK(crossings > 40);
}

TEST_CASE("blob: a component's transform must be invertible", "[primitives][blob]") {
  C c{C::Sphere, Vec3(0.0), Vec3(0.0), 1.0, 2.0};
  c.transform = glm::scale(Mat4(1.0), Vec3(1.0, 0.0, 1.0));
  CHECK_THROWS_AS(Blob(1.0, {c}), std::invalid_argument);
}
