// The scene writer (lang/scene_writer.h): numbers in their shortest exact form, a few
// elements as written, and a written scene read back to the same text (the shapes:
// scene_writer_shapes_test.cpp).
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "lang/xml_numbers.h"
#include "scenegraph/located_error.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace lucent;
using namespace lucent::test;

namespace {

std::string written(const std::string& body) {
  return writeSceneXml(*parseClean(body, "writer.xml"), WriteOptions{});
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("scene writer: numbers are written in the shortest form that reads back exactly",
          "[lang][scene-writer]") {
  CHECK(xmlNumber(0.1) == "0.1");
  CHECK(xmlNumber(2.0) == "2");
  CHECK(xmlNumber(-0.0) == "-0");
  CHECK(xmlNumber(1e300) == "1e+300");
  CHECK(xmlNumber(kInf) == "inf");
  CHECK(xmlNumber(1.0 / 3.0) == "0.3333333333333333");
  CHECK(xmlColor(Color(0.8f, 0.25f, 1.0f)) == "0.8 0.25 1");  // a float's digits, not a double's
  CHECK(xmlVector(Vec3(1.5, -2.0, 0.0)) == "1.5 -2 0");
  CHECK(xmlMatrix(Mat4(1.0)).empty());
  CHECK(xmlEscape("a<b & \"c\">") == "a&lt;b &amp; &quot;c&quot;&gt;");

  // Doubles of every magnitude, bit patterns from a fixed generator, read back bit for bit.
  uint64_t state = 0x9e3779b97f4a7c15ull;
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    double v;
    std::memcpy(&v, &state, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string text = xmlNumber(v);
    const double back = std::strtod(text.c_str(), nullptr);
    CHECK(std::memcmp(&back, &v, sizeof v) == 0);
    ++checked;
  }
  CHECK(checked > 19000);
}

TEST_CASE("scene writer: materials shared by several nodes get an id, others are inline",
          "[lang][scene-writer]") {
  const std::string text = written(
      "<material id=\"m\" diffuse=\"0.5\"/>"
      "<sphere radius=\"2\" material=\"m\"/><sphere material=\"m\"/>"
      "<box><material specular=\"0.25\" shininess=\"12\"/></box>"
      "<material id=\"unused\" diffuse=\"1\"/>");
  CHECK(contains(text, "<material id=\"m\" diffuse=\"0.5 0.5 0.5\"/>"));
  CHECK(contains(text, "<sphere center=\"0 0 0\" radius=\"2\" material=\"m\"/>"));
  CHECK(contains(text, "<material specular=\"0.25 0.25 0.25\" shininess=\"12\"/>"));
  CHECK_FALSE(contains(text, "unused"));
  // Each object is preceded by the source line it came from.
  CHECK(contains(text, "<!-- from writer.xml:1:"));
}

TEST_CASE("scene writer: a textured material's diffuse 0 is written (its default is 1)",
          "[lang][scene-writer]") {
  const std::string text = written(
      "<sphere center=\"0 0 -5\"><material ambient=\"1\" diffuse=\"0\"><checker color1=\"1 0 0\" "
      "color2=\"0 0 1\"/></material></sphere>"
      "<box><material diffuse=\"1\"><checker color1=\"1 0 0\" color2=\"0 0 1\"/></material></box>");
  CHECK(contains(text, "<material ambient=\"1\" diffuse=\"0 0 0\">"));
  CHECK(contains(text, "<material>"));
}

TEST_CASE("scene writer: repeats and expressions are written expanded, transforms as matrices",
          "[lang][scene-writer]") {
  const std::string text = written(
      "<repeat var=\"i\" count=\"3\"><sphere center=\"${i * 2} 0 0\" radius=\"0.5\"/></repeat>"
      "<group transform=\"translate(1 2 3)\"><box/></group>");
  CHECK(contains(text, "<sphere center=\"0 0 0\" radius=\"0.5\"/>"));
  CHECK(contains(text, "<sphere center=\"2 0 0\" radius=\"0.5\"/>"));
  CHECK(contains(text, "<sphere center=\"4 0 0\" radius=\"0.5\"/>"));
  CHECK(contains(text, "<group transform=\"matrix(1 0 0 1 0 1 0 2 0 0 1 3)\">"));
  CHECK_FALSE(contains(text, "repeat"));
}

TEST_CASE("scene writer: <defs> keep their ids, <use> names them, ids nothing names are dropped",
          "[lang][scene-writer]") {
  const std::string text = written(
      "<defs><sphere id=\"ball\" radius=\"0.5\"/><box id=\"unused\"/></defs>"
      "<use ref=\"ball\" transform=\"translate(0 1 0)\"/>"
      "<repeat var=\"i\" count=\"2\"><group id=\"g${i}\"><sphere/></group></repeat>");
  CHECK(contains(text, "<sphere id=\"ball\" center=\"0 0 0\" radius=\"0.5\"/>"));
  CHECK(contains(text, "<box id=\"unused\""));
  CHECK(contains(text, "<use ref=\"ball\" transform=\"matrix(1 0 0 0 0 1 0 1 0 0 1 0)\"/>"));
  CHECK_FALSE(contains(text, "id=\"g0\""));
  auto reread = parseSceneString(text, "writer.xml");
  CHECK(reread.scene);
}

TEST_CASE("scene writer: a spot light's inner angle is its own, not the angle it defaults to",
          "[lang][scene-writer]") {
  const std::string text = written(
      "<light type=\"spot\" position=\"0 5 0\" direction=\"0 -1 0\" angle=\"40\" "
      "inner=\"12\"/><sphere/>");
  CHECK(contains(text, "angle=\"40\" inner=\"12\""));
}

TEST_CASE("scene writer: POV-Ray's light rules and open shapes are written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<light type=\"spot\" position=\"0 5 0\" angle=\"40\" tightness=\"12\" "
      "fade-distance=\"3\" fade-power=\"1.5\" shadows=\"false\" highlights=\"false\"/>"
      "<light type=\"area\" position=\"0 5 0\" tightness=\"2\"/>"
      "<lathe points=\"0 0  1 0  1 1\" open=\"true\"/>");
  CHECK(contains(first, "fade-distance=\"3\" fade-power=\"1.5\""));
  CHECK(contains(first, "tightness=\"12\""));
  CHECK(contains(first, "shadows=\"false\" highlights=\"false\""));
  CHECK(contains(first, "open=\"true\""));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
  REQUIRE(reread.scene->lights.size() == 2);
  CHECK(reread.scene->lights[1].cone);  // the area light's tightness keeps it spot-shaped
  CHECK(reread.scene->lights[1].tightness == 2.0);
  // A light without them writes none of them.
  const std::string plain = written("<light position=\"0 5 0\"/><sphere/>");
  CHECK_FALSE(contains(plain, "fade-"));
  CHECK_FALSE(contains(plain, "highlights"));
}

TEST_CASE("scene writer: circular and oriented area lights are written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<light type=\"area\" position=\"0 5 0\" u=\"2 0 0\" v=\"0 0 2\" samples=\"4 6\" "
      "circular=\"true\" orient=\"true\" adaptive=\"1\"/>"
      "<light type=\"area\" position=\"1 5 0\" u=\"2 0 0\" v=\"0 0 1\" circular=\"true\"/>"
      "<sphere/>");
  CHECK(contains(first, "circular=\"true\" orient=\"true\""));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
  REQUIRE(reread.scene->lights.size() == 2);
  CHECK(reread.scene->lights[0].circular);
  CHECK(reread.scene->lights[0].orient);
  CHECK(reread.scene->lights[0].samplesV == 6);
  CHECK(reread.scene->lights[1].circular);
  CHECK_FALSE(reread.scene->lights[1].orient);
  // orient alone makes the light circular, as POV-Ray's.
  CHECK(contains(written("<light type=\"area\" orient=\"true\"/><sphere/>"),
                 "circular=\"true\" orient=\"true\""));
  // A light without them writes neither.
  const std::string plain =
      written("<light type=\"area\" position=\"0 5 0\" samples=\"4\"/><sphere/>");
  CHECK_FALSE(contains(plain, "circular"));
  CHECK_FALSE(contains(plain, "orient"));
}

