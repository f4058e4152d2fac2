// <pattern type="function">: the expression of x, y and z read and compiled, its value as
// POV-Ray's function pattern gives it (above 1 only the fraction), and its messages; the
// importer's `function { }` pattern.
#include "../sdl/scene_read_support.h"
#include "../support/scene_text.h"

#include "render/patterns/pattern_value.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

const PatternSpec& patternOf(const Scene& s, const std::string& id) {
  for (const Material& m : s.materials)
    if (m.id == id) return std::get<PatternTexture>(m.texture).pattern;
  FAIL("no material " << id);
  return std::get<PatternTexture>(s.materials.at(0).texture).pattern;
}

}  // namespace

TEST_CASE("function pattern: the expression's value, its fraction above 1",
          "[lang][pattern][function]") {
  auto s = parseClean(R"XML(<param name="k" value="2"/>
    <material id="f"><pattern type="function" function="x + k*y"/></material>)XML");
  const PatternSpec& p = patternOf(*s, "f");
  REQUIRE(p.function);
  CHECK(p.function->text == "x + k*y");
  REQUIRE(p.function->constants.size() == 1);
  CHECK(p.function->constants[0].second == 2.0);
  CHECK(patternValue(p, Vec3(0.1, 0.2, 5)) == Approx(0.5));
  CHECK(patternValue(p, Vec3(0.3, 0.4, 0)) == Approx(0.1));  // 1.1: its fraction
  CHECK(patternValue(p, Vec3(0.05, 0.05, 0)) == Approx(0.15));
}

TEST_CASE("function pattern: a missing or misplaced function is an error at its place",
          "[lang][pattern][function]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><pattern type=\"function\"/></material>"
      "\n<material id=\"b\"><pattern type=\"bozo\" function=\"x\"/></material>"
      "\n<material id=\"c\"><pattern type=\"function\" function=\"x +\"/></material>",
      "fn.xml");
  const std::string text = messages(r);
  INFO(text);
  CHECK(text.find("fn.xml:2:18: error: <pattern> type=\"function\" needs 'function' (an "
                  "expression of x, y and z)") != std::string::npos);
  CHECK(text.find("fn.xml:3:49: error: <pattern> attribute 'function': only type function "
                  "takes 'function', not bozo") != std::string::npos);
  CHECK(text.find("fn.xml:4:55: error: <pattern> attribute 'function': the expression ends") !=
        std::string::npos);
}

TEST_CASE("function pattern: the importer's function { } pigment, in POV-Ray's space",
          "[sdl][pattern][function]") {
  auto r = sdltest::readScene(
      "#declare F = function { x * y }\n"
      "sphere { 0, 1 pigment { function { F(x, y, z) + 0.25 } color_map { [0 rgb 0] [1 rgb 1] } "
      "} }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& p =
      std::get<PatternTexture>(s.materials.at(s.root->children.at(0)->material.value()).texture)
          .pattern;
  REQUIRE(p.type == PatternType::function);
  REQUIRE(p.function);
  CHECK(p.function->field->value(Vec3(0.5, 0.5, 0)) == Approx(0.5));
}
