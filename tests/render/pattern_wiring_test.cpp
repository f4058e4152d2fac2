// The contract's patterns, normals and sky as a scene uses them: parsed, shaded per pixel
// against their definitions, and exported.
#include "scene_builder.h"

#include "../support/scene_text.h"
#include "lang/parser.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  return parseValid(body, "pattern_wiring.xml", "<camera position=\"0 5 5\" look-at=\"0 0 0\"/>");
}

}  // namespace

TEST_CASE("a gradient pattern's colour map colours a plane exactly", "[render][pattern]") {
  // Emissive-free, lit by ambient alone: the pixel is ambient * T with T = map(fract(x/2)).
  auto scene = parse(R"XML(<render ambient="1"/>
    <plane normal="0 1 0" offset="0"><material ambient="1">
      <pattern type="gradient" axis="1 0 0" transform="scale(2)">
        <color-map><entry at="0" color="0 0 0"/><entry at="1" color="1 0.5 0.25"/></color-map>
      </pattern></material></plane>)XML");
  World world(*scene);
  for (double x : {0.3, 0.9, 1.7, 2.5, -0.4}) {
    Color c = traceOne(world, Ray(Vec3(x, 1, 0.2), Vec3(0, -1, 0)));
    const double v = x / 2 - std::floor(x / 2);
    INFO("x = " << x);
    CHECK(c.r == Approx(v).margin(1e-5));
    CHECK(c.g == Approx(0.5 * v).margin(1e-5));
    CHECK(c.b == Approx(0.25 * v).margin(1e-5));
  }
}

TEST_CASE("a sky colours rays that leave the scene by their direction", "[render][sky]") {
  auto scene = parse(R"XML(<sky><pattern type="gradient" axis="0 1 0">
      <color-map><entry at="0" color="1 1 1"/><entry at="1" color="0 0 1"/></color-map>
    </pattern></sky>)XML");
  World world(*scene);
  for (double y : {0.1, 0.5, 0.9}) {
    const Vec3 d = glm::normalize(Vec3(std::sqrt(1 - y * y), y, 0));
    Color c = traceOne(world, Ray(Vec3(0), d));
    INFO("y = " << y);
    CHECK(c.r == Approx(1 - y).margin(1e-5));
    CHECK(c.b == Approx(1.0).margin(1e-5));
  }
}

TEST_CASE("a normal perturbation changes shading only, never towards the back",
          "[render][pattern]") {
  auto planeWith = [](const std::string& normal) {
    return R"XML(<plane normal="0 1 0" offset="0"><material diffuse="1">)XML" + normal +
           R"XML(</material></plane><light type="point" position="0.3 4 0.2"/><render ambient="0"/>)XML";
  };
  auto flat = parse(planeWith(""));
  auto bumpy = parse(planeWith("<normal type=\"bumps\" depth=\"3\" transform=\"scale(0.2)\"/>"));
  World a(*flat), b(*bumpy);
  int differ = 0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 o(-1 + 0.04 * i, 2, 0.37);
    Hit ha, hb;
    // The geometry is the same: hits at the same distance.
    REQUIRE(a.intersect(Ray(o, Vec3(0, -1, 0)), ha));
    REQUIRE(b.intersect(Ray(o, Vec3(0, -1, 0)), hb));
    CHECK(ha.t == hb.t);
    const Color ca = traceOne(a, Ray(o, Vec3(0, -1, 0))), cb = traceOne(b, Ray(o, Vec3(0, -1, 0)));
    if (std::abs(ca.r - cb.r) > 1e-3f) ++differ;
    CHECK(cb.r >= 0.0f);
    CHECK(cb.r <= 1.0f + 1e-6f);  // N.L <= 1: a unit normal
  }
  CHECK(differ > 25);  // the bumps show
}

