// CSG with discs and objects without an inside, as the scene reader rewrites it
// (sdl/open_operands.cpp): a disc's inside is the half-space below its plane, so the
// other operands are clipped by a <plane> and the disc by them; a rewritten operation
// keeps its inside for the operation around it; a clip by a disc is its half-space, by a
// polygon (inside nowhere) it leaves nothing; POV-Ray's box of a top-level intersection
// bounds it. Pixels against POV-Ray: scene_image_test (csg_discs.pov).
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::readScene;

const Node& topNode(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

template <class Spec>
const Spec* shapeOf(const Node& n) {
  return n.kind == NodeKind::Shape && n.shape ? std::get_if<Spec>(&*n.shape) : nullptr;
}

}  // namespace

TEST_CASE(
    "csg disc reader: an intersection with a disc is the solid cut by its half-space "
    "and the disc cut by the solid",
    "[sdl][scene][csg][disc]") {
  auto r = readScene("intersection { sphere { 0, 1 } disc { <0, 0.25, 0>, y, 0.9 } }\n");
  REQUIRE(r->load.scene);
  const Node& n = topNode(*r->load.scene, 0);
  CHECK(n.kind == NodeKind::Union);
  CHECK(n.element == "intersection");
  REQUIRE(n.children.size() == 2);
  const Node& sphere = *n.children[0];
  REQUIRE(shapeOf<SphereSpec>(sphere));
  REQUIRE(sphere.clip.size() == 1);
  const PlaneSpec* half = shapeOf<PlaneSpec>(*sphere.clip[0]);
  REQUIRE(half);
  CHECK_FALSE(sphere.clip[0]->inverse);  // inside: below the plane
  CHECK(half->normal.y == Approx(1.0));
  CHECK(half->offset == Approx(0.25));
  const Node& disc = *n.children[1];
  REQUIRE(shapeOf<DiscSpec>(disc));
  REQUIRE(disc.clip.size() == 1);
  CHECK(shapeOf<SphereSpec>(*disc.clip[0]));
  CHECK_FALSE(disc.clip[0]->inverse);
  // The disc's box (POV-Ray's, 0.002 thick) bounds what rays see: the sphere below the
  // disc shows only along rays that cross it.
  REQUIRE(n.bound.size() == 1);
  const BoxSpec* box = shapeOf<BoxSpec>(*n.bound[0]);
  REQUIRE(box);
  CHECK(box->min.y == Approx(0.249));
  CHECK(box->max.y == Approx(0.251));
  CHECK(box->min.x == Approx(-0.9));
  CHECK(box->max.x == Approx(0.9));
}

TEST_CASE(
    "csg disc reader: a difference keeps the solid above the disc and a merge the box "
    "above and the disc outside it",
    "[sdl][scene][csg][disc]") {
  auto r = readScene(
      "difference { sphere { 0, 1 } disc { 0, y, 0.9 } }\n"
      "merge { box { -1, 1 } disc { 0, y, 2 } }\n");
  REQUIRE(r->load.scene);
  const Node& d = topNode(*r->load.scene, 0);
  REQUIRE(d.children.size() == 2);
  REQUIRE(d.children[0]->clip.size() == 1);
  CHECK(shapeOf<PlaneSpec>(*d.children[0]->clip[0]));
  CHECK(d.children[0]->clip[0]->inverse);  // outside the half-space: above
  REQUIRE(d.children[1]->clip.size() == 1);
  CHECK_FALSE(d.children[1]->clip[0]->inverse);  // the disc inside the sphere
  CHECK(d.bound.empty());  // a difference's box is its first operand's: it holds both
  const Node& m = topNode(*r->load.scene, 1);
  REQUIRE(m.children.size() == 2);
  CHECK(m.children[0]->clip[0]->inverse);  // the box above the plane
  CHECK(shapeOf<BoxSpec>(*m.children[1]->clip[0]));
  CHECK(m.children[1]->clip[0]->inverse);  // the disc outside the box
}

TEST_CASE("csg disc reader: a rewritten operation keeps its inside as an operand",
          "[sdl][scene][csg][disc]") {
  // The capped sphere (inside: the sphere below y = 0.5) minus a box: the box's surface is
  // kept inside the capped sphere (the sphere and the half-space intersected), the capped
  // sphere's pieces outside the box.
  auto r = readScene(
      "difference {\n"
      "  intersection { sphere { 0, 1 } disc { <0, 0.5, 0>, y, 2 } }\n"
      "  box { 0, 2 }\n"
      "}\n");
  REQUIRE(r->load.scene);
  const Node& n = topNode(*r->load.scene, 0);
  CHECK(n.element == "difference");
  REQUIRE(n.children.size() == 2);
  const Node& box = *n.children[0];
  REQUIRE(shapeOf<BoxSpec>(box));
  REQUIRE(box.clip.size() == 1);
  const Node& capped = *box.clip[0];
  CHECK(capped.kind == NodeKind::Intersection);
  REQUIRE(capped.children.size() == 2);
  CHECK(shapeOf<SphereSpec>(*capped.children[0]));
  CHECK(shapeOf<PlaneSpec>(*capped.children[1]));
  CHECK_FALSE(capped.inverse);
  const Node& pieces = *n.children[1];
  CHECK(pieces.element == "intersection");
  REQUIRE(pieces.clip.size() == 1);
  CHECK(shapeOf<BoxSpec>(*pieces.clip[0]));
  CHECK(pieces.clip[0]->inverse);
}

