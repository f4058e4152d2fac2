// shadows="false" on geometry nodes: read into Node::shadows on every kind of node; on a
// part of a merge, intersection or difference it is a warning (it changes nothing there).
#include "../support/scene_text.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

ParseResult parse(const std::string& body) { return parseBody(body, "shadows.xml"); }

}  // namespace

TEST_CASE("lang: shadows=\"false\" on shapes, groups, CSG, meshes and use", "[lang][no-shadow]") {
  ParseResult r = parse(
      "<sphere shadows=\"false\"/><box/>"
      "<group shadows=\"false\"><sphere/></group>"
      "<union shadows=\"false\"><sphere/></union>"
      "<mesh positions=\"0 0 0 1 0 0 0 1 0\" indices=\"0 1 2\" shadows=\"false\"/>"
      "<defs><sphere id=\"s\"/></defs><use ref=\"s\" shadows=\"false\"/>");
  INFO(messages(r));
  REQUIRE(r.scene);
  CHECK(r.diagnostics.all().empty());
  const auto& top = r.scene->root->children;
  REQUIRE(top.size() == 6);
  CHECK_FALSE(top[0]->shadows);
  CHECK(top[1]->shadows);  // the default
  CHECK_FALSE(top[2]->shadows);
  CHECK(top[2]->children[0]->shadows);  // inherited when the world is built, not copied
  CHECK_FALSE(top[3]->shadows);
  CHECK_FALSE(top[4]->shadows);
  CHECK_FALSE(top[5]->shadows);
}

TEST_CASE("lang: shadows=\"false\" inside a difference is a warning naming the operation",
          "[lang][no-shadow]") {
  ParseResult r = parse(
      "<difference><box/><group><sphere radius=\"0.5\" shadows=\"false\"/></group></difference>");
  REQUIRE(r.scene);
  REQUIRE(r.diagnostics.all().size() == 1);
  CHECK(
      r.diagnostics.all()[0].str() ==
      "shadows.xml:1:54: warning: <sphere> shadows=\"false\" has no effect inside <difference> (at "
      "shadows.xml:1:29), which casts its shadow as a whole, as in POV-Ray; put shadows=\"false\" "
      "on the "
      "<difference>");
}