TEST_CASE("patterns, normals and the sky are exported as POV-Ray's", "[povray][pattern]") {
  auto scene = parse(R"XML(<sky><pattern type="bozo" turbulence="0.5"/></sky>
    <sphere><material><pattern type="marble" frequency="2" wave="sine" turbulence="0.3 0 0.3">
      <color-map><entry at="0" color="1 1 1"/><entry at="1" color="0 0 0"/></color-map></pattern>
      <normal type="ripples" depth="0.4"/></material></sphere>)XML");
  PovExport e = exportPov(*scene, {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("sky_sphere {"));
  CHECK_THAT(e.text, Catch::Contains("bozo"));
  CHECK_THAT(e.text, Catch::Contains("marble"));
  CHECK_THAT(e.text, Catch::Contains("frequency 2"));
  CHECK_THAT(e.text, Catch::Contains("sine_wave"));
  CHECK_THAT(e.text, Catch::Contains("turbulence <0.3, 0, 0.3>"));
  CHECK_THAT(e.text, Catch::Contains("ripples 0.4"));
  CHECK_THAT(e.text, Catch::Contains("[0 rgbft <1, 1, 1, 0, 0>]"));
}

TEST_CASE("frequency, phase and wave shape the value before the colour map", "[render][pattern]") {
  // gradient x, frequency 2, phase 0.25: v = fmod(2·fract(x) + 0.25, 1.00001) (POV-Ray wraps
  // by 1.00001 so that a value of exactly 1 stays 1), then the wave.
  auto shaded = [](const std::string& attrs, double x) {
    auto scene = parse(R"XML(<render ambient="1"/>
      <plane normal="0 1 0" offset="0"><material ambient="1">
        <pattern type="gradient" axis="1 0 0" )XML" +
                       attrs + R"XML(/></material></plane>)XML");
    World world(*scene);
    return traceOne(world, Ray(Vec3(x, 1, 0.2), Vec3(0, -1, 0))).r;
  };
  for (double x : {0.1, 0.3, 0.45, 0.7, 1.9}) {
    INFO("x = " << x);
    const double fx = x - std::floor(x);
    const double v = std::fmod(2 * fx + 0.25, 1.00001);
    // Without a map the value is the grey level.
    CHECK(shaded("frequency=\"2\" phase=\"0.25\"", x) == Approx(v).margin(1e-5));
    // triangle: up then down, 2v below 1/2 and 2(1 − v) above.
    CHECK(shaded("frequency=\"2\" phase=\"0.25\" wave=\"triangle\"", x) ==
          Approx(v < 0.5 ? 2 * v : 2 * (1 - v)).margin(1e-5));
    // poly with exponent 3: v³.
    CHECK(shaded("frequency=\"2\" phase=\"0.25\" wave=\"poly\" exponent=\"3\"", x) ==
          Approx(v * v * v).margin(1e-5));
  }
}

TEST_CASE("a colour map is constant before its first entry and after its last",
          "[render][pattern]") {
  auto scene = parse(R"XML(<render ambient="1"/>
    <plane normal="0 1 0" offset="0"><material ambient="1">
      <pattern type="gradient" axis="1 0 0">
        <color-map><entry at="0.25" color="0.2 0.2 0.2"/><entry at="0.5" color="1 0 0"/>
                   <entry at="0.5" color="0 0 1"/><entry at="0.75" color="0 1 0"/></color-map>
      </pattern></material></plane>)XML");
  World world(*scene);
  auto at = [&](double x) { return traceOne(world, Ray(Vec3(x, 1, 0.2), Vec3(0, -1, 0))); };
  CHECK(at(0.1).r == Approx(0.2).margin(1e-5));    // before the first entry
  CHECK(at(0.375).r == Approx(0.6).margin(1e-5));  // halfway from 0.2 grey to red
  CHECK(at(0.375).g == Approx(0.1).margin(1e-5));
  CHECK(at(0.49).b == Approx(0.2 * 0.04).margin(1e-5));  // grey to red: 0.04 of grey's blue left
  CHECK(at(0.51).b == Approx(1 - 0.04).margin(1e-5));    // two entries at 0.5: a sharp edge to blue
  CHECK(at(0.9).g == Approx(1.0).margin(1e-5));          // after the last
  CHECK(at(0.9).b == Approx(0.0).margin(1e-5));
}