TEST_CASE("csg disc reader: a clip by a disc is its half-space and by a polygon nothing is left",
          "[sdl][scene][clip][disc]") {
  auto r = readScene(
      "sphere { 0, 1 clipped_by { disc { <0, 0.5, 0>, -y, 1 } } translate x }\n"
      "sphere { 0, 1 clipped_by { polygon { 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> } } }\n"
      "box { -1, 1 }\n");
  REQUIRE(r->load.scene);
  REQUIRE(r->load.scene->root->children.size() == 2);  // the polygon-clipped sphere is gone
  const Node& n = topNode(*r->load.scene, 0);
  REQUIRE(n.clip.size() == 1);
  const PlaneSpec* half = shapeOf<PlaneSpec>(*n.clip[0]);
  REQUIRE(half);
  // Inside the disc's half-space: below its plane along its normal -y, so y > 0.5.
  CHECK(half->normal.y == Approx(-1.0));
  CHECK(half->offset == Approx(-0.5));
  CHECK(shapeOf<BoxSpec>(topNode(*r->load.scene, 1)));
}

TEST_CASE("csg disc reader: an inverse operation with a disc keeps the same surfaces",
          "[sdl][scene][csg][disc]") {
  // POV-Ray inverts each operand and makes the intersection a merge: the sphere above the
  // plane and the disc inside the sphere, as without inverse; its inside is swapped.
  auto r = readScene("difference { sphere { 0, 1 } disc { 0, y, 0.9 } inverse }\n");
  REQUIRE(r->load.scene);
  const Node& n = topNode(*r->load.scene, 0);
  CHECK_FALSE(n.inverse);
  REQUIRE(n.children.size() == 2);
  CHECK(n.children[0]->clip[0]->inverse);
  CHECK_FALSE(n.children[1]->clip[0]->inverse);
}

TEST_CASE(
    "csg disc reader: a disc that covers the cut closes it where POV-Ray frames the "
    "operation",
    "[sdl][scene][csg][disc]") {
  // desk.pov's paperweight: the sphere projects onto the plane within radius 10 < 10.1, so
  // the disc's half-space makes a closed solid (its glass refracts through the flat face).
  auto r = readScene(
      "intersection { sphere { <0, -5, 0>, 10 } disc { 0, -y, 10.1 } }\n"
      "intersection { sphere { <0, -5, 0>, 10 } disc { 0, -y, 9.9 } }\n"
      "difference { box { -1, 1 } intersection { sphere { 0, 1 } disc { 0, y, 2 } } }\n");
  REQUIRE(r->load.scene);
  const Node& covered = topNode(*r->load.scene, 0);
  CHECK(covered.kind == NodeKind::Intersection);
  REQUIRE(covered.children.size() == 2);
  const PlaneSpec* half = shapeOf<PlaneSpec>(*covered.children[1]);
  REQUIRE(half);
  CHECK(half->normal.y == Approx(-1.0));
  CHECK(half->offset == Approx(0.0));
  // POV-Ray's box of it (the sphere's met with the disc's, 0.002 thick) is its bound.
  REQUIRE(covered.bound.size() == 1);
  const BoxSpec* box = shapeOf<BoxSpec>(*covered.bound[0]);
  REQUIRE(box);
  CHECK(box->min.y == Approx(-0.001));
  CHECK(box->max.y == Approx(0.001));
  // A disc narrower than the sphere's section leaves the cut open: the rewritten union.
  const Node& open = topNode(*r->load.scene, 1);
  CHECK(open.kind == NodeKind::Union);
  CHECK(open.element == "intersection");
  // Within another operation the disc is not closed: the operation around it keeps the
  // box POV-Ray gives the rewritten one.
  const Node& nested = topNode(*r->load.scene, 2);
  CHECK(nested.element == "difference");
  CHECK(nested.kind == NodeKind::Union);
}

TEST_CASE("csg disc reader: an inverted union is the intersection of its parts inverted",
          "[sdl][scene][csg][disc]") {
  // POV-Ray inverts a difference's later union into an intersection of its parts inverted:
  // the inner box's surface is kept above the disc's plane only, the disc's outside the
  // inner box (each also inside the outer box).
  auto r = readScene(
      "difference { box { -1, 1 } union { disc { 0, y, 0.5 } box { <0.2, -1, -1>, <1, -0.2, 1> "
      "} } }\n");
  REQUIRE(r->load.scene);
  const Node& n = topNode(*r->load.scene, 0);
  REQUIRE(n.children.size() == 2);
  const Node& parts = *n.children[1];
  REQUIRE(parts.children.size() == 2);
  const Node& disc = *parts.children[0];
  const Node& inner = *parts.children[1];
  REQUIRE(shapeOf<DiscSpec>(disc));
  REQUIRE(disc.clip.size() == 1);
  CHECK(shapeOf<BoxSpec>(*disc.clip[0]));
  CHECK(disc.clip[0]->inverse);  // outside the inner box
  REQUIRE(shapeOf<BoxSpec>(inner));
  REQUIRE(inner.clip.size() == 1);
  CHECK(shapeOf<PlaneSpec>(*inner.clip[0]));
  CHECK(inner.clip[0]->inverse);  // above the disc's plane
  // The union itself is kept inside the outer box.
  REQUIRE(parts.clip.size() == 1);
  CHECK(shapeOf<BoxSpec>(*parts.clip[0]));
  CHECK_FALSE(parts.clip[0]->inverse);
}
