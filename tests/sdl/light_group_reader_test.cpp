// light_group read by the scene reader (sdl/read_objects.cpp): a <light-group> node with its
// light sources and objects, global_lights with its optional value, its transforms moving
// its lights; any other modifier refused as POV-Ray refuses it.
#include <catch2/catch.hpp>

#include "scene_read_support.h"
#include "sdl_test_support.h"

#include "sdl/scene_reader.h"

using namespace lucent;
using namespace lucent::sdl;

namespace {

using sdltest::errorsOf;
using sdltest::readScene;

}  // namespace

TEST_CASE("light_group reader: lights, objects, global_lights and transforms",
          "[sdl][scene][light-group]") {
  auto r = readScene(R"(
light_source { <0, 9, 0> rgb 1 }
light_group {
  light_source { <0, 5, 0> rgb <1, 0, 0> }
  sphere { 0, 1 }
  light_group { light_source { <0, 5, 0> rgb 1 } box { 0, 1 } global_lights }
  translate x
  global_lights off
}
#declare G = light_group { light_source { <0, 5, 0> rgb 1 } sphere { 0, 1 } global_lights on }
object { G }
)");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  std::vector<const Node*> groups;
  for (const auto& n : s.root->children)
    if (n->lightGroup) groups.push_back(n.get());
  REQUIRE(groups.size() == 2);  // object { G } is the declared light group
  CHECK_FALSE(groups[0]->globalLights);
  CHECK(groups[1]->globalLights);
  REQUIRE(s.lights.size() == 4);
  CHECK(s.lights[0].group == 0);
  CHECK(s.lights[1].group == 1);
  CHECK(s.lights[1].position.x == Approx(1.0));  // translate x moves the group's light
  CHECK(s.lights[2].group == 2);
  CHECK(s.lights[3].group == 3);
}

TEST_CASE("light_group reader: a modifier POV-Ray refuses there", "[sdl][scene][light-group]") {
  auto errors = errorsOf("light_group { light_source { 0, 1 } sphere { 0, 1 } pigment { rgb 1 } }");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].find("test.pov:1:53: error: a transform or global_lights expected in "
                       "light_group, not 'pigment'") != std::string::npos);
}
