// Shapes through Instance: t stays in world units, world normals are unit and outward,
// under non-uniform scale, shear and mirroring.
#include "shape_checks.h"
#include "test_meshes.h"

#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/instance.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "primitives/triangle_mesh.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
Transform make(const Mat4& m) {
  auto t = Transform::fromMatrix(m);
  REQUIRE(t);
  return *t;
}
Mat4 scale(const Vec3& s) { return glm::scale(Mat4(1.0), s); }
Mat4 translate(const Vec3& v) { return glm::translate(Mat4(1.0), v); }
}  // namespace

TEST_CASE("instance: an ellipsoid from a scaled sphere, t in world units",
          "[primitives][instance]") {
  // Unit sphere scaled (2, 3, 4) and moved to (10, 0, 0).
  Instance e(std::make_shared<Sphere>(Vec3(0.0), 1.0),
             make(translate(Vec3(10, 0, 0)) * scale(Vec3(2, 3, 4))), 0);
  struct Case {
    Vec3 o, d;
    double t;
    Vec3 n;
  };
  const Case cases[] = {
      {{0, 0, 0}, {1, 0, 0}, 8.0, {-1, 0, 0}},
      {{10, 10, 0}, {0, -1, 0}, 7.0, {0, 1, 0}},
      {{10, 0, -10}, {0, 0, 2}, 3.0, {0, 0, -1}},
      {{20, 0, 0}, {-0.5, 0, 0}, 16.0, {1, 0, 0}},
  };
  for (const Case& c : cases) {
    Ray ray(c.o, c.d);
    Hit h;
    REQUIRE(e.intersect(ray, h));
    CHECK_THAT(h.t, WithinRel(c.t, 1e-15));
    CHECK(h.shape == &e);
    SurfaceInfo si = e.surface(ray, h);
    CHECK_THAT(glm::dot(si.ng, c.n), WithinAbs(1.0, 1e-15));
  }
  // An oblique point: on the ellipsoid x²/4 + y²/9 = 1 at (√2, 3/√2), the outward normal is
  // ∝ (x/4, y/9) = (√2/4, 1/(3√2)).
  Vec3 p(10 + std::sqrt(2.0), 3 / std::sqrt(2.0), 0);
  Ray ray(p + Vec3(1, 1, 0), Vec3(-1, -1, 0));
  Hit h;
  REQUIRE(e.intersect(ray, h));
  CHECK_THAT(h.t, WithinRel(1.0, 1e-14));
  SurfaceInfo si = e.surface(ray, h);
  Vec3 n = glm::normalize(Vec3(std::sqrt(2.0) / 4, 1 / (3 * std::sqrt(2.0)), 0));
  CHECK_THAT(glm::dot(si.ng, n), WithinAbs(1.0, 1e-14));
  CHECK_THAT(glm::length(si.ng), WithinAbs(1.0, 1e-15));
  CHECK_THAT(glm::length(si.p - p), WithinAbs(0.0, 1e-14));
}

TEST_CASE("instance: a sheared box, t and outward normals", "[primitives][instance]") {
  // x' = x + 0.5·y: the face x = 1 becomes the plane x' − 0.5·y' = 1, normal ∝ (1, −0.5, 0).
  Mat4 shear(1.0);
  shear[1][0] = 0.5;  // column y, row x
  Instance b(std::make_shared<Box>(Vec3(-1.0), Vec3(1.0)), make(shear), 0);
  // A ray along +x at y = 0.5 from inside leaves through x' = 1 + 0.25 at t = 1.25.
  Ray ray(Vec3(0, 0.5, 0), Vec3(1, 0, 0));
  Hit h;
  REQUIRE(b.intersect(ray, h));
  CHECK_THAT(h.t, WithinRel(1.25, 1e-15));
  SurfaceInfo si = b.surface(ray, h);
  Vec3 n = glm::normalize(Vec3(1, -0.5, 0));
  CHECK_THAT(glm::dot(si.ng, n), WithinAbs(1.0, 1e-15));
  CHECK(b.inside(Vec3(1.2, 0.5, 0)));
  CHECK_FALSE(b.inside(Vec3(1.3, 0.5, 0)));
}

TEST_CASE("instance: a mirror keeps normals outward and t exact", "[primitives][instance]") {
  // scale(-1, 1, 1) about the origin maps the sphere at (2,0,0) to (−2,0,0).
  Instance s(std::make_shared<Sphere>(Vec3(2, 0, 0), 1.0), make(scale(Vec3(-1, 1, 1))), 0);
  Instance c(std::make_shared<Cylinder>(Vec3(1, 0, 0), Vec3(3, 0, 0), 0.5, false),
             make(scale(Vec3(-1, 2, 1))), 0);
  Instance m(std::make_shared<TriangleMesh>(boxMesh(Vec3(1, -1, -1), Vec3(3, 1, 1)), false),
             make(scale(Vec3(-1, 1, 1))), 0);
  REQUIRE(s.transform().flipsHandedness());
  Rng rng(15);
  for (const Instance* inst : {&s, &c, &m}) {
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      Ray ray = randomRayAt(rng, inst->bounds());
      Hit h;
      if (!inst->intersect(ray, h)) continue;
      ++hits;
      SurfaceInfo si = inst->surface(ray, h);
      REQUIRE_THAT(glm::length(si.ng), WithinAbs(1.0, 1e-14));
      // Outward: a small step along the normal leaves the solid, one against it enters.
      double step = 1e-6;
      REQUIRE_FALSE(inst->inside(si.p + step * si.ng));
      REQUIRE(inst->inside(si.p - step * si.ng));
    }
    CHECK(hits > 500);
  }
  // The sphere's t: from (−10, 0, 0) along +x the mirrored sphere at x = −2 is hit at t = 7.
  Hit h;
  REQUIRE(s.intersect(Ray(Vec3(-10, 0, 0), Vec3(1, 0, 0)), h));
  CHECK_THAT(h.t, WithinRel(7.0, 1e-15));
}

TEST_CASE("instance: a scaled and rotated torus keeps world-unit t", "[primitives][instance]") {
  // Torus (R 1, r 0.25) scaled ×3 and stood up (rotated 90° about x): in the xy-plane.
  Mat4 m = glm::rotate(Mat4(1.0), kPi / 2, Vec3(1, 0, 0)) * scale(Vec3(3.0));
  Instance t(std::make_shared<Torus>(1.0, 0.25), make(m), 0);
  CrossingList cl;
  t.crossings(Ray(Vec3(10, 0, 0), Vec3(-1, 0, 0)), cl);
  REQUIRE(cl.items.size() == 4);
  const double expect[4] = {10 - 3.75, 10 - 2.25, 10 + 2.25, 10 + 3.75};
  for (int i = 0; i < 4; ++i) CHECK_THAT(cl.items[i].hit.t, WithinRel(expect[i], 1e-14));
}