TEST_CASE("a sky's transform turns the directions it is evaluated on, and it hides the background",
          "[render][sky]") {
  // gradient y turned by rotate-z(90): a world direction d is seen in the sky's frame as
  // rotate-z(-90)·d, whose y is −d.x, so directions with −d.x = s in (0, 1) have value s.
  auto scene = parse(
      R"XML(<render background="0 1 0"/><sky transform="rotate-z(90)"><pattern type="gradient">
      <color-map><entry at="0" color="0 0 0"/><entry at="1" color="1 0 0"/></color-map>
    </pattern></sky>)XML");
  World world(*scene);
  for (double s : {0.2, 0.6, 0.9}) {
    const Vec3 d = glm::normalize(Vec3(-s, 0, -std::sqrt(1 - s * s)));
    Color c = traceOne(world, Ray(Vec3(0), d));
    INFO("s = " << s);
    CHECK(c.r == Approx(s).margin(1e-5));
    CHECK(c.g == Approx(0.0).margin(1e-6));  // the background is not seen
  }
}

TEST_CASE("a bumpy sphere casts the same shadow as a smooth one", "[render][pattern]") {
  auto sceneWith = [](const std::string& normal) {
    return R"XML(<render ambient="0"/><light type="point" position="0 6 0"/>
      <plane normal="0 1 0" offset="0"><material diffuse="1"/></plane>
      <sphere center="0 2 0" radius="1"><material diffuse="1">)XML" +
           normal + R"XML(</material></sphere>)XML";
  };
  auto flat = parse(sceneWith(""));
  auto bumpy = parse(sceneWith("<normal type=\"bumps\" depth=\"2\" transform=\"scale(0.1)\"/>"));
  World a(*flat), b(*bumpy);
  for (int i = 0; i < 40; ++i) {
    // Points on the floor across the shadow's edge (radius 1.5 at y = 0 from the light at 6).
    const Vec3 o(0.05 * i, 0.5, 0.013);
    const Ray down(o, Vec3(0, -1, 0));
    INFO("x = " << o.x);
    CHECK(traceOne(a, down).r == traceOne(b, down).r);
  }
}

TEST_CASE("planar is 1 − |y| in its band and its normal a ridge along y = 0", "[render][pattern]") {
  // POV-Ray 3.7's values (docs/povray-semantics.md, planar): a wall facing -z lit by its
  // ambient alone shows 1 − |y|, 0 beyond |y| = 1; scaled by 2 the band is twice as wide.
  auto wall = [](const std::string& pattern) {
    return parse(R"XML(<render ambient="1"/><plane normal="0 0 -1" offset="0">
      <material ambient="1">)XML" +
                 pattern + R"XML(</material></plane>)XML");
  };
  auto grey = [](const Scene& scene, double y) {
    World world(scene);
    return traceOne(world, Ray(Vec3(0.3, y, -1), Vec3(0, 0, 1))).r;
  };
  auto plain = wall(R"X(<pattern type="planar"/>)X");
  auto wide = wall(R"X(<pattern type="planar" transform="scale(2)"/>)X");
  for (double y : {1.1, 0.9, 0.5, 0.1, -0.1, -0.7, -1.1}) {
    INFO("y = " << y);
    CHECK(grey(*plain, y) == Approx(std::abs(y) > 1 ? 0.0 : 1 - std::abs(y)).margin(1e-6));
    CHECK(grey(*wide, y) == Approx(1 - std::abs(y) / 2).margin(1e-6));
  }
  // normal { planar 3 } under a parallel light from (0, 1, -1): POV-Ray renders 0.9191 above
  // the plane y = 0, 0.3939 below and 0.7071 (unperturbed) beyond the band: the normal
  // leans by 2·depth/15 towards ±y (the slope of the four-sample gradient).
  auto ridge = parse(R"XML(<render ambient="0"/><plane normal="0 0 -1" offset="0">
      <material diffuse="1"><normal type="planar" depth="3"/></material></plane>
      <light type="directional" direction="0 -1 1"/>)XML");
  World world(*ridge);
  auto lit = [&](double y) { return traceOne(world, Ray(Vec3(0.3, y, -1), Vec3(0, 0, 1))).r; };
  const double up = (0.4 + 1) / (std::sqrt(2.0) * std::sqrt(1.16));
  const double down = (1 - 0.4) / (std::sqrt(2.0) * std::sqrt(1.16));
  for (double y : {0.3, 0.5, 0.9}) CHECK(lit(y) == Approx(up).margin(1e-5));
  for (double y : {-0.3, -0.5, -0.9}) CHECK(lit(y) == Approx(down).margin(1e-5));
  CHECK(lit(1.5) == Approx(std::sqrt(0.5)).margin(1e-6));
  CHECK(lit(-2.0) == Approx(std::sqrt(0.5)).margin(1e-6));
  PovExport e = exportPov(*ridge, {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("planar 3"));
}

