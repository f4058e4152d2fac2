// Pigment functions: POV-Ray's `#declare F = function { pigment { P } }` called as
// F(x, y, z).red in a function pattern or an isosurface, and the XML's <pigment-function>.
// The values are POV-Ray's own (#debug of F(x, y, z).member, POV-Ray 3.7.0, written below
// with each pigment) or the pigment's colour worked out by hand.
#include "../sdl/scene_read_support.h"
#include "../support/scene_text.h"

#include "lang/scene_writer.h"
#include "scenegraph/pigment_function.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

// The POV-Ray pigments of the checks, declared as pigment functions.
const char* const kPovPigments =
    "#declare G = function { pigment { gradient x color_map { [0 rgb <0.2, 0.4, 0.6> filter 0.1]"
    " [1 rgb <1, 0.5, 0> transmit 0.3] } scale 2 translate 0.1*x } }\n"
    "#declare W = function { pigment { wood turbulence 0.1 color_map { [0 rgb <0.9, 0.6, 0.3>]"
    " [1 rgb <0.3, 0.2, 0.1>] } scale 0.3 rotate 30*y } }\n"
    "#declare C = function { pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> scale 0.5 } }\n"
    "#declare S = function { pigment { rgbft <0.25, 0.5, 0.75, 0.125, 0.0625> } }\n";

// The field of `pigment { function { F } }` imported with the pigments above (a function
// pattern's x, y and z are POV-Ray's).
std::shared_ptr<const ScalarField> patternField(const std::string& function) {
  auto r = sdltest::readScene(std::string(kPovPigments) + "sphere { 0, 1 pigment { function { " +
                              function + " } } }\n");
  REQUIRE(r->load.scene);
  const Scene& s = *r->load.scene;
  const auto& p =
      std::get<PatternTexture>(s.materials.at(s.root->children.at(0)->material.value()).texture)
          .pattern;
  REQUIRE(p.function);
  return p.function->field;
}

double at(const std::string& function, double x, double y, double z) {
  return patternField(function)->value(Vec3(x, y, z));
}

}  // namespace

TEST_CASE("pigment function: every member, as POV-Ray gives it", "[sdl][function][pigment]") {
  // POV-Ray: 0.400000006 0.425000012 0.450000018 0.075000003 0.075000003 0.420425011
  CHECK(at("G(x, y, z).red", 0.6, 0, 0) == Approx(0.4).epsilon(1e-6));
  CHECK(at("G(x, y, z).green", 0.6, 0, 0) == Approx(0.425).epsilon(1e-6));
  CHECK(at("G(x, y, z).blue", 0.6, 0, 0) == Approx(0.45).epsilon(1e-6));
  CHECK(at("G(x, y, z).filter", 0.6, 0, 0) == Approx(0.075).epsilon(1e-6));
  CHECK(at("G(x, y, z).transmit", 0.6, 0, 0) == Approx(0.075).epsilon(1e-6));
  CHECK(at("G(x, y, z).gray", 0.6, 0, 0) == Approx(0.420425011).epsilon(1e-6));
  // .x .y .z .t and .u .v: red, green, blue, filter. POV-Ray: 0.68 0.46 0.24 0.04
  CHECK(at("G(x, y, z).x", -0.7, 1, 2) == Approx(0.68).epsilon(1e-6));
  CHECK(at("G(x, y, z).y", -0.7, 1, 2) == Approx(0.46).epsilon(1e-6));
  CHECK(at("G(x, y, z).z", -0.7, 1, 2) == Approx(0.24).epsilon(1e-6));
  CHECK(at("G(x, y, z).t", -0.7, 1, 2) == Approx(0.04).epsilon(1e-6));
  CHECK(at("G(x, y, z).u + 10*G(x, y, z).v", -0.7, 1, 2) == Approx(0.68 + 4.6).epsilon(1e-6));
  // A solid colour. POV-Ray: 0.25 0.125 0.0625 0.45425
  CHECK(at("S(x, y, z).red", 1, 2, 3) == Approx(0.25));
  CHECK(at("S(x, y, z).filter", 1, 2, 3) == Approx(0.125));
  CHECK(at("S(x, y, z).transmit", 1, 2, 3) == Approx(0.0625));
  CHECK(at("S(x, y, z).gray", 1, 2, 3) == Approx(0.45425));
}

