// POV-Ray's transform functions, `function { transform { T } }`: the point moved, as
// transforms.inc's vtransform and vinv_transform use them while the scene is read.
#include <catch2/catch.hpp>

#include "scene_read_support.h"

using sdltest::errorsOf;
using sdltest::readScene;

TEST_CASE("transform function: vtransform and vinv_transform give POV-Ray's points",
          "[sdl][function]") {
  // POV-Ray 3.7's #debug output for this scene, to the digit.
  auto r = readScene(
      "#include \"transforms.inc\"\n"
      "#declare T = transform { rotate <10, 20, 30> scale <1, 2, 3> translate <4, 5, 6> }\n"
      "#declare P = vtransform(<1, 2, 3>, T);\n"
      "#declare Q = vinv_transform(P, T);\n"
      "#debug concat(vstr(3, P, \", \", 0, 6), \"  \", vstr(3, Q, \", \", 0, 6), \"\\n\")\n"
      "#declare F = function { transform { T } }\n"
      "#declare G = function { F(x, y, z).y + 1 }\n"
      "#debug concat(str(G(1, 2, 3), 0, 6), \" \", str(vlength(F(1, 0, 0)), 0, 6), \"\\n\")\n");
  REQUIRE(r->load.scene);
  CHECK(r->out.debugText ==
        "5.067425, 9.578119, 14.281744  1.000000, 2.000000, 3.000000\n"
        "10.578119 9.121002\n");
}

TEST_CASE("transform function: a vector, so a function takes one of its components",
          "[sdl][function][errors]") {
  const auto bare = errorsOf(
      "#declare F = function { transform { scale 2 } }\n"
      "#declare G = function { F(x, y, z) }\n");
  REQUIRE(bare.size() == 1);
  CHECK(bare[0].find("test.pov:2:25: error: 'F' is a transform function: it gives a vector") == 0);
  // In an isosurface Lucent's expressions cannot hold it.
  const auto iso = errorsOf(
      "#declare F = function { transform { scale 2 } }\n"
      "isosurface { function { F(x, y, z).x - 1 } }\n");
  REQUIRE(!iso.empty());
  CHECK(iso[0].find("is a transform function, which Lucent cannot evaluate in an isosurface") !=
        std::string::npos);
}
