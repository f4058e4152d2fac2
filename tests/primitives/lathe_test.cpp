#include "shape_checks.h"

#include "primitives/lathe.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace lucent;
using namespace lucent::test;
using Catch::Matchers::WithinAbs;

namespace {

// A cylinder of radius 1 from y = 0 to 1, as a linear lathe.
Lathe cylinder() { return Lathe(LatheSpline::Linear, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }

// One Bezier piece from the axis out and back: x(s) = 3.6·s·(1 − s), y(s) = 3s² − 2s³.
Lathe bulb() { return Lathe(LatheSpline::Bezier, {{0, 0}, {1.2, 0}, {1.2, 1}, {0, 1}}); }

}  // namespace

TEST_CASE("lathe: a linear cylinder is hit where the closed form says", "[primitives][lathe]") {
  const Lathe l = cylinder();
  Hit h;
  // Horizontal, through the axis: the side at x = 1 and x = -1.
  REQUIRE(l.intersect(Ray(Vec3(3, 0.5, 0), Vec3(-1, 0, 0)), h));
  CHECK_THAT(h.t, WithinAbs(2.0, 1e-14));
  SurfaceInfo s = l.surface(Ray(Vec3(3, 0.5, 0), Vec3(-1, 0, 0)), h);
  CHECK_THAT(s.ng.x, WithinAbs(1.0, 1e-14));
  // Down the axis: the top disc's centre (a pole of the curve) and the bottom.
  const Ray down(Vec3(0, 5, 0), Vec3(0, -2, 0));
  CrossingList cl;
  l.crossings(down, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(2.0, 1e-14));
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(2.5, 1e-14));
  CHECK(cl.items[0].entering);
  s = l.surface(down, cl.items[0].hit);
  CHECK_THAT(s.ng.y, WithinAbs(1.0, 1e-14));
  // A slanted ray: enters the top at (0.5, 1, 0), leaves the side.
  const Ray slant(Vec3(0.5, 2, 0), Vec3(0.1, -1, 0));
  REQUIRE(l.intersect(slant, h));
  CHECK_THAT(h.t, WithinAbs(1.0, 1e-14));
  l.crossings(slant, cl = {});
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(2.0, 1e-14));  // the bottom at x = 0.7
}

TEST_CASE("lathe: a tangent ray touches the silhouette without crossing", "[primitives][lathe]") {
  const Lathe l = cylinder();
  // Exactly tangent: at most a contact, an entering and a leaving crossing at one t (as a
  // sphere's tangent ray), never a chord.
  const Ray tangent(Vec3(1.0, 0.5, -3), Vec3(0, 0.1, 1));
  CrossingList cl;
  l.crossings(tangent, cl);
  REQUIRE(cl.items.size() % 2 == 0);
  if (!cl.items.empty()) {
    REQUIRE(cl.items.size() == 2);
    CHECK(cl.items[0].hit.t == cl.items[1].hit.t);
    CHECK_THAT(cl.items[0].hit.t, WithinAbs(3.0, 1e-6));
  }
  Hit h;
  CHECK(l.intersect(Ray(Vec3(0.999, 0.5, -3), Vec3(0, 0.1, 1)), h));
  CHECK_FALSE(l.intersect(Ray(Vec3(1.001, 0.5, -3), Vec3(0, 0.1, 1)), h));
}

TEST_CASE("lathe: rays at a joint's corner and at a closing disc's rim keep their crossings paired",
          "[primitives][lathe]") {
  // Found by the accuracy rows (docs/accuracy.md, "Lathes"): a ray clipping the corner of a
  // goblet's foot 4.5e-12 above the joint of its side and its bottom enters and leaves
  // 1.9e-12 apart (the two roots were once merged as one found on both pieces), and a ray
  // leaving a vase through its mouth's disc 4.4e-16 inside the rim must not also re-enter
  // through the curve's end.
  const Lathe goblet(LatheSpline::Linear, {{0, 0},
                                           {0.8, 0},
                                           {0.8, 0.1},
                                           {0.15, 0.2},
                                           {0.15, 0.9},
                                           {0.7, 1.4},
                                           {0.65, 1.45},
                                           {0.1, 1.0},
                                           {0, 1.0}});
  const Ray corner(Vec3(-1.5837306108095823, 1.3670464104817854, -2.5072915427154534),
                   Vec3(3.3803544680011766, -2.3485483187950038, 3.1016760177821525));
  CrossingList cl;
  goblet.crossings(corner, cl);
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].entering);
  CHECK_FALSE(cl.items[1].entering);
  CHECK_THAT(cl.items[1].hit.t - cl.items[0].hit.t, WithinAbs(1.92e-12, 0.05e-12));

  const Lathe vase(
      LatheSpline::Bezier,
      {{0, 0}, {0.9, 0}, {0.9, 0.3}, {0.6, 0.6}, {0.6, 0.6}, {0.3, 0.9}, {0.7, 1.2}, {0.5, 1.5}});
  const Ray mouth(Vec3(2.3839893870331932, 0.56673086531584094, 0.38972714487587279),
                  Vec3(-4.5673090762144568, 1.4985306982023796, -0.3129544260990334));
  vase.crossings(mouth, cl = {});
  REQUIRE(cl.items.size() == 2);
  CHECK(cl.items[0].entering);
  CHECK_FALSE(cl.items[1].entering);
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(0.6227894669116209, 1e-15));
}

