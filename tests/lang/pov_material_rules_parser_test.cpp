// The <material> attributes that select POV-Ray's rules (full-tir, metallic-amount,
// metallic-color, reflect-metallic, fade-distance, fade-power, fade-color): read, their
// defaults, written back by the scene writer (lucent convert), and bad values.
#include "../support/scene_text.h"

#include "lang/scene_writer.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const char* kBody =
    "<material id=\"pov\" diffuse=\"0.45 0.3 0.1\" phong=\"0.9\" metallic=\"true\" "
    "metallic-amount=\"0.5\" metallic-color=\"0.9 0.6 0.2\" reflective=\"0.5\" "
    "reflect-metallic=\"0.25\" transmissive=\"0.7\" ior=\"1.5\" full-tir=\"true\" "
    "fade-distance=\"0.8\" fade-power=\"1\" fade-color=\"0.9 0.3 0.1\"/>"
    "<material id=\"white\" metallic=\"true\" metallic-color=\"1\"/>"
    "<material id=\"plain\" diffuse=\"0.5\"/>"
    "<sphere material=\"pov\"/><sphere material=\"white\"/><sphere material=\"plain\"/>";

}  // namespace

TEST_CASE("POV-Ray's material rules: the attributes are read and default to Lucent's rules",
          "[lang][finish][pov-rules]") {
  auto s = parseClean(kBody);
  const Material& pov = materialNamed(*s, "pov");
  CHECK(pov.fullTir);
  CHECK(pov.metallicAmount == 0.5);
  REQUIRE(pov.metallicColor);
  CHECK(*pov.metallicColor == Color(0.9f, 0.6f, 0.2f));
  CHECK(pov.reflectMetallic == 0.25);
  CHECK(pov.fadeDistance == 0.8);
  CHECK(pov.fadePower == 1.0);
  CHECK(pov.fadeColor == Color(0.9f, 0.3f, 0.1f));
  const Material& plain = materialNamed(*s, "plain");
  CHECK_FALSE(plain.fullTir);
  CHECK(plain.metallicAmount == 1.0);
  CHECK_FALSE(plain.metallicColor);
  CHECK(plain.reflectMetallic == 0.0);
  CHECK_FALSE(plain.hasFade());
  CHECK(plain.fadePower == 2.0);
}

TEST_CASE("POV-Ray's material rules: lucent convert writes them, and only where set",
          "[lang][finish][pov-rules][scene-writer]") {
  auto written = [](const Scene& s) {
    std::string text = writeSceneXml(s, WriteOptions{});
    // Without the comments naming the lines read, on one line.
    std::string out;
    for (size_t at = 0; at < text.size();) {
      size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      const std::string line = text.substr(at, end - at);
      if (line.find("<!--") == std::string::npos) out += " " + line;
      at = end + 1;
    }
    return out;
  };
  const std::string first = written(*parseClean(kBody, "writer.xml"));
  auto has = [&](const std::string& part) { return first.find(part) != std::string::npos; };
  CHECK(has("full-tir=\"true\""));
  CHECK(has("fade-distance=\"0.8\""));
  CHECK(has("fade-power=\"1\""));
  CHECK(has("fade-color=\"0.9 0.3 0.1\""));
  CHECK(has("metallic-color=\"0.9 0.6 0.2\" reflect-metallic=\"0.25\""));
  // A metallic colour of 1 is written (it is not the absent one); the plain material
  // writes none of them.
  CHECK(has("<material metallic=\"true\" metallic-color=\"1 1 1\"/>"));
  CHECK(has("<material diffuse=\"0.5 0.5 0.5\"/>"));
  auto reread = parseSceneString(writeSceneXml(*parseClean(kBody, "writer.xml"), WriteOptions{}),
                                 "writer.xml");
  REQUIRE(reread.scene);
  CHECK(written(*reread.scene) == first);
  int white = 0, unset = 0;
  for (const Material& m : reread.scene->materials) {
    if (m.metallicColor && *m.metallicColor == Color(1.0f)) ++white;
    if (!m.metallicColor) ++unset;
  }
  CHECK(white == 1);
  CHECK(unset >= 1);
}

TEST_CASE(
    "POV-Ray's material rules: bad values are errors at the attribute, POV-Ray's words "
    "hinted",
    "[lang][finish][pov-rules]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\" fade-distance=\"-1\" fade-power=\"-2\" metallic-amount=\"-0.5\" "
      "full-tir=\"yes\"/>"
      "\n<material id=\"b\" fade_power=\"2\"/>",
      "rules.xml");
  const std::string text = messages(r);
  CHECK(text.find("rules.xml:2:33: error: <material> attribute 'fade-distance': expected a "
                  "number >= 0, got '-1'") != std::string::npos);
  CHECK(text.find("attribute 'fade-power': expected a number >= 0, got '-2'") != std::string::npos);
  CHECK(text.find("attribute 'metallic-amount': expected a number >= 0, got '-0.5'") !=
        std::string::npos);
  CHECK(text.find("attribute 'full-tir'") != std::string::npos);
  CHECK(text.find("rules.xml:3:18: error: <material>: unknown attribute 'fade_power' "
                  "(POV-Ray's 'fade_power' is 'fade-power' in Lucent)") != std::string::npos);
}
