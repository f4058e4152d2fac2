// Lights in POV-Ray: colours with intensity, attenuation as fade (exact numbers), parallel,
// spotlight, cylinder and area lights, and the warnings where POV-Ray differs.
#include "pov_test_support.h"

#include "povray/pov_lights.h"

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

// POV-Ray's light fade: 2 / (1 + (d/fd)^fp) (fade_distance fd, fade_power fp).
double povFadeAt(const PovFade& f, double d) {
  if (!f.fade) return f.scale;
  return f.scale * 2.0 / (1.0 + std::pow(d / f.distance, f.power));
}

double lucentAttenuation(const Vec3& abc, double r) {
  return std::min(1.0, 1.0 / (abc.x + abc.y * r + abc.z * r * r));
}

}  // namespace

TEST_CASE("a point light carries color times intensity", "[povray][lights]") {
  Exported e = exportScene(R"XML(<light position="1 2 3" color="1 0.5 0.25" intensity="2"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("light_source {\n  <1, 2, 3>\n  color rgb <2, 1, 0.5>\n}\n"));
}

TEST_CASE("quadratic attenuation maps exactly onto fade_power 2", "[povray][lights]") {
  // 1/(1 + 0.25 r²) = ½ · 2/(1 + (r/2)²)
  PovFade f = povFade(Vec3(1.0, 0.0, 0.25));
  CHECK(f.fade);
  CHECK(f.exact);
  CHECK(f.power == 2.0);
  CHECK(f.distance == 2.0);
  CHECK(f.scale == 0.5);
  CHECK(f.exactBeyond == 0.0);
  for (double r : {0.0, 0.5, 1.0, 3.0, 10.0, 100.0})
    CHECK(povFadeAt(f, r) == Approx(lucentAttenuation(Vec3(1.0, 0.0, 0.25), r)).epsilon(1e-14));

  Exported e = exportScene(R"XML(<light position="0 4 0" attenuation="1 0 0.25"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(e.has("  color rgb <0.5, 0.5, 0.5>\n  fade_distance 2\n  fade_power 2\n"));
}

TEST_CASE("linear attenuation maps exactly onto fade_power 1", "[povray][lights]") {
  PovFade f = povFade(Vec3(2.0, 0.5, 0.0));
  CHECK(f.exact);
  CHECK(f.power == 1.0);
  CHECK(f.distance == 4.0);
  CHECK(f.scale == 0.25);
  for (double r : {0.0, 1.0, 7.0, 50.0})
    CHECK(povFadeAt(f, r) == Approx(lucentAttenuation(Vec3(2.0, 0.5, 0.0), r)).epsilon(1e-14));
}

TEST_CASE("attenuation with a < 1 is exact only where the clamp is inactive", "[povray][lights]") {
  // min(1, 1/(0.5 + 0.5 r²)) is clamped for r < 1.
  PovFade f = povFade(Vec3(0.5, 0.0, 0.5));
  CHECK(f.exactBeyond == 1.0);
  CHECK(povFadeAt(f, 2.0) == Approx(lucentAttenuation(Vec3(0.5, 0.0, 0.5), 2.0)));
  CHECK(povFadeAt(f, 0.5) > 1.0);  // POV-Ray's fade exceeds 1 near the light

  Exported e = exportScene(R"XML(<light position="0 4 0" attenuation="0.5 0 0.5"/>)XML");
  CHECK(e.pov.ok());
  CHECK(e.messages() ==
        "test.xml:3:1: warning: point light: attenuation \"0.5 0 0.5\" maps onto POV-Ray's fade "
        "exactly only 1 or more from the light, where min(1, ...) stops clamping\n");
}

TEST_CASE("attenuation with both b and c is approximated with a warning", "[povray][lights]") {
  PovFade f = povFade(Vec3(1.0, 0.1, 0.01));
  CHECK_FALSE(f.exact);
  CHECK(f.power == 2.0);
  CHECK(f.distance == Approx(10.0));
  Exported e = exportScene(R"XML(<light position="0 4 0" attenuation="1 0.1 0.01"/>)XML");
  CHECK(e.pov.ok());
  CHECK(e.messages() ==
        "test.xml:3:1: warning: point light: attenuation with both b and c has "
        "no POV-Ray equivalent; the linear term b is dropped\n");
}

TEST_CASE("a constant attenuation scales the colour", "[povray][lights]") {
  PovFade f = povFade(Vec3(4.0, 0.0, 0.0));
  CHECK_FALSE(f.fade);
  CHECK(f.scale == 0.25);
  CHECK(povFade(Vec3(0.5, 0.0, 0.0)).scale == 1.0);  // min(1, 2)
}

TEST_CASE("a directional light is a parallel light far behind the scene", "[povray][lights]") {
  Exported e = exportScene(R"XML(<light type="directional" direction="0 -2 0" color="0.5"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(
      e.has("light_source {\n  <0, 1000000, 0>\n  color rgb <0.5, 0.5, 0.5>\n  parallel\n"
            "  point_at <0, 0, 0>\n}\n"));
}

TEST_CASE("a spot light is a spotlight with its tightness", "[povray][lights]") {
  Exported e = exportScene(
      R"XML(<light type="spot" position="0 5 0" direction="0 -1 0" angle="40" inner="25"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  spotlight\n  point_at <0, 4, 0>\n  radius 25\n  falloff 40\n  tightness 0\n"));
  Exported tight = exportScene(
      R"XML(<light type="spot" position="0 5 0" direction="0 -1 0" angle="40" tightness="12.5"/>)XML");
  REQUIRE(tight.pov.ok());
  CHECK(tight.pov.issues.empty());
  CHECK(tight.has("  radius 40\n  falloff 40\n  tightness 12.5\n"));
}

TEST_CASE("POV-Ray's fade is written as it is, the colour unscaled", "[povray][lights]") {
  Exported e = exportScene(
      R"XML(<light position="0 5 0" color="0.5" fade-distance="3" fade-power="2.5"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(
      e.has("light_source {\n  <0, 5, 0>\n  color rgb <0.5, 0.5, 0.5>\n  fade_distance 3\n"
            "  fade_power 2.5\n}\n"));
}

TEST_CASE("shadowless: POV-Ray's light without shadows has no highlights", "[povray][lights]") {
  const std::string shiny =
      R"XML(<sphere center="0 0 0" radius="1"><material specular="0.5"/></sphere>)XML";
  // shadows and highlights off: POV-Ray's shadowless, exactly.
  Exported both =
      exportScene(R"XML(<light position="0 5 0" shadows="false" highlights="false"/>)XML" + shiny);
  REQUIRE(both.pov.ok());
  CHECK(both.pov.issues.empty());
  CHECK(both.has("  color rgb <1, 1, 1>\n  shadowless\n}\n"));
  // Either alone has no POV-Ray equivalent where a material has highlights.
  Exported noShadows = exportScene(R"XML(<light position="0 5 0" shadows="false"/>)XML" + shiny);
  CHECK(noShadows.messages().find("POV-Ray's shadowless lights give no specular highlights") !=
        std::string::npos);
  Exported noHighlights =
      exportScene(R"XML(<light position="0 5 0" highlights="false"/>)XML" + shiny);
  CHECK(noHighlights.messages().find("POV-Ray's lights with shadows always give highlights") !=
        std::string::npos);
  CHECK_FALSE(noHighlights.has("shadowless"));
}

TEST_CASE("a cylindrical light is POV-Ray's cylinder with its radius, falloff and tightness",
          "[povray][lights]") {
  Exported e = exportScene(
      R"XML(<light type="cylindrical" position="0 5 0" look-at="0 0 0" radius="0.5" falloff="2" tightness="1.5" color="0.5"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(
      e.has("light_source {\n  <0, 5, 0>\n  color rgb <0.5, 0.5, 0.5>\n  cylinder\n"
            "  point_at <0, 4, 0>\n  radius 0.5\n  falloff 2\n  tightness 1.5\n}\n"));

  // The defaults are written too, though they are POV-Ray's own.
  Exported plain = exportScene(R"XML(<light type="cylindrical" direction="1 0 0"/>)XML");
  CHECK(
      plain.has("  cylinder\n  point_at <1, 0, 0>\n  radius 0.75\n  falloff 1\n"
                "  tightness 0\n"));
  CHECK_FALSE(plain.has("parallel"));  // implied by cylinder
}

TEST_CASE("a cylindrical light's attenuation is POV-Ray's fade, its beam not scaled",
          "[povray][lights]") {
  // POV-Ray fades a cylinder light with the distance along its axis, as Lucent attenuates it.
  Exported e = exportScene(
      R"XML(<light type="cylindrical" position="0 4 0" attenuation="1 0 0.25" shadows="false"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.pov.issues.empty());
  CHECK(e.has("  color rgb <0.5, 0.5, 0.5>\n  fade_distance 2\n  fade_power 2\n  cylinder\n"));
  CHECK(e.has("  tightness 0\n  shadowless\n}\n"));

  // Placed in the world; radius and falloff stay distances, as POV-Ray never scales them.
  Exported placed = exportScene(R"XML(<group transform="scale(2) translate(1 0 0)">
      <light type="cylindrical" position="0 3 0" radius="0.2" falloff="0.4"/></group>)XML");
  REQUIRE(placed.pov.ok());
  CHECK(
      placed.has("  <1, 6, 0>\n  color rgb <1, 1, 1>\n  cylinder\n  point_at <1, 5, 0>\n"
                 "  radius 0.2\n  falloff 0.4\n"));
}

TEST_CASE("area lights keep their grid, uneven POV-Ray weights are warned about",
          "[povray][lights]") {
  Exported even = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="4 2"/>)XML");
  REQUIRE(even.pov.ok());
  CHECK(even.pov.issues.empty());
  CHECK(even.has("  area_light <2, 0, 0>, <0, 0, 1>, 4, 2\n"));

  Exported odd = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="5 4"/>)XML");
  CHECK(odd.pov.ok());
  CHECK(odd.messages() ==
        "test.xml:3:1: warning: area light: POV-Ray weights a 5x4 sample grid unevenly (edge "
        "samples count less); it matches Lucent's plain average only for 2, 4, 8, ... samples "
        "per side\n");
}