TEST_CASE("lathe: a cone from an open linear profile closes with its base disc",
          "[primitives][lathe]") {
  const Lathe l(LatheSpline::Linear, {{0, 1}, {1, 0}});
  CHECK(l.inside(Vec3(0.2, 0.5, 0.1)));
  CHECK_FALSE(l.inside(Vec3(0.6, 0.5, 0)));
  CrossingList cl;
  l.crossings(Ray(Vec3(0.25, -1, 0), Vec3(0, 1, 0)), cl);
  REQUIRE(cl.items.size() == 2);
  CHECK_THAT(cl.items[0].hit.t, WithinAbs(1.0, 1e-14));   // the base
  CHECK_THAT(cl.items[1].hit.t, WithinAbs(1.75, 1e-14));  // y = 1 − x on the side
}

TEST_CASE("lathe: an open lathe has no closing disc, as POV-Ray's", "[primitives][lathe]") {
  // The cone of the test above, open: the ray up the axis side meets the slant alone.
  const Lathe l(LatheSpline::Linear, {{0, 1}, {1, 0}}, true);
  CHECK_FALSE(l.isSolid());
  const Ray up(Vec3(0.25, -1, 0), Vec3(0, 1, 0));
  Hit h;
  REQUIRE(l.intersect(up, h));
  CHECK_THAT(h.t, WithinAbs(1.75, 1e-14));
  // Its normal is the closed cone's: outward, up and away from the axis.
  const SurfaceInfo si = l.surface(up, h);
  CHECK_THAT(si.ng.x, WithinAbs(std::sqrt(0.5), 1e-12));
  CHECK_THAT(si.ng.y, WithinAbs(std::sqrt(0.5), 1e-12));
  CrossingList cl;
  l.crossings(up, cl);
  REQUIRE(cl.items.size() == 1);  // a surface: every crossing enters
  CHECK(cl.items[0].entering);
  CHECK_FALSE(cl.startsInside);
  // A cup without its lid (the curve from the axis out and up): seen from above, the ray
  // down the middle meets the bottom, not a disc at the rim.
  const Lathe cup(LatheSpline::Linear, {{0, 0}, {1, 0}, {1, 1}}, true);
  REQUIRE(cup.intersect(Ray(Vec3(0.5, 3, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(3.0, 1e-14));
  const Lathe lidded(LatheSpline::Linear, {{0, 0}, {1, 0}, {1, 1}});
  REQUIRE(lidded.intersect(Ray(Vec3(0.5, 3, 0), Vec3(0, -1, 0)), h));
  CHECK_THAT(h.t, WithinAbs(2.0, 1e-14));
}

TEST_CASE("lathe: a Bezier profile against its own curve", "[primitives][lathe]") {
  const Lathe l = bulb();
  // x(s) = 3.6·s·(1 − s), y(s) = 3s² − 2s³: at s = 0.5, x = 0.9, y = 0.5.
  Hit h;
  const Ray r(Vec3(-2, 0.5, 0), Vec3(1, 0, 0));
  REQUIRE(l.intersect(r, h));
  CHECK_THAT(h.t, WithinAbs(1.1, 1e-13));
  const SurfaceInfo s = l.surface(r, h);
  CHECK_THAT(s.ng.x, WithinAbs(-1.0, 1e-12));
  // A slanted ray through the point of s = 0.25: x = 0.675, y = 0.15625.
  const Vec3 p(0.675 * std::cos(0.3), 0.15625, 0.675 * std::sin(0.3));
  const Vec3 d = glm::normalize(Vec3(-0.3, 0.7, 0.2));
  CrossingList cl;
  l.crossings(Ray(p - 3.0 * d, d), cl);
  bool found = false;
  for (const Crossing& c : cl.items) found |= std::abs(c.hit.t - 3.0) < 1e-12;
  CHECK(found);
}

TEST_CASE("lathe: crossings alternate and agree with inside()", "[primitives][lathe]") {
  const std::vector<Lathe> shapes = {
      cylinder(), bulb(),
      Lathe(LatheSpline::Cubic,
            {{0, -0.2}, {0, 0}, {0.6, 0.1}, {0.9, 0.5}, {0.4, 1}, {0.6, 1.4}, {0, 1.5}, {0, 1.7}}),
      Lathe(LatheSpline::Quadratic, {{0, -1}, {0, -0.5}, {0.8, 0}, {0.5, 0.6}, {0, 1}})};
  Rng rng(7);
  int wrong = 0, total = 0;
  for (const Lathe& l : shapes)
    for (int i = 0; i < 2000; ++i) {
      const Ray ray = randomRayAt(rng, l.bounds());
      CHECK(intersectAgreesWithCrossings(l, ray) == "");
      CrossingList cl;
      l.crossings(Ray(ray.o, ray.d, -kInf, kInf), cl);
      // Midpoints between crossings are inside exactly when the list says so.
      for (size_t k = 0; k + 1 < cl.items.size(); ++k) {
        const double a = cl.items[k].hit.t, b = cl.items[k + 1].hit.t;
        if (b - a < 1e-6) continue;
        ++total;
        if (l.inside(ray.at(0.5 * (a + b))) != cl.items[k].entering) {
          ++wrong;
          if (wrong < 6)
            WARN("shape " << (&l - shapes.data()) << " k " << k << " of " << cl.items.size()
                          << " t " << a << " " << b);
        }
      }
    }
  CHECK(total > 1000);
  CHECK(wrong == 0);
}

TEST_CASE("lathe: a secondary ray leaving the surface does not hit it again at once",
          "[primitives][lathe]") {
  const Lathe l = bulb();
  Rng rng(11);
  int selfHits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray = randomRayAt(rng, l.bounds());
    Hit h;
    if (!l.intersect(ray, h)) continue;
    const SurfaceInfo s = l.surface(ray, h);
    const Vec3 off = s.p + s.ng * (4.0 * glm::length(s.pError));
    Hit h2;
    if (l.intersect(Ray(off, s.ng + 0.5 * randomUnit(rng) * 0.9), h2) && h2.t < 1e-9) ++selfHits;
  }
  CHECK(selfHits == 0);
}

TEST_CASE("lathe: bad point lists are refused", "[primitives][lathe]") {
  using V = std::vector<Vec2>;
  CHECK_THROWS_AS(Lathe(LatheSpline::Linear, V{{1, 0}}), std::invalid_argument);
  CHECK_THROWS_AS(Lathe(LatheSpline::Cubic, V{{1, 0}, {1, 1}, {1, 2}}), std::invalid_argument);
  CHECK_THROWS_AS(Lathe(LatheSpline::Bezier, V{{1, 0}, {1, 1}, {1, 2}, {0, 3}, {0, 4}}),
                  std::invalid_argument);
  CHECK_THROWS_AS(Lathe(LatheSpline::Linear, V{{-1, 0}, {1, 1}}), std::invalid_argument);
  CHECK_THROWS_AS(Lathe(LatheSpline::Linear, V{{1, 1}, {1, 1}}), std::invalid_argument);
}

TEST_CASE("lathe: rays through the axis and the poles against the closed form",
          "[primitives][lathe]") {
  const Lathe l = cylinder();
  Rng rng(5);
  for (int i = 0; i < 2000; ++i) {
    // From the axis inside, in every direction: one crossing, where the side or a cap is.
    const Vec3 o(0.0, uniform(rng, 0.05, 0.95), 0.0);
    const Vec3 d = randomUnit(rng);
    const double rxz = std::sqrt(d.x * d.x + d.z * d.z);
    const double tSide = rxz > 0.0 ? 1.0 / rxz : kInf;
    const double tCap = d.y > 0.0 ? (1.0 - o.y) / d.y : d.y < 0.0 ? -o.y / d.y : kInf;
    const double want = std::min(tSide, tCap);
    if (std::abs(tSide - tCap) < 1e-9) continue;  // the rim
    CrossingList cl;
    l.crossings(Ray(o, d), cl);
    CHECK(cl.startsInside);
    REQUIRE(cl.items.size() == 1);
    CHECK_THAT(cl.items[0].hit.t, WithinAbs(want, 1e-13 * (1.0 + want)));
    // Back along the line from outside, through both poles' rings: enters and leaves.
    const Ray back(o + 3.0 * d, -d);
    Hit h;
    REQUIRE(l.intersect(back, h));
    CHECK_THAT(h.t, WithinAbs(3.0 - want, 1e-12));
  }
}
