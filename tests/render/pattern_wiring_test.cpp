// The contract's patterns, normals and sky as a scene uses them: parsed, shaded per pixel
// against their definitions, and exported.
#include "scene_builder.h"

#include "lang/parser.h"
#include "povray/pov_export.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::test;

namespace {

std::unique_ptr<Scene> parse(const std::string& body) {
  ParseResult r = parseSceneString("<scene version=\"1\"><camera position=\"0 5 5\" look-at=\"0 0 0\"/>" + body +
                                       "</scene>",
                                   "pattern_wiring.xml");
  std::string all;
  for (const Diagnostic& d : r.diagnostics.all()) all += d.str() + "\n";
  INFO(all);
  REQUIRE(r.scene);
  return std::move(r.scene);
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
