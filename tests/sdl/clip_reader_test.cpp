// clipped_by and bounded_by read by the scene reader (sdl/read_objects.cpp): the clip in the
// object's frame, moved by the transforms written after it only; the two linked by
// `clipped_by { bounded_by }` and the reverse; the bounds POV-Ray keeps (in CSG it keeps
// whole, and on a top-level CSG, poly, text or quadric), those it drops and the box it
// keeps of them; bad input located.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/pov_space.h"
#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::checkMat;
using sdltest::checkVec;
using sdltest::errorsOf;
using sdltest::readScene;

const Node& topNode(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

}  // namespace

TEST_CASE("clip reader: a clip follows only the transforms written after it",
          "[sdl][scene][clip]") {
  auto r = readScene(R"(
sphere { 0, 1 translate x clipped_by { plane { y, 0 } translate 3*z } translate 2*y }
)");
  REQUIRE(r->load.scene);
  const Node& n = topNode(*r->load.scene, 0);
  checkMat(n.parentFromNode, PovTransform::translation(Vec3(1, 2, 0)).lucentMatrix());
  REQUIRE(n.clip.size() == 1);
  const Node& plane = *n.clip[0];
  REQUIRE(plane.shape);
  CHECK(std::holds_alternative<PlaneSpec>(*plane.shape));
  // In the world the plane is moved by its own translate and the sphere's later one, not
  // by the sphere's earlier translate x.
  checkMat(n.parentFromNode * plane.parentFromNode,
           PovTransform::translation(Vec3(0, 2, 3)).lucentMatrix());
  CHECK(n.bound.empty());
}

TEST_CASE("clip reader: several objects clip as one list, clipped_by blocks add up",
          "[sdl][scene][clip]") {
  auto r = readScene(R"(
sphere { 0, 1 clipped_by { plane { y, 0 } plane { x, 0 } } clipped_by { box { -1, 1 } } }
)");
  REQUIRE(r->load.scene);
  CHECK(topNode(*r->load.scene, 0).clip.size() == 3);
}

TEST_CASE("clip reader: bounded_by is kept where POV-Ray tests rays against it",
          "[sdl][scene][clip]") {
  auto r = readScene(R"(
sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } }
quartic { <1,0,0,0,0,0,0,0,0,-1, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,1,0,0,0,0, 0,0,1,0,0>
  bounded_by { sphere { 0, 2 } } }
merge { sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } sphere { x, 1 } }
union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, 1 } } }
sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }
sphere { 0, 1 clipped_by { box { -1, 1 } } bounded_by { clipped_by } }
sphere { 0, 1 bounded_by { box { -2, 2 } } translate x }
union { sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } sphere { x, 1 } }
union { sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } sphere { x, 1 } translate y }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  // A top-level sphere's bounds are dropped as unnecessary, but their box, smaller than
  // the sphere's, stays its bounding box: a box bound in the world.
  const Node& sphere = topNode(s, 0);
  REQUIRE(sphere.bound.size() == 1);
  const Node& box = *sphere.bound[0];
  REQUIRE(box.shape);
  REQUIRE(std::holds_alternative<BoxSpec>(*box.shape));
  checkVec(std::get<BoxSpec>(*box.shape).min, Vec3(-0.5));
  checkVec(std::get<BoxSpec>(*box.shape).max, Vec3(0.5));
  checkMat(sphere.parentFromNode * box.parentFromNode, Mat4(1.0));
  // A poly's are kept.
  CHECK(topNode(s, 1).bound.size() == 1);
  // An operand's are kept where POV-Ray keeps the operation whole.
  REQUIRE(topNode(s, 2).children.at(0)->bound.size() == 1);
  CHECK(topNode(s, 2).children.at(0)->bound[0]->element == "sphere");
  // A union's are kept.
  CHECK(topNode(s, 3).bound.size() == 1);
  // Linked with the clip: the clip alone (every point it keeps lies in the bounds).
  CHECK(topNode(s, 4).clip.size() == 1);
  CHECK(topNode(s, 4).bound.empty());
  CHECK(topNode(s, 5).clip.size() == 1);
  CHECK(topNode(s, 5).bound.empty());
  // A box larger than the sphere's own: POV-Ray keeps the sphere's, nothing is cut.
  CHECK(topNode(s, 6).bound.empty());
  // A union without clip or bounds is split into objects of their own: its operand's
  // bounds are dropped as a top-level sphere's, their box kept.
  REQUIRE(topNode(s, 7).children.at(0)->bound.size() == 1);
  CHECK(topNode(s, 7).children.at(0)->bound[0]->element == "box");
  // Unless the union moves it afterwards: POV-Ray computes the sphere's box again.
  CHECK(topNode(s, 8).children.at(0)->bound.empty());
}

TEST_CASE("clip reader: bad clipped_by and bounded_by are errors at their place",
          "[sdl][scene][clip]") {
  CHECK(errorsOf("sphere { 0, 1 clipped_by { } }") ==
        std::vector<std::string>{
            "test.pov:1:28: error: clipped_by needs at least one object, not '}'"});
  CHECK(errorsOf("sphere { 0, 1 clipped_by { box { -1, 1 } } bounded_by { clipped_by } "
                 "bounded_by { box { -1, 1 } } }") ==
        std::vector<std::string>{
            "test.pov:1:70: error: cannot add bounds after linking bounds and clips"});
  CHECK(errorsOf("sphere { 0, 1 bounded_by { box { -1, 1 } } bounded_by { clipped_by } }") ==
        std::vector<std::string>{"test.pov:1:57: error: cannot link clips with previous bounds"});
  CHECK(errorsOf("sphere { 0, 1 clipped_by { box { -1, 1 } pigment { rgb 1 } } }") ==
        std::vector<std::string>{"test.pov:1:42: error: an object or a transform expected in "
                                 "clipped_by, not 'pigment'"});
}
