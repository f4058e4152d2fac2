// Faces written backwards are turned over to agree with their neighbours, and the parser
// says so in a warning at the <mesh> element; a mesh that needed nothing, or one written
// inside-out as a whole (only its global orientation is chosen), gives no warning.
#include "mesh_test_support.h"

#include "../support/paths.h"
#include "lang/parser.h"

#include <fmt/format.h>

#include <fstream>
#include <set>
#include <sstream>

using namespace lucent;
using namespace lucent::meshtest;

namespace {

// The gallery's icosahedron (counter-clockwise seen from outside) with the faces in
// `backwards` written clockwise.
std::string icosahedronOff(const std::set<int>& backwards, bool insideOut = false) {
  std::ifstream in(std::string(lucentSourceDir()) + "/examples/gallery/meshes/icosahedron.off");
  std::string line, out;
  int face = 0;
  while (std::getline(in, line)) {
    int n = 0, a = 0, b = 0, c = 0;
    std::istringstream words(line);
    if (line.rfind("3 ", 0) == 0 && (words >> n >> a >> b >> c)) {
      if (backwards.count(face++) != insideOut) std::swap(b, c);
      line = fmt::format("3 {} {} {}", a, b, c);
    }
    out += line + "\n";
  }
  REQUIRE(face == 20);
  return out;
}

std::vector<std::string> diagnosticsOf(const std::string& scene) {
  ParseResult r = parseSceneFile(scene);
  std::vector<std::string> all;
  for (const Diagnostic& d : r.diagnostics.all()) all.push_back(d.str());
  REQUIRE(r.scene != nullptr);  // a warning never refuses the scene
  return all;
}

const char* kSceneWithFile = R"(<scene version="1">
  <camera/>
  <mesh src="ico.off"/>
</scene>
)";

}  // namespace

TEST_CASE("a closed mesh with a face written backwards is repaired with a located warning",
          "[mesh][lang]") {
  TempDir dir;
  const std::string scene = dir.write("scene.xml", kSceneWithFile);
  const std::string at = scene + ":3:3: warning: <mesh src=\"ico.off\">: ";

  SECTION("one face") {
    dir.write("ico.off", icosahedronOff({7}));
    CHECK(diagnosticsOf(scene) ==
          std::vector<std::string>{at +
                                   "1 of 20 triangles was flipped to agree with its neighbours; "
                                   "the mesh is closed and is used as a solid"});
  }
  SECTION("three faces, whichever face CGAL starts from") {
    // Faces 0 and 1 share an edge, so the first face CGAL meets may well be a wrong one.
    dir.write("ico.off", icosahedronOff({0, 1, 12}));
    CHECK(diagnosticsOf(scene) ==
          std::vector<std::string>{at +
                                   "3 of 20 triangles were flipped to agree with their neighbours; "
                                   "the mesh is closed and is used as a solid"});
  }
  SECTION("the same three faces in a mesh written inside-out: the other 17 are the odd ones") {
    dir.write("ico.off", icosahedronOff({0, 1, 12}, /*insideOut=*/true));
    CHECK(diagnosticsOf(scene) ==
          std::vector<std::string>{at +
                                   "3 of 20 triangles were flipped to agree with their neighbours; "
                                   "the mesh is closed and is used as a solid"});
  }
  SECTION("a clean mesh, and one inside-out as a whole, give no warning") {
    dir.write("ico.off", icosahedronOff({}));
    CHECK(diagnosticsOf(scene).empty());
    dir.write("ico.off", icosahedronOff({}, /*insideOut=*/true));
    CHECK(diagnosticsOf(scene).empty());
  }
}

TEST_CASE("an inline mesh with a triangle written backwards is repaired with a located warning",
          "[mesh][lang]") {
  TempDir dir;
  // The octahedron of docs/scene-language.md with its second triangle (2 1 4) reversed.
  const std::string scene = dir.write("scene.xml", R"(<scene version="1">
  <camera/>
  <mesh positions="1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1"
        indices="0 2 4  2 4 1  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  0 3 5"/>
</scene>
)");
  CHECK(diagnosticsOf(scene) ==
        std::vector<std::string>{scene +
                                 ":3:3: warning: <mesh>: 1 of 8 triangles was flipped to agree "
                                 "with its neighbours; the mesh is closed and is used as a solid"});
}

TEST_CASE("an open mesh with a face written backwards is repaired with a warning too",
          "[mesh][lang]") {
  TempDir dir;
  // Two squares of a strip, the second one's triangles clockwise.
  dir.write("strip.obj",
            "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
            "f 1 2 5 4\nf 2 5 6 3\n");
  const std::string scene = dir.write("scene.xml", R"(<scene version="1">
  <camera/>
    <mesh src="strip.obj"/>
</scene>
)");
  CHECK(diagnosticsOf(scene) ==
        std::vector<std::string>{scene +
                                 ":3:5: warning: <mesh src=\"strip.obj\">: 1 of 2 faces was "
                                 "flipped to agree with its neighbours"});
}