TEST_CASE("keep-facing-away keeps a bent normal that faces away from the viewer, as POV-Ray",
          "[render][pattern]") {
  // normal { planar 15 } on a wall facing -z leans the normal below y = 0 by 2·15/15 = 2
  // towards -y: n = (0, -2, -1)/√5. Seen along (0, -0.8, 0.6) that normal faces away
  // (n·v = -1/√5). Lit from (0, -1, -1): POV-Ray shades with n, N·L = 3/√10; Lucent's
  // default shades with the wall's own normal there, N·L = 1/√2.
  auto wall = [](const std::string& keep) {
    return parse(R"XML(<render ambient="0"/><plane normal="0 0 -1" offset="0">
      <material diffuse="1"><normal type="planar" depth="15")XML" +
                 keep + R"XML(/></material></plane>
      <light type="directional" direction="0 1 1"/>)XML");
  };
  auto lucentRule = wall(""), povrayRule = wall(" keep-facing-away=\"true\"");
  const Vec3 d(0, -0.8, 0.6);
  for (double y : {-0.3, -0.5, -0.7}) {
    INFO("y = " << y);
    const Ray ray(Vec3(0.3, y, 0) - 1.25 * d, d);
    World lucent(*lucentRule), povray(*povrayRule);
    CHECK(traceOne(lucent, ray).r == Approx(std::sqrt(0.5)).margin(1e-6));
    CHECK(traceOne(povray, ray).r == Approx(3 / std::sqrt(10.0)).margin(1e-6));
  }
}

TEST_CASE("a mirror ray that a bent normal sends below the surface is turned back, as POV-Ray",
          "[render][pattern]") {
  // normal { planar 3.125 } on a mirror wall facing -z leans the normal below y = 0 by
  // 2·3.125/15 = 5/12 towards -y: n = (0, -5, -12)/13, which faces the viewer looking along
  // d = (0, -0.8, 0.6) but mirrors d into the wall, to (0, -0.98935, 0.14556). POV-Ray
  // reflects that once more about the wall's normal, to (0, -0.98935, -0.14556): back to
  // the viewer's side, where an emissive plane at z = -2 is seen.
  auto scene = parse(R"XML(<render ambient="0"/><plane normal="0 0 -1" offset="0">
      <material reflective="1"><normal type="planar" depth="3.125"/></material></plane>
      <plane normal="0 0 1" offset="-2"><material emissive="0.25 0.5 1"/></plane>)XML");
  World world(*scene);
  const Vec3 d(0, -0.8, 0.6);
  for (double y : {-0.3, -0.5, -0.7}) {
    INFO("y = " << y);
    const Color seen = traceOne(world, Ray(Vec3(0.3, y, 0) - 1.25 * d, d));
    CHECK(seen.r == Approx(0.25).margin(1e-6));
    CHECK(seen.g == Approx(0.5).margin(1e-6));
    CHECK(seen.b == Approx(1.0).margin(1e-6));
  }
}