TEST_CASE("an adaptive area light is POV-Ray's adaptive, whose weights it shares",
          "[povray][lights]") {
  Exported e = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="5 9" adaptive="2"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  area_light <2, 0, 0>, <0, 0, 1>, 5, 9\n  adaptive 2\n"));
  CHECK(e.pov.issues.empty());  // no warning about uneven weights: they are the definition

  Exported zero = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="4" adaptive="0"/>)XML");
  CHECK(zero.has("  area_light <2, 0, 0>, <0, 0, 1>, 4, 4\n  adaptive 0\n"));
  Exported plain =
      exportScene(R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="4"/>)XML");
  CHECK_FALSE(plain.has("adaptive"));
}

TEST_CASE("circular and oriented area lights are POV-Ray's circular and orient",
          "[povray][lights]") {
  Exported e = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 2" samples="4" adaptive="1" circular="true" orient="true"/>)XML");
  REQUIRE(e.pov.ok());
  CHECK(e.has("  area_light <2, 0, 0>, <0, 0, 2>, 4, 4\n  adaptive 1\n  circular\n  orient\n"));
  CHECK(e.pov.issues.empty());  // the same disc, the same turn
  Exported round = exportScene(
      R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="4" adaptive="0" circular="true"/>)XML");
  CHECK(round.has("  adaptive 0\n  circular\n"));
  CHECK_FALSE(round.has("orient"));
  Exported plain =
      exportScene(R"XML(<light type="area" position="0 5 0" u="2 0 0" v="0 0 1" samples="4"/>)XML");
  CHECK_FALSE(plain.has("circular"));
}

