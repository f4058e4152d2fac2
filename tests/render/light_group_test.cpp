// <light-group> (POV-Ray's light_group) against POV-Ray 3.7's rules, read in its source
// (parser: Parse_Light_Group, Promote_Local_Lights, Set_CSG_Children_Flag; render:
// ComputeDiffuseLight and the shadow rays) and checked by rendering with POV-Ray: a
// group's lights light only its geometry; the other lights light it only with
// global-lights="true"; nested groups take the innermost group's lights and the outermost
// group's global-lights; every object shadows every light. Each scene is a row of white
// diffuse balls (diffuse 1, no ambient) seen head on, lit from the camera's side by lights
// of pure colours, so a ball's centre shows the sum of the colours that light it.
#include "scene_builder.h"

#include "../support/scene_text.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;
using namespace lucent::test;

namespace {

const Color kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1), kBlack(0.0f);

// A ball of radius 0.9 at x, white and diffuse (its centre faces the lights head on).
std::string ball(double x) {
  return "<sphere center=\"" + std::to_string(x) + " 0 0\" radius=\"0.9\" material=\"white\"/>";
}
// A point light of that colour far along +z (towards the camera).
std::string lamp(const std::string& color, double z = 100) {
  return "<light position=\"0 0 " + std::to_string(z) + "\" color=\"" + color + "\"/>";
}

// N.L at the front of the ball at x for a lamp at (0, 0, 100): 1 for the ball at 0.
float facing(double x) { return float(99.1 / std::sqrt(99.1 * 99.1 + x * x)); }

// The colour at the centre of the ball at x, seen from +z.
Color centreOf(const Scene& scene, double x) {
  World world(scene);
  return traceOne(world, Ray(Vec3(x, 0, 10), Vec3(0, 0, -1)));
}

void checkColor(const Color& got, const Color& want) {
  INFO("got " << got.r << " " << got.g << " " << got.b);
  for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-4));
}

std::unique_ptr<Scene> sceneOf(const std::string& body) {
  return parseClean("<material id=\"white\" diffuse=\"1\"/>" + body);
}

}  // namespace

TEST_CASE("a light group's light lights its objects only, the global light the others",
          "[render][light-group]") {
  auto s = sceneOf(lamp("0 0 1") + "<light-group>" + lamp("1 0 0") + ball(-1) + "</light-group>" +
                   ball(2));
  checkColor(centreOf(*s, -1), kRed * facing(-1));  // not the global blue: global-lights is off
  checkColor(centreOf(*s, 2), kBlue * facing(2));   // not the group's red
}

TEST_CASE("global-lights=true lets the global lights into a light group", "[render][light-group]") {
  auto s = sceneOf(lamp("0 0 1") + "<light-group global-lights=\"true\">" + lamp("1 0 0") +
                   ball(-1) + "</light-group>");
  checkColor(centreOf(*s, -1), (kRed + kBlue) * facing(-1));
}

TEST_CASE("nested light groups: the innermost group's lights, the outermost's global-lights",
          "[render][light-group]") {
  // POV-Ray 3.7 renders the inner ball green only: the outer red does not reach into the
  // inner group, and the outer group's global_lights off overrides the inner one's on.
  auto s = sceneOf(lamp("0 0 1") + "<light-group>" + lamp("1 0 0") +
                   "<light-group global-lights=\"true\">" + lamp("0 1 0") + ball(-3) +
                   "</light-group>" + ball(-1) + "</light-group>");
  checkColor(centreOf(*s, -3), kGreen * facing(-3));
  checkColor(centreOf(*s, -1), kRed * facing(-1));
}

TEST_CASE("a light deeper in a light group is global, and a group without lights lights nothing",
          "[render][light-group]") {
  // As POV-Ray's light_source inside a union inside a light_group: a global light.
  auto s = sceneOf("<light-group><group>" + lamp("1 0 0") + ball(1) + "</group>" + lamp("0 1 0") +
                   "</light-group>" + ball(-3) + "<light-group>" + ball(3) + "</light-group>");
  checkColor(centreOf(*s, 1), kGreen * facing(1));
  checkColor(centreOf(*s, -3), kRed * facing(-3));
  // Its objects are cut off from the global lights all the same (global-lights off).
  checkColor(centreOf(*s, 3), kBlack);
}

TEST_CASE("a light group's transform moves its lights with its objects", "[render][light-group]") {
  // The red light at z = 100 in the group's frame, turned to +x by the group: the ball,
  // moved to x = 0 with it, is lit from +x, so its centre facing +z is lit at grazing
  // incidence (N.L = 0: black) while its side facing +x is fully lit.
  auto s = sceneOf("<light-group transform=\"rotate-y(90)\">" + lamp("1 0 0") + ball(0) +
                   "</light-group>");
  checkColor(centreOf(*s, 0), kBlack);
  World world(*s);
  checkColor(traceOne(world, Ray(Vec3(10, 0, 0), Vec3(-1, 0, 0))), kRed);
}

TEST_CASE("objects outside a light group shadow its lights, and its objects the global ones",
          "[render][light-group]") {
  // A floor y = 0 in the group lit by the group's red light from above; a blocker outside
  // the group above x = 0, and a ball inside it above x = 4, lit by nothing but casting
  // shadows. A global blue light from above lights a second floor patch (outside the
  // group) under the group's ball.
  auto s = parseClean(R"(
    <material id="white" diffuse="1"/>
    <light type="directional" direction="0 -1 0" color="0 0 1"/>
    <light-group>
      <light type="directional" direction="0 -1 0" color="1 0 0"/>
      <box min="-10 -1 -10" max="10 0 -1" material="white"/>
      <sphere center="4 3 2" radius="0.5" material="white"/>
    </light-group>
    <box min="-10 -1 1" max="10 0 10" material="white"/>
    <box min="-0.5 2.5 -3" max="0.5 3.5 -2" material="white"/>)");
  World world(*s);
  auto floorAt = [&](double x, double z) {
    return traceOne(world, Ray(Vec3(x, 1, z), Vec3(0, -1, 0)));
  };
  checkColor(floorAt(3, -2.5), kRed);    // the group's floor, in the open
  checkColor(floorAt(0, -2.5), kBlack);  // under the blocker from outside the group
  checkColor(floorAt(0, 2), kBlue);      // the other floor: the global light only
  checkColor(floorAt(4, 2), kBlack);     // under the group's ball: its shadow of the blue
}

TEST_CASE("a <use> of a light group is an instance with its own lights", "[render][light-group]") {
  auto s = sceneOf("<defs><light-group id=\"g\">" + lamp("1 0 0", 100) + ball(0) +
                   "</light-group></defs>"
                   "<use ref=\"g\" transform=\"translate(-2 0 0)\"/>"
                   "<use ref=\"g\" transform=\"translate(2 0 0) rotate-y(90)\"/>");
  // The first instance, at x = -2, is lit head on by its own red light at (-2, 0, 100); the
  // second, turned to (0, 0, -2), by its own light alone, turned to (100, 0, -2): from +x,
  // so its front (facing +z, where the first's light would shine) stays black.
  checkColor(centreOf(*s, -2), kRed);
  World world(*s);
  checkColor(traceOne(world, Ray(Vec3(0, 0, 10), Vec3(0, 0, -1))), kBlack);
  checkColor(traceOne(world, Ray(Vec3(10, 0, -2), Vec3(-1, 0, 0))), kRed);
}