TEST_CASE("quilted, the fractals and dents as a pigment are exported with POV-Ray's syntax",
          "[povray][pattern]") {
  auto scene = parse(R"XML(
    <sphere><material><pattern type="quilted" control0="0.25" frequency="2"/>
      <normal type="quilted" depth="0.6"/></material></sphere>
    <sphere center="3 0 0"><material><pattern type="julia" c="-0.5 0.5" iterations="20" power="7"
      interior="1 2"/><normal type="mandel" iterations="30" depth="0.4"/></material></sphere>
    <sphere center="6 0 0"><material><pattern type="magnet" magnet-type="2" form="julia"
      c="1.1 0.3" iterations="25" exterior="6 0.01"/></material></sphere>
    <sphere center="9 0 0"><material><pattern type="magnet" iterations="5"/>
      <normal type="quilted" depth="0.5" frequency="0"/></material></sphere>
    <sphere center="12 0 0"><material><pattern type="dents"/></material></sphere>)XML");
  PovExport e = exportPov(*scene, {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("quilted\n"));
  CHECK_THAT(e.text, Catch::Contains("control0 0.25 control1 1"));
  CHECK_THAT(e.text, Catch::Contains("frequency 2"));
  CHECK_THAT(e.text, Catch::Contains("quilted 0.6"));
  CHECK_THAT(e.text, Catch::Contains("julia <-0.5, 0.5>, 20"));
  CHECK_THAT(e.text, Catch::Contains("exponent 7"));
  CHECK_THAT(e.text, Catch::Contains("interior 1, 2"));
  CHECK_THAT(e.text, Catch::Contains("mandel 30 0.4"));
  CHECK_THAT(e.text, Catch::Contains("magnet 2 julia <1.1, 0.3>, 25"));
  CHECK_THAT(e.text, Catch::Contains("exterior 6, 0.01"));
  CHECK_THAT(e.text, Catch::Contains("magnet 1 mandel 5"));
  CHECK_THAT(e.text, Catch::Contains("dents\n"));
}

TEST_CASE("pigment-pattern's value is the grey level of its pigment", "[render][pattern]") {
  // A wall lit by its ambient alone shows the value: over a checker of two colours, POV-Ray's
  // grey 0.297 r + 0.589 g + 0.114 b of each (docs/scene-language.md, pigment-pattern).
  auto scene = parse(R"XML(<render ambient="1"/><plane normal="0 0 -1" offset="0">
      <material ambient="1"><pattern type="pigment-pattern"><pigment>
        <checker color1="1 0.5 0" color2="0 0.2 1" transform="translate(0 0 0.5)"/>
      </pigment></pattern></material></plane>)XML");
  World world(*scene);
  auto grey = [&](double x, double y) {
    return traceOne(world, Ray(Vec3(x, y, -1), Vec3(0, 0, 1))).r;
  };
  const double first = 0.297 * 1 + 0.589 * 0.5, second = 0.589 * 0.2 + 0.114 * 1;
  // The wall z = 0 lies in the checker's cubes from z = -1 (translated by 0.5).
  CHECK(grey(0.5, 0.5) == Approx(second).margin(1e-6));
  CHECK(grey(1.5, 0.5) == Approx(first).margin(1e-6));
  CHECK(grey(-0.5, 0.5) == Approx(first).margin(1e-6));
  CHECK(grey(-0.5, -0.5) == Approx(second).margin(1e-6));
  PovExport e = exportPov(*scene, {});
  REQUIRE(e.ok());
  CHECK_THAT(e.text, Catch::Contains("pigment_pattern {"));
}
