// <light><projected-through> read, written back and exported: the objects in the light's
// frame, placed with it; the bad forms are in tests/bad/cases.txt.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "scenegraph/node.h"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

using namespace lucent;
using namespace lucent::test;

TEST_CASE("a light's projected-through objects are read in its frame and placed with it",
          "[lang][projected-through]") {
  auto s = parseClean(
      "<light position=\"0 8 0\" transform=\"translate(-2 0 0)\"><projected-through>"
      "<repeat var=\"i\" count=\"2\"><sphere center=\"${i} 4 0\" radius=\"0.5\"/></repeat>"
      "<box min=\"-1 -1 -1\" max=\"1 1 1\"/></projected-through></light>");
  REQUIRE(s->lights.size() == 1);
  const Light& placed = s->lights[0];
  CHECK(placed.position == Vec3(-2, 8, 0));
  REQUIRE(placed.projectedThrough);
  const Node& group = *placed.projectedThrough;
  CHECK(group.kind == NodeKind::Group);
  REQUIRE(group.children.size() == 3);  // the repeat's two spheres and the box
  CHECK(group.children[1]->kind == NodeKind::Shape);
  // The light's frame: its transform, where the objects stand.
  CHECK(placed.worldFromLight == glm::translate(Mat4(1.0), Vec3(-2, 0, 0)));
}

TEST_CASE("a light without projected-through objects has none", "[lang][projected-through]") {
  auto s = parseClean("<light position=\"0 8 0\"/>");
  REQUIRE(s->lights.size() == 1);
  CHECK_FALSE(s->lights[0].projectedThrough);
}

TEST_CASE("projected-through objects are written and read back, uses and materials kept",
          "[lang][projected-through][scene-writer]") {
  const std::string first = writeSceneXml(
      *parseClean("<material id=\"red\" diffuse=\"1 0 0\"/>"
                  "<defs><torus id=\"ring\" major=\"1\" minor=\"0.1\"/></defs>"
                  "<light position=\"0 8 0\"><projected-through><use ref=\"ring\" "
                  "transform=\"translate(0 4 0)\"/><sphere radius=\"0.3\" material=\"red\"/>"
                  "</projected-through></light><sphere material=\"red\"/>",
                  "writer.xml"),
      WriteOptions{});
  INFO(first);
  CHECK(first.find("<projected-through>") != std::string::npos);
  CHECK(first.find("<use ref=\"ring\"") != std::string::npos);
  auto reread = parseSceneString(first, "writer.xml");
  INFO(messages(reread));
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
  REQUIRE(reread.scene->lights.size() == 1);
  REQUIRE(reread.scene->lights[0].projectedThrough);
  CHECK(reread.scene->lights[0].projectedThrough->children.size() == 2);
}

TEST_CASE("a <use> of the light inside its own projected-through objects is a cycle",
          "[lang][projected-through]") {
  ParseResult r = parseBody(
      "<defs><light id=\"lamp\" position=\"0 8 0\"><projected-through><group><use "
      "ref=\"lamp\"/><sphere/></group></projected-through></light></defs><use ref=\"lamp\"/>",
      "cycle.xml", "<camera/>");
  INFO(messages(r));
  CHECK(r.diagnostics.errorCount() >= 1);
  CHECK(messages(r).find("reference cycle") != std::string::npos);
}