TEST_CASE("scene writer: a spherical camera's v-angle is its own, not half of h-angle",
          "[lang][scene-writer]") {
  const std::string text =
      writeSceneXml(*parseClean("<sphere/>", "writer.xml",
                                "<camera type=\"spherical\" h-angle=\"200\" v-angle=\"60\"/>"),
                    WriteOptions{});
  CHECK(contains(text, "h-angle=\"200\" v-angle=\"60\""));
}

TEST_CASE("scene writer: a written scene reads back to the same text", "[lang][scene-writer]") {
  const std::string first = written(
      "<render width=\"64\" height=\"48\" background=\"0.1 0.2 0.3\"/>"
      "<fog color=\"0.5\" distance=\"20\"/>"
      "<fog type=\"ground\" color=\"0 0 1\" distance=\"2\" turbulence=\"0.2 0.3 0.4\" "
      "octaves=\"5\" omega=\"0.35\" lambda=\"1.25\" turb-depth=\"0.6\" noise-generator=\"3\" "
      "transform=\"scale(1 1 -1)\"/>"
      "<material id=\"air\" transmissive=\"1\" hollow=\"true\"/>"
      "<light position=\"1 2 3\" media-attenuation=\"true\"/>"
      "<light type=\"area\" position=\"0 5 0\" u=\"1 0 0\" v=\"0 0 1\" samples=\"3 2\"/>"
      "<difference><box material=\"air\"/><sphere radius=\"1.2\" inverse=\"true\"/></difference>"
      "<torus major=\"2\" minor=\"0.5\" shadows=\"false\"><material>"
      "<pattern type=\"marble\" turbulence=\"0.5\"><color-map><entry at=\"0\" color=\"1\"/>"
      "<entry at=\"1\" color=\"0 0 1\"/></color-map></pattern></material></torus>");
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
  CHECK(contains(first, "<light type=\"area\" position=\"0 5 0\" samples=\"3 2\"/>"));
  CHECK(contains(first, "turbulence=\"0.2 0.3 0.4\" octaves=\"5\" omega=\"0.35\""));
  CHECK(contains(first, "hollow=\"true\""));
  CHECK(contains(first, "media-attenuation=\"true\""));
}

