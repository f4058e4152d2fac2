// <clip> (POV-Ray's clipped_by) and <bound> (POV-Ray's bounded_by as POV-Ray applies it)
// through real scenes: hit distances and normals against exact values, the open shell a
// ray sees into through the cut, the inside test of a clipped solid in CSG (POV-Ray's:
// inside the shape and inside its clips), the clip moved by the node's transform, and the
// bound's test of the whole ray.
#include "../support/scene_text.h"
#include "first_hit.h"
#include "scenegraph/world.h"

#include <catch2/catch.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

void checkNormal(const Vec3& got, const Vec3& want) {
  CHECK(got.x == Approx(want.x).margin(1e-9));
  CHECK(got.y == Approx(want.y).margin(1e-9));
  CHECK(got.z == Approx(want.z).margin(1e-9));
}

// The unit sphere with only its lower half kept (y < 0).
const char* kLowerHalf = R"XML(
  <sphere radius="1"><clip><plane normal="0 1 0" offset="0"/></clip></sphere>)XML";

}  // namespace

TEST_CASE("clip: the surface is kept only inside the clip, at the shape's own distances",
          "[csg][clip]") {
  auto scene = parseClean(kLowerHalf);
  World world(*scene);
  const double h = std::sqrt(0.75);
  // y = -0.5 lies inside the clip: the sphere's own hit and outward normal.
  Seen below = look(world, Ray(Vec3(0, -0.5, -5), Vec3(0, 0, 1)));
  REQUIRE(below.found);
  CHECK(below.t == Approx(5.0 - h).epsilon(1e-12));
  checkNormal(below.ng, Vec3(0, -0.5, -h));
  // y = 0.5 lies outside it: both crossings of the sphere are cut away.
  CHECK_FALSE(look(world, Ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1))).found);
  // Shadow rays agree.
  CHECK(world.occluded(Ray(Vec3(0, -0.5, -5), Vec3(0, 0, 1), 0.0, 10.0)));
  CHECK_FALSE(world.occluded(Ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1), 0.0, 10.0)));
}

TEST_CASE("clip: an open shell, a ray entering through the cut sees the inside surface",
          "[csg][clip]") {
  auto scene = parseClean(kLowerHalf);
  World world(*scene);
  // Straight down from above: the upper half is gone and the cut is not closed, so the
  // first surface is the bottom of the bowl, its outward normal facing away from the ray.
  Seen s = look(world, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)));
  REQUIRE(s.found);
  CHECK(s.t == Approx(6.0).epsilon(1e-12));
  checkNormal(s.ng, Vec3(0, -1, 0));
}

TEST_CASE("clip: inside a clipped solid is inside its clips too, in CSG as in POV-Ray",
          "[csg][clip]") {
  // The clipped sphere intersected with a box that ends at z = 0.25.
  auto scene = parseClean(R"XML(
    <intersection>
      <sphere radius="1"><clip><plane normal="0 1 0" offset="0"/></clip></sphere>
      <box min="-2 -2 -2" max="2 2 0.25"/>
    </intersection>)XML");
  World world(*scene);
  // At y = 0.5 the box's face z = 0.25 is inside the sphere but outside the clip: not part
  // of the intersection (were the clip only a filter of surfaces, the face would show).
  CHECK_FALSE(look(world, Ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1))).found);
  // At y = -0.5 the sphere's front, then from inside the box's face at t = 0.25.
  Seen front = look(world, Ray(Vec3(0, -0.5, -5), Vec3(0, 0, 1)));
  REQUIRE(front.found);
  CHECK(front.t == Approx(5.0 - std::sqrt(0.75)).epsilon(1e-12));
  Seen face = look(world, Ray(Vec3(0, -0.5, 0), Vec3(0, 0, 1)));
  REQUIRE(face.found);
  CHECK(face.t == Approx(0.25).epsilon(1e-12));
  checkNormal(face.ng, Vec3(0, 0, 1));
  // From above, through the cut: the clip's plane bounds the intersection but shows
  // nothing; the bowl's bottom does.
  Seen down = look(world, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0)));
  REQUIRE(down.found);
  CHECK(down.t == Approx(6.0).epsilon(1e-12));
  checkNormal(down.ng, Vec3(0, -1, 0));
}