TEST_CASE("pigment function: the pigment's own transform, turbulence and cells",
          "[sdl][function][pigment]") {
  // POV-Ray: 0.716391861 0.407698750 0.213867664
  CHECK(at("W(x, y, z).red", 0.3, 0.2, 0.7) == Approx(0.716391861).epsilon(1e-5));
  CHECK(at("W(x, y, z).green", -1.1, 0.4, 0.35) == Approx(0.407698750).epsilon(1e-5));
  CHECK(at("W(x, y, z).blue", 2.5, -0.3, 1.2) == Approx(0.213867664).epsilon(1e-5));
  // POV-Ray: 1 1 1 (the checker's even cell red, the odd one blue)
  CHECK(at("C(x, y, z).red", 0.25, 0.25, 0.25) == 1.0);
  CHECK(at("C(x, y, z).blue", 0.75, 0.25, 0.25) == 1.0);
  CHECK(at("C(x, y, z).red", 0.75, 0.25, -0.25) == 1.0);
  CHECK(at("C(x, y, z).red", 0.75, 0.25, 0.25) == 0.0);
  // Arguments other than the point, and a call inside arithmetic.
  CHECK(at("pow(G(x + 0.5, 0, 0).red, 2)", 0.1, 7, 7) == Approx(0.4 * 0.4).epsilon(1e-6));
}

TEST_CASE("pigment function: an isosurface's point is carried into POV-Ray's space",
          "[sdl][function][pigment][isosurface]") {
  auto r = sdltest::readScene(
      "#declare Z = function { pigment { gradient z color_map { [0 rgb 0] [1 rgb 1] } scale 2 } "
      "}\n"
      "isosurface { function { Z(x, y, z).red - 0.5 } contained_by { box { -1, 1 } } }\n");
  REQUIRE(r->load.scene);
  const Node& n = *r->load.scene->root->children.at(0);
  const auto& iso = std::get<IsosurfaceSpec>(*n.shape);
  REQUIRE(iso.pigments.size() == 1);
  CHECK(iso.pigments[0]->component == PigmentComponent::red);
  // Lucent's z = -0.5 is POV-Ray's 0.5: the gradient's value there is 0.25.
  CHECK(iso.field->value(Vec3(0.3, 0.1, -0.5)) == Approx(0.25 - 0.5).epsilon(1e-6));
  CHECK(iso.field->value(Vec3(0.3, 0.1, 0.5)) == Approx(0.75 - 0.5).epsilon(1e-6));
}

TEST_CASE("pigment function: a bare call, an unknown member and an image are refused",
          "[sdl][function][pigment]") {
  auto has = [](const std::vector<std::string>& errors, const std::string& text) {
    for (const std::string& e : errors)
      if (e.find(text) != std::string::npos) return true;
    INFO(text);
    for (const std::string& e : errors) UNSCOPED_INFO(e);
    return false;
  };
  CHECK(has(sdltest::errorsOf(std::string(kPovPigments) +
                              "sphere { 0, 1 pigment { function { G(x, y, z) } } }\n"),
            "'G' is a pigment function: it gives a vector, so a function takes one of its "
            "components"));
  CHECK(has(sdltest::errorsOf(std::string(kPovPigments) +
                              "sphere { 0, 1 pigment { function { G(x, y, z).hue } } }\n"),
            "expected x, y, z, t, u, v, red, green, blue, gray, grey, filter, transmit or hf "
            "after '.'"));
  CHECK(has(sdltest::errorsOf(
                "#declare I = function { pigment { image_map { png \"scenes/image_maps.png\" } } "
                "}\n"
                "sphere { 0, 1 pigment { function { I(x, y, z).red } } }\n"),
            "is an image pigment, which Lucent cannot evaluate at a point in a function"));
}

