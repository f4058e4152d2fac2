// The scene reader's tiles: POV-Ray's old checker of two textures, the first (layered when
// several are written) at the checker's value 1, tile2's at 0.
#include <catch2/catch.hpp>

#include "scene_read_support.h"

#include "sdl/scene_reader.h"

#include <variant>

using namespace lucent;

using sdltest::errorsOf;
using sdltest::readScene;

TEST_CASE("scene reader tiles: a checker material map, tile2's texture on the even cells",
          "[sdl][scene][texture][tiles]") {
  auto r = readScene(
      "sphere { 0, 1 texture { tiles {\n"
      "  texture { pigment { rgb <1, 0, 0> } }\n"
      "  texture { pigment { rgbt <0, 1, 0, 0.5> } }\n"
      "  tile2 texture { pigment { rgb <0, 0, 1> } finish { phong 1 } } } scale 2 } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  REQUIRE(s.root->children.at(0)->material);
  const Material& m = s.materials.at(*s.root->children[0]->material);
  REQUIRE(m.mapped());
  CHECK(std::holds_alternative<CheckerTexture>(m.mapPattern));
  REQUIRE(m.mapEntries.size() == 2);
  CHECK(m.mapEntries[0].at == 0.0);
  CHECK(m.mapEntries[0].material.diffuse.b > 0.0f);
  CHECK(m.mapEntries[0].material.phong.r > 0.0f);
  CHECK(m.mapEntries[1].at == 1.0);
  // The two first textures are layers: red below, the half-clear green on top.
  CHECK(m.mapEntries[1].material.diffuse.r > 0.0f);
  REQUIRE(m.mapEntries[1].material.layers.size() == 1);
  CHECK(m.mapEntries[1].material.layers[0].diffuse.g > 0.0f);
}

TEST_CASE("scene reader tiles: tile2 and both textures are needed",
          "[sdl][scene][texture][tiles]") {
  CHECK(errorsOf("sphere { 0, 1 texture { tiles { tile2 texture { pigment { rgb 1 } } } } }\n") ==
        std::vector<std::string>{
            "test.pov:1:25: error: the first texture is missing from tiles (POV-Ray's error)"});
  CHECK(errorsOf("sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } } } }\n") ==
        std::vector<std::string>{"test.pov:1:63: error: 'tile2' expected in tiles, not '}'"});
}
