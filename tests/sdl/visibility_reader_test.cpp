// no_image, no_reflection, double_illuminate, no_radiosity and interior_texture read by the
// scene reader (sdl/read_objects.cpp): the flags with their optional on/off value, on
// shapes and CSG; interior_texture as a material of its own (with the object's interior),
// inherited by the operands, refused without a texture as POV-Ray refuses it.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

void checkColor(const Color& got, const Color& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-6));
}

const Node& topNode(const Scene& scene, size_t i) {
  REQUIRE(scene.root->children.size() > i);
  return *scene.root->children[i];
}

}  // namespace

TEST_CASE("visibility reader: no_image, no_reflection and double_illuminate with their values",
          "[sdl][scene][visibility]") {
  auto r = readScene(R"(
sphere { 0, 1 no_image }
sphere { 0, 1 no_reflection double_illuminate }
sphere { 0, 1 no_image off no_reflection 0 double_illuminate false no_radiosity }
union { sphere { 0, 1 } box { 0, 1 no_image } no_reflection }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  CHECK_FALSE(topNode(s, 0).image);
  CHECK(topNode(s, 0).reflection);
  CHECK_FALSE(topNode(s, 0).doubleIlluminate);
  CHECK(topNode(s, 1).image);
  CHECK_FALSE(topNode(s, 1).reflection);
  CHECK(topNode(s, 1).doubleIlluminate);
  CHECK(topNode(s, 2).image);
  CHECK(topNode(s, 2).reflection);
  CHECK_FALSE(topNode(s, 2).doubleIlluminate);
  const Node& u = topNode(s, 3);
  CHECK_FALSE(u.reflection);
  REQUIRE(u.children.size() == 2);
  CHECK(u.children[0]->image);
  CHECK_FALSE(u.children[1]->image);
}

TEST_CASE("visibility reader: interior_texture is a material of its own with the interior",
          "[sdl][scene][visibility]") {
  auto r = readScene(R"(
sphere { 0, 1
  texture { pigment { rgb <0, 0, 1> } }
  interior_texture { pigment { rgb <1, 1, 0> } finish { ambient 0 diffuse 0.5 } }
  interior { ior 1.5 }
}
difference {
  sphere { 0, 1 } box { 0, 2 }
  material { texture { pigment { rgb 1 } } interior_texture { pigment { rgb <1, 0, 0> } } }
}
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const Node& ball = topNode(s, 0);
  REQUIRE(ball.material);
  REQUIRE(ball.interiorMaterial);
  const Material& outside = s.materials.at(*ball.material);
  const Material& inside = s.materials.at(*ball.interiorMaterial);
  checkColor(outside.diffuse, Color(0.0f, 0.0f, 0.6f));
  checkColor(inside.diffuse, Color(0.5f, 0.5f, 0.0f));
  checkColor(inside.ambient, Color(0.0f));
  CHECK(inside.ior == 1.5);
  const Node& d = topNode(s, 1);
  REQUIRE(d.interiorMaterial);
  checkColor(s.materials.at(*d.interiorMaterial).diffuse, Color(0.6f, 0.0f, 0.0f));
  for (const auto& c : d.children) CHECK(!c->interiorMaterial);  // inherited
}

TEST_CASE("visibility reader: interior_texture without a texture is refused",
          "[sdl][scene][visibility]") {
  const auto errors = errorsOf("sphere { 0, 1 interior_texture { pigment { rgb 1 } } }\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        "test.pov:1:15: error: 'interior_texture' needs a texture of the object's own, as in "
        "POV-Ray");
}