TEST_CASE("a light without shadows is shadowless, with a warning when highlights exist",
          "[povray][lights]") {
  Exported plain = exportScene(R"XML(<light position="0 5 0" shadows="false"/>
      <sphere><material diffuse="0.5"/></sphere>)XML");
  CHECK(plain.has("  shadowless\n"));
  CHECK(plain.pov.issues.empty());

  Exported shiny = exportScene(R"XML(<light position="0 5 0" shadows="false"/>
      <sphere><material diffuse="0.5" specular="0.3"/></sphere>)XML");
  CHECK(shiny.messages() ==
        "test.xml:3:1: warning: point light with shadows=\"false\": "
        "POV-Ray's shadowless lights give no specular highlights\n");
}

TEST_CASE("a light in the hierarchy is written where it is placed in the world",
          "[povray][lights]") {
  Exported e = exportScene(R"XML(
    <defs><group id="lamp"><light type="spot" position="0 2 0" direction="1 0 0" angle="20"/><sphere radius="0.1" center="0 2 0" shadows="false"/></group></defs>
    <use ref="lamp" transform="rotate-y(90) translate(5 0 0)"/>)XML");
  REQUIRE(e.pov.ok());
  // rotate-y(90) turns +x to -z: the spot at (5, 2, 0) points along -z.
  CHECK(e.has(
      "light_source {\n  <5, 2, 0>\n  color rgb <1, 1, 1>\n  spotlight\n  point_at <5, 2, -1>\n"));
  CHECK(e.has("no_shadow"));
}
