#include "primitives/polygon.h"

#include <catch2/catch.hpp>

using namespace lucent;
using Catch::Matchers::WithinAbs;

namespace {

// A square from -1 to 1 in x and y at z = 0 with a square hole from -0.5 to 0.5.
std::vector<Vec3> ring() {
  return {{-1, -1, 0},     {1, -1, 0},     {1, 1, 0},     {-1, 1, 0},     {-1, -1, 0},
          {-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {-0.5, -0.5, 0}};
}

bool hits(const Polygon& p, const Vec3& at) {
  Hit h;
  return p.intersect(Ray(at + Vec3(0, 0, 3), Vec3(0, 0, -1)), h);
}

}  // namespace

TEST_CASE("polygon: POV-Ray's reading of the points", "[primitives][polygon]") {
  // Closed outlines are kept; a point within 1e-10 of its outline's first closes it and is
  // made that point.
  std::vector<Vec3> pts = ring();
  pts[4] = Vec3(-1 + 4e-11, -1, 0);
  PolygonOutline o = polygonOutline(pts);
  CHECK_FALSE(o.closedLast);
  REQUIRE(o.points.size() == 10);
  CHECK(o.points[4] == Vec3(-1, -1, 0));
  // An unclosed last outline gets its first point appended.
  o = polygonOutline({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  CHECK(o.closedLast);
  REQUIRE(o.points.size() == 4);
  CHECK(o.points[3] == Vec3(0, 0, 0));
  std::vector<Vec3> open = ring();
  open.pop_back();  // the hole's outline unclosed: its own first point closes it
  o = polygonOutline(open);
  CHECK(o.closedLast);
  CHECK(o.points.back() == Vec3(-0.5, -0.5, 0));
}

TEST_CASE("polygon: what makes no polygon", "[primitives][polygon]") {
  CHECK(polygonProblem({{0, 0, 0}, {1, 0, 0}}) != "");
  CHECK(polygonProblem({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 0}}).find("one line") !=
        std::string::npos);
  const std::string bent =
      polygonProblem({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-6}, {0, 0, 0}});
  CHECK(bent.find("point 4") != std::string::npos);
  CHECK(bent.find("one plane") != std::string::npos);
  CHECK(polygonProblem(ring()) == "");
  CHECK_THROWS_AS(Polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-6}, {0, 0, 0}}),
                  std::invalid_argument);
}

TEST_CASE("polygon: hits inside the outline, not in its hole, from both sides",
          "[primitives][polygon]") {
  const Polygon p(ring());
  CHECK_FALSE(p.isSolid());
  CHECK(hits(p, Vec3(0.75, 0, 0)));
  CHECK(hits(p, Vec3(-0.9, 0.9, 0)));
  CHECK_FALSE(hits(p, Vec3(0, 0, 0)));       // the hole
  CHECK_FALSE(hits(p, Vec3(0.2, -0.3, 0)));  // the hole
  CHECK_FALSE(hits(p, Vec3(1.1, 0, 0)));     // outside
  Hit h;
  const Ray below(Vec3(0.75, 0.25, -2), Vec3(0, 0, 0.5));
  REQUIRE(p.intersect(below, h));
  CHECK(h.t == 4.0);
  const SurfaceInfo s = p.surface(below, h);
  CHECK(s.p == Vec3(0.75, 0.25, 0));
  CHECK(s.ng == Vec3(0, 0, 1));  // (p1 − p0) × (p2 − p0) of the first corners
  CHECK_FALSE(s.hasUV);
  CHECK_FALSE(p.intersect(Ray(Vec3(0.75, 0.25, 1), Vec3(1, 0, 0)), h));  // parallel
  CrossingList cl;
  p.crossings(below, cl);
  REQUIRE(cl.items.size() == 1);
  CHECK(cl.items[0].entering);
  CHECK_FALSE(cl.startsInside);
  CHECK(p.bounds().lo == Vec3(-1, -1, 0));
  CHECK(p.bounds().hi == Vec3(1, 1, 0));
}

TEST_CASE("polygon: overlapping outlines by the even-odd rule", "[primitives][polygon]") {
  // Two squares overlapping in [0.5, 1] x [0, 1]: the overlap is outside.
  const Polygon p({{0, 0, 0},
                   {1, 0, 0},
                   {1, 1, 0},
                   {0, 1, 0},
                   {0, 0, 0},
                   {0.5, 0, 0},
                   {1.5, 0, 0},
                   {1.5, 1, 0},
                   {0.5, 1, 0},
                   {0.5, 0, 0}});
  CHECK(hits(p, Vec3(0.25, 0.5, 0)));
  CHECK_FALSE(hits(p, Vec3(0.75, 0.5, 0)));
  CHECK(hits(p, Vec3(1.25, 0.5, 0)));
  // A concave outline (an L): the notch is outside.
  const Polygon l({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}});
  CHECK(hits(l, Vec3(1.5, 0.5, 0)));
  CHECK(hits(l, Vec3(0.5, 1.5, 0)));
  CHECK_FALSE(hits(l, Vec3(1.5, 1.5, 0)));
}

TEST_CASE("polygon: a tilted polygon's hit distance against the plane's", "[primitives][polygon]") {
  // The plane x + 2y + 2z = 3 (unit normal (1, 2, 2)/3), a triangle in it.
  const Vec3 a(3, 0, 0), b(1, 1, 0), c(1, 0, 1);
  const Polygon p({a, b, c, a});
  const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
  CHECK_THAT(glm::dot(n, Vec3(1, 2, 2) / 3.0), WithinAbs(1.0, 1e-15));
  const Vec3 inside = (a + b + c) / 3.0;  // (5/3, 1/3, 1/3)
  const Vec3 origin(-1, -2, 0.5);
  const Vec3 dir = inside - origin;
  Hit h;
  REQUIRE(p.intersect(Ray(origin, dir), h));
  // Exact: (3 − n0·o) / (n0·d) with n0 = (1, 2, 2): (3 + 4) / 7 = 1.
  CHECK_THAT(h.t, WithinAbs(1.0, 1e-14));
  const SurfaceInfo s = p.surface(Ray(origin, dir), h);
  CHECK_THAT(glm::length(s.p - inside), WithinAbs(0.0, 1e-14));
  // Just outside the edge a–b.
  const Vec3 out = 0.5 * (a + b) + 1e-6 * (0.5 * (a + b) - c);  // away from c, in the plane
  CHECK_FALSE(p.intersect(Ray(origin, out - origin), h));
}
