// <clip> and <bound> on geometry nodes: read into Node::clip and Node::bound in the node's
// frame, written back by `lucent convert`, exported as POV-Ray's clipped_by and
// bounded_by, and the messages for what they cannot hold.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kClipped = R"XML(
  <group>
    <sphere radius="1" transform="translate(0 2 0)">
      <clip><plane normal="0 1 0" offset="0"/><box min="-1 -1 -1" max="0 1 1"/></clip>
      <bound><sphere radius="2"/></bound>
    </sphere>
    <union>
      <sphere radius="1"/>
      <sphere radius="1" center="1 0 0"/>
      <clip><sphere radius="1.5"/></clip>
    </union>
  </group>)XML";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("clip: <clip> and <bound> hold solids in the node's frame", "[lang][clip]") {
  auto scene = parseClean(kClipped);
  const Node& group = *scene->root->children.at(0);
  const Node& sphere = *group.children.at(0);
  REQUIRE(sphere.clip.size() == 2);
  CHECK(sphere.clip[0]->element == "plane");
  CHECK(sphere.clip[1]->element == "box");
  REQUIRE(sphere.bound.size() == 1);
  CHECK(sphere.bound[0]->element == "sphere");
  CHECK(sphere.children.empty());
  // The clip of a CSG node is not one of its operands.
  const Node& onion = *group.children.at(1);
  CHECK(onion.children.size() == 2);
  REQUIRE(onion.clip.size() == 1);
  CHECK(onion.bound.empty());
}

TEST_CASE("clip: lucent convert writes <clip> and <bound> back", "[lang][clip]") {
  auto scene = parseClean(kClipped, "clip.xml");
  const std::string xml = writeSceneXml(*scene, WriteOptions{});
  INFO(xml);
  CHECK(has(xml, "<clip>"));
  CHECK(has(xml, "<bound>"));
  // Read back, the same structure.
  ParseResult again = parseSceneString(xml, "again.xml");
  INFO(messages(again));
  REQUIRE(again.scene);
  REQUIRE(again.diagnostics.errorCount() == 0);
  const Node& sphere = *again.scene->root->children.at(0)->children.at(0);
  CHECK(sphere.clip.size() == 2);
  CHECK(sphere.bound.size() == 1);
  CHECK(withoutComments(writeSceneXml(*again.scene, WriteOptions{})) == withoutComments(xml));
}

TEST_CASE("clip: export-pov writes clipped_by before the object's matrix, bounded_by on a union",
          "[lang][clip][povray]") {
  auto scene = parseClean(kClipped, "clip.xml");
  PovExport e = exportPov(*scene);
  INFO(e.text);
  REQUIRE(e.ok());
  // The clip is written in the object's frame, followed by the matrix that moves both,
  // and without a texture (POV-Ray refuses one there).
  const size_t clip = e.text.find("clipped_by {");
  const size_t matrix = e.text.find("matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 2, 0>");
  REQUIRE(clip != std::string::npos);
  REQUIRE(matrix != std::string::npos);
  CHECK(clip < matrix);
  const std::string clipBlock = e.text.substr(clip, matrix - clip);
  CHECK(has(clipBlock, "plane {"));
  CHECK(has(clipBlock, "box {"));
  CHECK_FALSE(has(clipBlock, "texture"));
  // POV-Ray keeps a union's bounded_by (it drops a plain shape's): the bounded sphere is
  // written in a union of its own.
  CHECK(has(e.text, "(bounded)"));
  CHECK(has(e.text, "bounded_by {"));
}

TEST_CASE("clip: export-pov clips a group as a union of its objects, inverted before the clip",
          "[lang][clip][povray]") {
  auto scene = parseClean(R"XML(
    <group inverse="true" shadows="false" transform="translate(0 1 0)">
      <sphere radius="1"/>
      <sphere radius="1" center="3 0 0"/>
      <clip><plane normal="0 1 0" offset="0"/></clip>
    </group>)XML",
                          "clip.xml");
  PovExport e = exportPov(*scene);
  INFO(e.text);
  REQUIRE(e.ok());
  const size_t start = e.text.find("union {  // <group> clip.xml:2:5 (clipped)");
  REQUIRE(start != std::string::npos);
  const std::string block = e.text.substr(start);
  const size_t clip = block.find("clipped_by {");
  const size_t matrix = block.find("matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 1, 0>");
  const size_t inverse = block.find("\n  inverse\n");
  REQUIRE(clip != std::string::npos);
  REQUIRE(matrix != std::string::npos);
  REQUIRE(inverse != std::string::npos);
  CHECK(clip < matrix);
  CHECK(matrix < inverse);
  // The spheres keep the group's shadows="false".
  CHECK(block.find("no_shadow") < clip);
}

TEST_CASE("clip: bad <clip> and <bound> contents are errors at their place", "[lang][clip]") {
  ParseResult r = parseBody(R"XML(
<sphere radius="1"><clip/></sphere>
<sphere radius="1"><clip><disc radius="1"/></clip></sphere>
<sphere radius="1"><clip><box/></clip><clip><box/></clip></sphere>
<sphere radius="1"><bound scale="2"><box/></bound></sphere>
<sphere radius="1"><clip><light position="0 1 0"/></clip></sphere>
<sphere radius="1"><bound><material/></bound></sphere>)XML",
                            "clip.xml");
  CHECK(messages(r) ==
        "clip.xml:2:20: error: <clip> needs at least one solid: the surface is kept only inside "
        "all of them (POV-Ray's clipped_by)\n"
        "clip.xml:3:26: error: <disc> in the <clip> of <sphere> (at clip.xml:3:1) must be a "
        "solid: it is not one (a disc encloses no volume)\n"
        "clip.xml:4:39: error: <sphere> holds one <clip> at most; the first is at clip.xml:4:20\n"
        "clip.xml:5:27: error: <bound>: unknown attribute 'scale'\n"
        "clip.xml:6:26: error: <light> is not allowed inside <clip>; a light stands at the top "
        "level or in a group, CSG operation, <defs>, <repeat> or <if>\n"
        "clip.xml:7:27: error: <material> is not allowed inside <bound>\n");
}
