// <light-group global-lights>: read into the Node (a group with lightGroup set), its lights
// placed with the number of their group's instance (scenegraph/light_group.h), and written
// back by `lucent convert`.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kBody =
    "<light position=\"0 9 0\"/>"
    "<light-group global-lights=\"true\" transform=\"translate(1 0 0)\">"
    "<light position=\"0 5 0\" color=\"1 0 0\"/><sphere/>"
    "<light-group><light position=\"0 5 0\"/><group><light position=\"1 1 1\"/><box/></group>"
    "</light-group></light-group>"
    "<defs><light id=\"l\" position=\"2 2 2\"/></defs>"
    "<light-group><use ref=\"l\"/><sphere/></light-group>";

}  // namespace

TEST_CASE("lang: light-group is read with global-lights and its lights are numbered",
          "[lang][light-group]") {
  auto s = parseClean(kBody);
  const auto& top = s->root->children;
  REQUIRE(top.size() == 2);
  CHECK(top[0]->element == "light-group");
  CHECK(top[0]->kind == NodeKind::Group);
  CHECK(top[0]->lightGroup);
  CHECK(top[0]->globalLights);
  REQUIRE(top[0]->children.size() == 3);
  CHECK(top[0]->children[2]->lightGroup);
  CHECK_FALSE(top[0]->children[2]->globalLights);  // the default
  // The top-level light, then the first group's, the nested group's own, the light deeper
  // in it (global), and the <use> of a light in the third group.
  REQUIRE(s->lights.size() == 5);
  CHECK(s->lights[0].group == 0);
  CHECK(s->lights[1].group == 1);
  CHECK(s->lights[1].position == Vec3(1, 5, 0));  // moved with its group
  CHECK(s->lights[2].group == 2);
  CHECK(s->lights[3].group == 0);
  CHECK(s->lights[4].group == 3);
}

TEST_CASE("lang: convert writes light-group and global-lights back", "[lang][light-group]") {
  auto s = parseClean(kBody);
  const std::string text = writeSceneXml(*s, WriteOptions{});
  INFO(text);
  CHECK(text.find("<light-group global-lights=\"true\"") != std::string::npos);
  ParseResult again = parseSceneString(text, "again.xml");
  INFO(messages(again));
  REQUIRE(again.scene);
  REQUIRE(again.scene->lights.size() == 5);
  for (size_t i = 0; i < 5; ++i) CHECK(again.scene->lights[i].group == s->lights[i].group);
  CHECK(withoutComments(writeSceneXml(*again.scene, WriteOptions{})) == withoutComments(text));
}

TEST_CASE("lang: global-lights belongs to light-group alone", "[lang][light-group]") {
  ParseResult r = parseBody("<group global-lights=\"true\"><sphere/></group>", "lg.xml");
  CHECK(r.diagnostics.errorCount() == 1);
  ParseResult bad =
      parseBody("<light-group global-lights=\"yes\"><sphere/></light-group>", "lg.xml");
  CHECK(bad.diagnostics.errorCount() == 1);
}