TEST_CASE("pigment function: <pigment-function> in a function pattern, each component",
          "[lang][pattern][function][pigment]") {
  // gradient x from (0.2, 0.4, 0.6) filter 0.1 to (1, 0.5, 0) transmit 0.3 over 2 units.
  auto pattern = [](const char* component) {
    auto s = parseClean(std::string(R"XML(<material id="m">
      <pattern type="function" function="P(x, y, z) + 0*Q(1, 2, 3)">
        <pigment-function name="P" component=")XML") +
                        component + R"XML(">
          <pattern type="gradient" axis="1 0 0" transform="scale(2)">
            <color-map><entry at="0" color="0.2 0.4 0.6" filter="0.1"/>
              <entry at="1" color="1 0.5 0" transmit="0.3"/></color-map>
          </pattern>
        </pigment-function>
        <pigment-function name="Q" component="red"><checker/></pigment-function>
      </pattern></material>)XML");
    const Material& m = materialNamed(*s, "m");
    return std::get<PatternTexture>(m.texture).pattern.function;
  };
  const double v = 0.25;  // x = 0.5
  const double red = 0.2 + 0.8 * v, green = 0.4 + 0.1 * v, blue = 0.6 - 0.6 * v;
  CHECK(pattern("red")->field->value(Vec3(0.5, 3, 4)) == Approx(red).epsilon(1e-6));
  CHECK(pattern("green")->field->value(Vec3(0.5, 3, 4)) == Approx(green).epsilon(1e-6));
  CHECK(pattern("blue")->field->value(Vec3(0.5, 3, 4)) == Approx(blue).epsilon(1e-6));
  CHECK(pattern("filter")->field->value(Vec3(0.5, 3, 4)) == Approx(0.1 * 0.75).epsilon(1e-6));
  CHECK(pattern("transmit")->field->value(Vec3(0.5, 3, 4)) == Approx(0.3 * 0.25).epsilon(1e-6));
  CHECK(pattern("gray")->field->value(Vec3(0.5, 3, 4)) ==
        Approx(0.297 * red + 0.589 * green + 0.114 * blue).epsilon(1e-6));
  const auto f = pattern("red");
  REQUIRE(f->pigments.size() == 2);
  CHECK(f->pigments[0]->name == "P");
  CHECK(f->pigments[1]->name == "Q");
}

TEST_CASE("pigment function: <pigment-function> in an isosurface, written back by convert",
          "[lang][isosurface][pigment]") {
  const std::string body = R"XML(
    <isosurface function="B(x, y, z) - 0.5" min="-1 -1 -1" max="1 1 1">
      <pigment-function name="B" component="blue">
        <pattern type="onion"><color-map><entry at="0" color="0 0 0"/>
          <entry at="1" color="0 0 1"/></color-map></pattern>
      </pigment-function>
    </isosurface>)XML";
  auto s = parseClean(body);
  const auto& iso = std::get<IsosurfaceSpec>(*s->root->children.at(0)->shape);
  CHECK(iso.field->value(Vec3(0.3, 0.4, 0)) == Approx(0.5 - 0.5).epsilon(1e-6));
  CHECK(iso.field->value(Vec3(0.6, 0, 0)) == Approx(0.6 - 0.5).epsilon(1e-6));
  // Written, read again: the same values.
  const std::string xml = writeSceneXml(*s, WriteOptions{});
  INFO(xml);
  CHECK(xml.find("<pigment-function name=\"B\" component=\"blue\">") != std::string::npos);
  auto again = parseSceneString(xml, "again.xml");
  REQUIRE(again.scene);
  const auto& iso2 = std::get<IsosurfaceSpec>(*again.scene->root->children.at(0)->shape);
  CHECK(iso2.field->value(Vec3(0.6, 0, 0)) == Approx(0.6 - 0.5).epsilon(1e-6));
}