TEST_CASE("clip: a clipped subtrahend keeps its clip, as POV-Ray's inverted object does",
          "[csg][clip]") {
  // POV-Ray's difference is the intersection with the later operands inverted, and an
  // inverted clipped object is inside where it is inside its clip and outside its shape:
  // a slab minus the sphere clipped to y < 0 is what of the slab lies below y = 0 and
  // outside the sphere. Where the clip bounds it no surface is drawn.
  auto scene = parseClean(R"XML(
    <difference>
      <box min="-2 -0.5 -2" max="2 0.5 2"/>
      <sphere radius="1"><clip><plane normal="0 1 0" offset="0"/></clip></sphere>
    </difference>)XML");
  World world(*scene);
  // Beside the sphere, straight down: the slab's top (outside the clip) is gone and the
  // cut at y = 0 shows nothing: the first surface is the slab's bottom, seen from inside.
  Seen side = look(world, Ray(Vec3(1.5, 5, 0), Vec3(0, -1, 0)));
  REQUIRE(side.found);
  CHECK(side.t == Approx(5.5).epsilon(1e-12));
  checkNormal(side.ng, Vec3(0, -1, 0));
  // From the side at y = -0.25: the slab's face x = -2, then the sphere's surface (its
  // normal flipped to face out of the result) where the ray enters the hole.
  Seen face = look(world, Ray(Vec3(-5, -0.25, 0), Vec3(1, 0, 0)));
  REQUIRE(face.found);
  CHECK(face.t == Approx(3.0).epsilon(1e-12));
  Seen hole = look(world, Ray(Vec3(-1.5, -0.25, 0), Vec3(1, 0, 0)));
  REQUIRE(hole.found);
  const double x = std::sqrt(1.0 - 0.0625);
  CHECK(hole.t == Approx(1.5 - x).epsilon(1e-12));
  checkNormal(hole.ng, Vec3(x, 0.25, 0));
  // Down the axis nothing is met: the sphere fills the slab's height below the clip.
  CHECK_FALSE(look(world, Ray(Vec3(0, 5, 0), Vec3(0, -1, 0))).found);
}

TEST_CASE("clip: the node's transform moves its clip with it", "[csg][clip]") {
  auto scene = parseClean(R"XML(
    <sphere radius="1" transform="translate(0 2 0)">
      <clip><plane normal="0 1 0" offset="0"/></clip>
    </sphere>)XML");
  World world(*scene);
  // Kept where y < 2 in the world.
  Seen s = look(world, Ray(Vec3(0, 1.5, -5), Vec3(0, 0, 1)));
  REQUIRE(s.found);
  CHECK(s.t == Approx(5.0 - std::sqrt(0.75)).epsilon(1e-12));
  CHECK_FALSE(look(world, Ray(Vec3(0, 2.5, -5), Vec3(0, 0, 1))).found);
}

TEST_CASE("clip: several solids clip as their intersection", "[csg][clip]") {
  auto scene = parseClean(R"XML(
    <sphere radius="1">
      <clip><plane normal="0 1 0" offset="0"/><plane normal="1 0 0" offset="0"/></clip>
    </sphere>)XML");
  World world(*scene);
  CHECK(look(world, Ray(Vec3(-0.5, -0.5, -5), Vec3(0, 0, 1))).found);
  CHECK_FALSE(look(world, Ray(Vec3(0.5, -0.5, -5), Vec3(0, 0, 1))).found);
  CHECK_FALSE(look(world, Ray(Vec3(-0.5, 0.5, -5), Vec3(0, 0, 1))).found);
}

