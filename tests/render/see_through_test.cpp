// Colours with filter and transmit (render/see_through.h): a see-through texture over a
// known background, the sky's layers, shadows through such a texture, and their export.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "see_through.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

}  // namespace

TEST_CASE("a colour map's filter and transmit let the background through, interpolated",
          "[render][pattern][see-through]") {
  // Lit by ambient alone: the pixel is C·a + (C·f + t)·background, a = 1 − f − t, with f
  // and t interpolated along the gradient as the colour is: f = 0.8·v, t = 0.6·(1 − v).
  auto scene = parse(R"XML(<render ambient="1" background="0.2 0.4 0.8"/>
    <plane normal="0 1 0" offset="0"><material ambient="1">
      <pattern type="gradient" axis="1 0 0">
        <color-map><entry at="0" color="1 0.5 0.25" transmit="0.6"/>
                   <entry at="1" color="1 0.5 0.25" filter="0.8"/></color-map>
      </pattern></material></plane>)XML");
  World world(*scene);
  const Color c(1.0f, 0.5f, 0.25f), background(0.2f, 0.4f, 0.8f);
  for (double v : {0.1, 0.35, 0.5, 0.9}) {
    const Color got = traceOne(world, Ray(Vec3(v, 1, 0.2), Vec3(0, -1, 0)));
    const double f = 0.8 * v, t = 0.6 * (1 - v), a = 1 - f - t;
    INFO("v = " << v);
    for (int i = 0; i < 3; ++i)
      CHECK(got[i] == Approx(c[i] * a + (c[i] * f + t) * background[i]).margin(1e-5));
  }
}

TEST_CASE("a checker's colour with transmit 1 is a hole, the other colour opaque",
          "[render][pattern][see-through]") {
  auto scene = parse(R"XML(<render ambient="1" background="0 1 0"/>
    <plane normal="0 1 0" offset="0"><material ambient="1">
      <checker color1="1 0 0" color2="0 0 1" transmit2="1"/></material></plane>)XML");
  World world(*scene);
  const Color red = traceOne(world, Ray(Vec3(0.5, 1, 0.5), Vec3(0, -1, 0)));
  const Color hole = traceOne(world, Ray(Vec3(1.5, 1, 0.5), Vec3(0, -1, 0)));
  CHECK(red == Color(1.0f, 0.0f, 0.0f));
  CHECK(hole == Color(0.0f, 1.0f, 0.0f));
}

TEST_CASE("a shadow ray keeps C·f + t of a see-through texture it crosses",
          "[render][pattern][see-through]") {
  // A sheet at y = 1 with filter 0.5 over red (1, 0.2, 0) and transmit 0.25 between the
  // light and a white floor: the floor's diffuse light is scaled by C·0.5 + 0.25.
  auto scene = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <disc center="0 1 0" normal="0 1 0" radius="100"><material diffuse="0"><pattern type="gradient">
      <color-map><entry at="0" color="1 0.2 0" filter="0.5" transmit="0.25"/></color-map>
    </pattern></material></disc>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world(*scene);
  // From below the sheet, straight down onto the floor.
  const Color got = traceOne(world, Ray(Vec3(0.3, 0.5, 0.3), Vec3(0, -1, 0)));
  CHECK(got.r == Approx(0.75f).margin(1e-6));
  CHECK(got.g == Approx(0.35f).margin(1e-6));
  CHECK(got.b == Approx(0.25f).margin(1e-6));
}

