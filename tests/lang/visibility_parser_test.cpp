// image, reflection, double-illuminate and interior-material on geometry nodes: read into
// the Node on every kind of node; image="false" or reflection="false" on a part of a merge,
// intersection or difference is a warning; `lucent convert` writes them back.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

ParseResult parse(const std::string& body) { return parseBody(body, "visibility.xml"); }

const char* kBody =
    "<material id=\"shell\" diffuse=\"0 1 0\"/><material id=\"lining\" diffuse=\"1 1 0\"/>"
    "<sphere image=\"false\"/>"
    "<group reflection=\"false\" double-illuminate=\"true\"><sphere/></group>"
    "<difference material=\"shell\" interior-material=\"lining\"><sphere/><box/></difference>"
    "<defs><sphere id=\"s\"/></defs><use ref=\"s\" image=\"false\" reflection=\"false\"/>";

}  // namespace

TEST_CASE("lang: image, reflection, double-illuminate and interior-material are read",
          "[lang][visibility]") {
  ParseResult r = parse(kBody);
  INFO(messages(r));
  REQUIRE(r.scene);
  CHECK(r.diagnostics.all().empty());
  const auto& top = r.scene->root->children;
  REQUIRE(top.size() == 4);
  CHECK_FALSE(top[0]->image);
  CHECK(top[0]->reflection);
  CHECK_FALSE(top[0]->doubleIlluminate);
  CHECK(top[1]->image);
  CHECK_FALSE(top[1]->reflection);
  CHECK(top[1]->doubleIlluminate);
  CHECK_FALSE(top[1]->children[0]->doubleIlluminate);  // inherited when the world is built
  REQUIRE(top[2]->interiorMaterial);
  CHECK(r.scene->materials.at(*top[2]->interiorMaterial).id == "lining");
  CHECK_FALSE(top[2]->children[0]->interiorMaterial);
  CHECK_FALSE(top[3]->image);
  CHECK_FALSE(top[3]->reflection);
}

TEST_CASE("lang: image=\"false\" inside an intersection is a warning naming the operation",
          "[lang][visibility]") {
  ParseResult r =
      parse("<intersection><box/><sphere radius=\"0.5\" image=\"false\"/></intersection>");
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.all().size() == 1);
  CHECK(r.diagnostics.all()[0].str() ==
        "visibility.xml:1:49: warning: <sphere> image=\"false\" has no effect inside "
        "<intersection> (at visibility.xml:1:29), which is seen as a whole, as in POV-Ray; put "
        "image=\"false\" on the <intersection>");
}

TEST_CASE("lang: convert writes image, reflection, double-illuminate and interior-material",
          "[lang][visibility]") {
  ParseResult r = parse(kBody);
  REQUIRE(r.scene);
  const std::string text = writeSceneXml(*r.scene, WriteOptions{});
  INFO(text);
  ParseResult again = parseSceneString(text, "again.xml");
  INFO(messages(again));
  REQUIRE(again.scene);
  const auto& top = again.scene->root->children;
  REQUIRE(top.size() == 4);
  CHECK_FALSE(top[0]->image);
  CHECK_FALSE(top[1]->reflection);
  CHECK(top[1]->doubleIlluminate);
  REQUIRE(top[2]->interiorMaterial);
  CHECK(again.scene->materials.at(*top[2]->interiorMaterial).diffuse == Color(1, 1, 0));
  CHECK_FALSE(top[3]->image);
  CHECK_FALSE(top[3]->reflection);
  CHECK(withoutComments(writeSceneXml(*again.scene, WriteOptions{})) == withoutComments(text));
}