TEST_CASE("bound: the object is searched only along rays that meet the bound", "[csg][bound]") {
  // The unit sphere bounded by a sphere of radius 0.5 inside it.
  auto scene = parseClean(R"XML(
    <sphere radius="1"><bound><sphere radius="0.5"/></bound></sphere>)XML");
  World world(*scene);
  // A ray that misses the bound misses the object, though it crosses the object.
  CHECK_FALSE(look(world, Ray(Vec3(0, 0.8, -5), Vec3(0, 0, 1))).found);
  CHECK_FALSE(world.occluded(Ray(Vec3(0, 0.8, -5), Vec3(0, 0, 1), 0.0, 10.0)));
  // One that meets it sees the whole object, its surface outside the bound too: the
  // bound is a test of the ray, not a cut of the surface.
  const Vec3 o(0, 0.9, -5), d(0, -0.09, 1);
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
  const double t = (-b - std::sqrt(b * b - a * c)) / a;
  REQUIRE(glm::length(o + t * d) > 0.99);  // the hit lies far outside the bound
  Seen s = look(world, Ray(o, d));
  REQUIRE(s.found);
  CHECK(s.t == Approx(t).epsilon(1e-12));
  // A ray that starts inside the bound is let through, whichever way it goes.
  Seen out = look(world, Ray(Vec3(0, 0, 0), Vec3(0, 1, 0)));
  REQUIRE(out.found);
  CHECK(out.t == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("bound: in CSG a bounded solid the ray is turned from still counts inside",
          "[csg][bound]") {
  // POV-Ray's inside test ignores bounds: the box's face inside the bounded sphere is part
  // of the intersection even along a ray that misses the bound (the sphere's own surface
  // is not reported there).
  auto scene = parseClean(R"XML(
    <intersection>
      <sphere radius="1"><bound><sphere radius="0.5"/></bound></sphere>
      <box min="-2 -2 -2" max="2 2 0.25"/>
    </intersection>)XML");
  World world(*scene);
  Seen s = look(world, Ray(Vec3(0, 0.8, -5), Vec3(0, 0, 1)));
  REQUIRE(s.found);
  CHECK(s.t == Approx(5.25).epsilon(1e-12));
  checkNormal(s.ng, Vec3(0, 0, 1));
}

TEST_CASE("clip: an unbounded shape clipped to a turned slab of a cylinder gets a finite box",
          "[csg][clip]") {
  // POV-Ray's Helix (shapesq.inc): a quartic clipped by Cylinder_Z scaled by 2 and the slab
  // 0 <= z <= 1.4142, then turned: only in the clip's own frame are the planes square to
  // its axes, so the box is met there and carried to the world.
  // The helix's quartic, clipped; TRANSFORM its placement.
  auto helix = [](const std::string& transform) {
    return R"XML(<poly order="4" transform=")XML" + transform + R"XML("
          coefficients="0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 -0.1666 0 1 0 0 0 0 0 0 0 0 0.5 0 -1 0 0 0 0 0">
      <clip>
        <quadric a="1 1 0" b="0 0 0" c="0 0 0" d="-1" transform="scale(2)"/>
        <plane normal="0 0 1" offset="1.4142"/>
        <plane normal="0 0 -1" offset="0"/>
      </clip>
    </poly>)XML";
  };
  auto scene = parseClean(helix("rotate-z(160) rotate-x(-90) translate(0 -2 5)") +
                          R"XML(<sphere center="0 -1.5 5" radius="0.1"/>)XML");
  World world(*scene);
  // Both in the tree (a lone object would be tested directly), the clipped quartic with the
  // box of the slab's square [-2, 2]² x [0, 1.4142] turned by 160 degrees about z (half-width
  // 2·(|cos 160°| + |sin 160°|)), turned about x (z to y) and moved.
  REQUIRE(world.bvh().itemCount() == 2);
  const AABB b = world.bvh().bounds();
  REQUIRE(b.isBounded());
  const double reach =
      2.0 * (std::abs(std::cos(glm::radians(160.0))) + std::abs(std::sin(glm::radians(160.0))));
  CHECK(b.lo.x >= -reach - 1e-6);
  CHECK(b.hi.x <= reach + 1e-6);
  CHECK(b.lo.y >= -2.0 - 1e-6);
  CHECK(b.hi.y <= -2.0 + 1.4142 + 1e-6);
  CHECK(b.lo.z >= 5.0 - reach - 1e-6);
  CHECK(b.hi.z <= 5.0 + reach + 1e-6);
  // The same object without the turn and the move: the same hits in its own frame as the
  // turned one at the turned rays (the box changes where the search looks, not what it finds).
  auto plain = parseClean(helix("scale(1)"));
  World plainWorld(*plain);
  const Mat4 place = glm::translate(Mat4(1.0), Vec3(0, -2, 5)) *
                     glm::rotate(Mat4(1.0), glm::radians(-90.0), Vec3(1, 0, 0)) *
                     glm::rotate(Mat4(1.0), glm::radians(160.0), Vec3(0, 0, 1));
  int hits = 0;
  for (int i = 0; i < 21; ++i)
    for (int j = 0; j < 21; ++j) {
      const Vec3 o(-2.0 + 0.2 * i, 3.0, -1.0 + 0.1 * j);  // from above the slab, in its frame
      const Vec3 d = glm::normalize(Vec3(0.1, -1.0, 0.05));
      Seen own = look(plainWorld, Ray(o, d));
      Seen turned = look(world, Ray(Vec3(place * Vec4(o, 1.0)), Vec3(place * Vec4(d, 0.0))));
      REQUIRE(own.found == turned.found);
      if (!own.found) continue;
      ++hits;
      CHECK(turned.t == Approx(own.t).epsilon(1e-9));
    }
  CHECK(hits > 20);
}