TEST_CASE("a sky's layers: the upper ones' filter and transmit show the lower and the background",
          "[render][sky][see-through]") {
  // Bottom: a gradient from black to red along y, opaque. Top: blue (0, 0, 1) with filter
  // 0.25 and transmit 0.5 everywhere. Seen: blue·0.25 + (blue·0.25 + 0.5)·gradient.
  auto layered = parse(R"XML(<render background="0 1 0"/><sky>
      <pattern type="gradient"><color-map><entry at="0" color="0 0 0"/><entry at="1" color="1 0 0"/></color-map></pattern>
      <pattern type="gradient"><color-map><entry at="0" color="0 0 1" filter="0.25" transmit="0.5"/></color-map></pattern>
    </sky>)XML");
  World world(*layered);
  for (double y : {0.2, 0.6}) {
    const Vec3 d = glm::normalize(Vec3(std::sqrt(1 - y * y), y, 0));
    const Color got = traceOne(world, Ray(Vec3(0), d));
    INFO("y = " << y);
    CHECK(got.r == Approx(0.5 * y).margin(1e-5));
    CHECK(got.g == Approx(0.0).margin(1e-6));  // the opaque bottom layer hides the background
    CHECK(got.b == Approx(0.25).margin(1e-6));
  }
  // POV-Ray's rule for #version 3.6 scenes: the bottom layer is weighted by the top's
  // filter plus transmit (0.75), untinted: 0.75·gradient + 0.25·blue.
  auto legacy = parse(R"XML(<render background="0 1 0"/><sky layering="pov-3.6">
      <pattern type="gradient"><color-map><entry at="0" color="0 0 0"/><entry at="1" color="1 0 0"/></color-map></pattern>
      <pattern type="gradient"><color-map><entry at="0" color="0 0 1" filter="0.25" transmit="0.5"/></color-map></pattern>
    </sky>)XML");
  World world3(*legacy);
  for (double y : {0.2, 0.6}) {
    const Vec3 d = glm::normalize(Vec3(std::sqrt(1 - y * y), y, 0));
    const Color got = traceOne(world3, Ray(Vec3(0), d));
    INFO("y = " << y);
    CHECK(got.r == Approx(0.75 * y).margin(1e-5));
    CHECK(got.g == Approx(0.0).margin(1e-6));
    CHECK(got.b == Approx(0.25).margin(1e-6));
  }
  // One layer with transmit: the background shows through it.
  auto single = parse(R"XML(<render background="0 1 0"/><sky>
      <checker color1="1 1 1" color2="1 1 1" transmit1="0.5" transmit2="0.5"/></sky>)XML");
  World world2(*single);
  const Color got = traceOne(world2, Ray(Vec3(0), Vec3(0.3, 0.4, -0.5)));
  CHECK(got == Color(0.5f, 1.0f, 0.5f));
}

TEST_CASE("filter and transmit are exported into each colour, and the sky's layers in order",
          "[povray][pattern][see-through]") {
  auto scene = parse(R"XML(<sky>
      <pattern type="gradient"><color-map><entry at="0" color="1"/></color-map></pattern>
      <brick color1="0.5" filter1="0.25" transmit2="0.75"/></sky>
    <sphere><material><pattern type="bozo">
      <color-map><entry at="0" color="1 0.5 0.25" transmit="0.6"/><entry at="1" color="0" filter="0.8"/></color-map>
    </pattern></material></sphere>
    <box><material><hexagon transmit3="1"/></material></box>)XML");
  PovExport e = exportPov(*scene, {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("[0 rgbft <1, 0.5, 0.25, 0, 0.6>]"));
  CHECK_THAT(e.text, Catch::Contains("[1 rgbft <0, 0, 0, 0.8, 0>]"));
  CHECK_THAT(e.text, Catch::Contains("rgbft <1, 0, 0, 0, 1>"));  // hexagon's color3
  const size_t sky = e.text.find("sky_sphere {");
  REQUIRE(sky != std::string::npos);
  const size_t gradient = e.text.find("gradient", sky), brick = e.text.find("brick", sky);
  REQUIRE(gradient != std::string::npos);
  REQUIRE(brick != std::string::npos);
  CHECK(gradient < brick);
  CHECK_THAT(e.text, Catch::Contains("rgbft <0.5, 0.5, 0.5, 0.25, 0>,"));
  CHECK_THAT(e.text, Catch::Contains("rgbft <0.6, 0.15, 0.15, 0, 0.75>"));
}

TEST_CASE("a negative transmissive subtracts what the ray behind sees", "[render][see-through]") {
  // A sheet of k_a 1 (twice POV-Ray's 0.5 at transmit -1) over a floor lit by ambient: the
  // pixel is 1 minus the floor's 0.3 seen through the sheet, and the floor alone beside it.
  auto scene = parse(R"XML(<render ambient="1" background="0 0 0"/>
    <disc center="0 1 0" normal="0 1 0" radius="1"><material ambient="1" transmissive="-1"/></disc>
    <plane normal="0 1 0" offset="0"><material ambient="0.3"/></plane>)XML");
  World world(*scene);
  const Color through = traceOne(world, Ray(Vec3(0.2, 2, 0.1), Vec3(0, -1, 0)));
  const Color floor = traceOne(world, Ray(Vec3(3, 2, 0.1), Vec3(0, -1, 0)));
  CHECK(floor.g == Approx(0.3f));
  CHECK(through.g == Approx(1.0f - 0.3f));
}

TEST_CASE("a negative light takes light away", "[render][light]") {
  // Two directional lights straight down on a white floor of diffuse 1: 1 - 0.4.
  auto scene = parse(R"XML(<light type="directional" direction="0 -1 0" color="1"/>
    <light type="directional" direction="0 -1 0" color="-0.4"/>
    <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>)XML");
  World world(*scene);
  const Color lit = traceOne(world, Ray(Vec3(0.2, 2, 0.1), Vec3(0, -1, 0)));
  CHECK(lit.r == Approx(0.6f));
}