TEST_CASE("pigment function: <pigment-function> mistakes are located", "[lang][pattern][pigment]") {
  ParseResult r = parseBody(
      "\n<material id=\"a\"><pattern type=\"function\" function=\"P(x, y, z)\">"
      "<pigment-function name=\"P\" component=\"hue\"><checker/></pigment-function></pattern>"
      "</material>"
      "\n<material id=\"b\"><pattern type=\"function\" function=\"P(x, y)\">"
      "<pigment-function name=\"P\" component=\"red\"><checker/></pigment-function></pattern>"
      "</material>"
      "\n<material id=\"c\"><pattern type=\"function\" function=\"P + 1\">"
      "<pigment-function name=\"P\" component=\"red\"><checker/></pigment-function></pattern>"
      "</material>"
      "\n<material id=\"d\"><pattern type=\"function\" function=\"sin(x)\">"
      "<pigment-function name=\"sin\" component=\"red\"><checker/></pigment-function></pattern>"
      "</material>"
      "\n<material id=\"e\"><pattern type=\"function\" function=\"x\">"
      "<pigment-function name=\"P\" component=\"red\"/></pattern></material>"
      "\n<material id=\"f\"><pattern type=\"bozo\">"
      "<pigment-function name=\"P\" component=\"red\"><checker/></pigment-function></pattern>"
      "</material>",
      "pf.xml");
  const std::string text = messages(r);
  INFO(text);
  CHECK(text.find("pf.xml:2:") != std::string::npos);
  CHECK(text.find("<pigment-function> attribute 'component'") != std::string::npos);
  CHECK(text.find("pf.xml:3:") != std::string::npos);
  CHECK(text.find("pf.xml:4:") != std::string::npos);
  CHECK(text.find("'P' is a pigment function: write P(x, y, z)") != std::string::npos);
  CHECK(text.find("'sin' is a function of the expressions") != std::string::npos);
  CHECK(text.find("<pigment-function> needs a texture child") != std::string::npos);
  CHECK(text.find("pf.xml:7:") != std::string::npos);
}

TEST_CASE("pigment function: component value is a pattern's own value in double precision",
          "[lang][pattern][function][pigment]") {
  auto field = [](const char* component, const char* texture) {
    ParseResult r = parseBody(std::string(R"XML(
      <isosurface function="N(x, y, z) - 0.5" min="-1 -1 -1" max="1 1 1">
        <pigment-function name="N" component=")XML") +
                                  component + "\">" + texture + "</pigment-function></isosurface>",
                              "v.xml");
    return r;
  };
  const char* bozo =
      "<pattern type=\"bozo\"><color-map><entry at=\"0\" color=\"0 0 0\"/>"
      "<entry at=\"1\" color=\"1 1 1\"/></color-map></pattern>";
  ParseResult v = field("value", bozo);
  ParseResult red = field("red", bozo);
  REQUIRE(v.scene);
  REQUIRE(red.scene);
  const auto& iv = std::get<IsosurfaceSpec>(*v.scene->root->children.at(0)->shape);
  const auto& ir = std::get<IsosurfaceSpec>(*red.scene->root->children.at(0)->shape);
  REQUIRE(iv.pigments.size() == 1);
  CHECK(iv.pigments[0]->component == PigmentComponent::value);
  // The same value; red is the colour's, rounded to single precision, value is not.
  int unrounded = 0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 p(0.013 * i, 0.37 - 0.007 * i, 0.021 * i);
    const double a = iv.field->value(p), b = ir.field->value(p);
    CHECK(a == Approx(b).margin(1e-7));
    CHECK(b + 0.5 == static_cast<double>(static_cast<float>(b + 0.5)));
    if (a + 0.5 != static_cast<double>(static_cast<float>(a + 0.5))) ++unrounded;
  }
  CHECK(unrounded > 40);
  // Written back as it is.
  const std::string xml = writeSceneXml(*v.scene, WriteOptions{});
  CHECK(xml.find("component=\"value\"") != std::string::npos);
  // Not a pattern: refused at the attribute.
  ParseResult bad = field("value", "<checker/>");
  CHECK_FALSE(bad.scene);
  const std::string text = messages(bad);
  INFO(text);
  CHECK(text.rfind("v.xml:", 0) == 0);
  CHECK(text.find("error: <pigment-function> attribute 'component': 'value' is a <pattern>'s own "
                  "value") != std::string::npos);
}