TEST_CASE("scene writer: a checker's placement is written and reads back", "[lang][scene-writer]") {
  const std::string first = written(
      "<plane><material><checker color1=\"1\" color2=\"0\" scale=\"0.5\" "
      "transform=\"translate(1, 2, 3)\" turbulence=\"0.25\" octaves=\"3\"/></material></plane>");
  CHECK(contains(first, "turbulence=\"0.25 0.25 0.25\" octaves=\"3\""));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  const CheckerTexture* checker = nullptr;
  for (const Material& m : reread.scene->materials)
    if (const auto* c = std::get_if<CheckerTexture>(&m.texture)) checker = c;
  REQUIRE(checker);
  const CheckerTexture& c = *checker;
  CHECK(c.scale == 0.5);
  CHECK(c.placement.patternFromObject[3] == Vec4(-1, -2, -3, 1));
  CHECK(c.placement.turbulence == Vec3(0.25));
  CHECK(c.placement.octaves == 3);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: a rounding residue in a transform is written as 0, a tiny scale refused",
          "[lang][scene-writer]") {
  // As two rotations' rounding leaves in an imported POV-Ray scene (sin 180° · sin 90°):
  // beside entries near 1, -4.5e-32 is written as 0 (the language reads nothing that small).
  auto scene = parseClean("\n<sphere/>", "writer.xml");
  scene->root->children.front()->parentFromNode[1][0] = -4.5e-32;
  const std::string xml = writeSceneXml(*scene, WriteOptions{});
  INFO(xml);
  CHECK(xml.find("e-32") == std::string::npos);
  auto reread = parseSceneString(xml, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(reread.scene->root->children.front()->parentFromNode == Mat4(1.0));
  // A matrix of such entries alone (a scale of 1e-35) cannot be: 0 would be singular.
  Mat4 tiny(1e-35);
  tiny[3][3] = 1.0;
  scene->root->children.front()->parentFromNode = tiny;
  try {
    writeSceneXml(*scene, WriteOptions{});
    FAIL("no error");
  } catch (const LocatedError& e) {
    CHECK(e.loc().line == 2);
    CHECK(e.message() ==
          "cannot convert: the transform's entry 1e-35 is below the smallest magnitude the "
          "scene language reads (1e-30)");
  }
}

TEST_CASE("scene writer: a normal's keep-facing-away is written when true and reads back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sphere><material><normal type=\"granite\" depth=\"2.6\" keep-facing-away=\"true\"/>"
      "</material></sphere><sphere center=\"3 0 0\"><material>"
      "<normal type=\"gradient\" depth=\"1\"/></material></sphere>");
  CHECK(contains(first, "<normal type=\"granite\" depth=\"2.6\" keep-facing-away=\"true\"/>"));
  CHECK(contains(first, "<normal type=\"gradient\" depth=\"1\"/>"));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: filter and transmit of colours and the sky's layers read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sky layering=\"pov-3.6\"><pattern type=\"gradient\"/>"
      "<checker transmit1=\"0.5\" filter2=\"0.25\"/></sky>"
      "<sphere><material><pattern type=\"bozo\"><color-map>"
      "<entry at=\"0\" color=\"1\" filter=\"0.125\" transmit=\"0.5\"/>"
      "<entry at=\"1\" color=\"0\"/></color-map></pattern></material></sphere>"
      "<box><material><hexagon filter3=\"1\"/></material></box>"
      "<cylinder><material><brick transmit1=\"2\"/></material></cylinder>");
  CHECK(contains(first, "<entry at=\"0\" color=\"1 1 1\" filter=\"0.125\" transmit=\"0.5\"/>"));
  CHECK(contains(first, "<entry at=\"1\" color=\"0 0 0\"/>"));  // nothing written for 0
  CHECK(contains(first, "transmit1=\"0.5\" filter2=\"0.25\""));
  CHECK(contains(first, "filter3=\"1\""));
  CHECK(contains(first, "<sky layering=\"pov-3.6\">"));
  CHECK(contains(first, "transmit1=\"2\""));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  REQUIRE(reread.scene->sky);
  REQUIRE(reread.scene->sky->layers.size() == 2);
  const auto& checker = std::get<CheckerTexture>(reread.scene->sky->layers[1]);
  CHECK(checker.ft1 == FilterTransmit{0.0f, 0.5f});
  CHECK(checker.ft2 == FilterTransmit{0.25f, 0.0f});
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: quilted's controls and the fractals' parameters are written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sphere><material><pattern type=\"quilted\" control0=\"0.25\" frequency=\"1\"/>"
      "<normal type=\"magnet\" magnet-type=\"2\" form=\"julia\" c=\"1.1 0.3\" iterations=\"25\" "
      "exterior=\"6 0.01\"/></material></sphere>"
      "<sphere center=\"3 0 0\"><material><pattern type=\"julia\" c=\"-0.5 0.5\" "
      "iterations=\"20\" power=\"7\" interior=\"1 2\"/></material></sphere>"
      "<sphere center=\"6 0 0\"><material><pattern type=\"mandel\" iterations=\"10\"/>"
      "</material></sphere>");
  // quilted's default frequency is 0, so a frequency of 1 is written.
  CHECK(contains(first, "<pattern type=\"quilted\" frequency=\"1\" control0=\"0.25\"/>"));
  CHECK(contains(first,
                 "<normal type=\"magnet\" iterations=\"25\" magnet-type=\"2\" "
                 "form=\"julia\" c=\"1.1 0.3\" exterior=\"6 0.01\" depth=\"0.5\"/>"));
  CHECK(contains(first,
                 "<pattern type=\"julia\" iterations=\"20\" power=\"7\" c=\"-0.5 0.5\" "
                 "interior=\"1 2\"/>"));
  CHECK(contains(first, "<pattern type=\"mandel\" iterations=\"10\"/>"));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: pigment-pattern's pigment is written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sphere><material><pattern type=\"pigment-pattern\" frequency=\"2\">"
      "<pigment><checker color1=\"1 0.5 0\" color2=\"0 0.2 1\"/></pigment>"
      "<color-map><entry at=\"0\" color=\"0 0 0\"/><entry at=\"1\" color=\"1 0 0\"/></color-map>"
      "</pattern><normal type=\"pigment-pattern\" depth=\"0.3\"><pigment color=\"0.5 0.5 0.5\"/>"
      "</normal></material></sphere>"
      "<sphere center=\"3 0 0\"><material><pattern type=\"cells\"/></material></sphere>");
  CHECK(contains(first, "<pattern type=\"pigment-pattern\" frequency=\"2\">"));
  CHECK(contains(first, "<checker color1=\"1 0.5 0\" color2=\"0 0.2 1\""));
  CHECK(contains(first, "<pigment color=\"0.5 0.5 0.5\"/>"));
  CHECK(contains(first, "<pattern type=\"cells\"/>"));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: slope's direction or point, ranges and altitude are written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sphere><material><pattern type=\"slope\" direction=\"0 -3 0\" slope-range=\"0 0.5\" "
      "altitude=\"0 1 0\" altitude-range=\"0.005 0.4\"/></material></sphere>"
      "<sphere center=\"3 0 0\"><material><pattern type=\"slope\" point-at=\"1 2 3\"/>"
      "</material></sphere>"
      "<sphere center=\"6 0 0\"><material><normal type=\"slope\" direction=\"1 0 0\" "
      "depth=\"0.3\"/></material></sphere>");
  CHECK(contains(first,
                 "<pattern type=\"slope\" direction=\"0 -3 0\" slope-range=\"0 0.5\" "
                 "altitude=\"0 1 0\" altitude-range=\"0.005 0.4\"/>"));
  CHECK(contains(first, "<pattern type=\"slope\" point-at=\"1 2 3\"/>"));
  CHECK(contains(first, "<normal type=\"slope\" direction=\"1 0 0\" depth=\"0.3\"/>"));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}

TEST_CASE("scene writer: facets' size, coords and metric are written and read back",
          "[lang][scene-writer]") {
  const std::string first = written(
      "<sphere><material><normal type=\"facets\"/></material></sphere>"
      "<sphere center=\"3 0 0\"><material><normal type=\"facets\" size=\"0.25\" coords=\"0.4\" "
      "metric=\"1\"/></material></sphere>");
  CHECK(contains(first, "<normal type=\"facets\" depth=\"0.5\"/>"));
  CHECK(contains(
      first, "<normal type=\"facets\" size=\"0.25\" coords=\"0.4\" metric=\"1\" depth=\"0.5\"/>"));
  auto reread = parseSceneString(first, "writer.xml");
  REQUIRE(reread.scene);
  CHECK(withoutComments(writeSceneXml(*reread.scene, WriteOptions{})) == withoutComments(first));
}
