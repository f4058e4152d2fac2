// POV-Ray's global_settings, background, sky_sphere and fog (sdl/pov_settings.h).
#include "sdl/pov_settings.h"

#include <catch2/catch.hpp>

using namespace lucent;
using namespace lucent::sdl;

TEST_CASE("global_settings and background with POV-Ray's defaults", "[sdl][settings]") {
  RenderSettings render;
  render.maxDepth = 9;
  CHECK(applyGlobalSettings(PovGlobalSettings{}, PovBackground{}, render).empty());
  CHECK(render.maxDepth == 5);
  CHECK(render.minWeight == Approx(1.0 / 255.0));
  CHECK(render.ambient == Color(1.0f));
  CHECK(render.background == Color(0.0f));

  PovGlobalSettings g;
  g.maxTraceLevel = 12;
  g.adcBailout = 0.01;
  g.ambientLight = Color(0.5f, 0.4f, 0.3f);
  g.assumedGamma = 2.2;
  PovBackground background{Color(0.1f, 0.2f, 0.3f)};
  const auto notes = applyGlobalSettings(g, background, render);
  CHECK(render.maxDepth == 12);
  CHECK(render.minWeight == 0.01);
  CHECK(render.ambient == Color(0.5f, 0.4f, 0.3f));
  CHECK(render.background == Color(0.1f, 0.2f, 0.3f));
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("assumed_gamma 2.2") == 0);
}

TEST_CASE("a sky_sphere gradient keeps POV-Ray's value for every direction", "[sdl][settings]") {
  PovSkySphere pov;
  PovSkyGradient g;
  g.axis = Vec3(0.0, 1.0, 1.0);
  g.colorMap = {{0.0, Color(1.0f)}, {1.0, Color(0.0f, 0.0f, 1.0f)}};
  g.transform.rotate(Vec3(20.0, 0.0, 0.0));
  pov.pigments.push_back(g);
  pov.transform.translate(Vec3(0.0, 0.25, 0.0));
  const SkyImport imported = importSkySphere(pov);
  REQUIRE(imported.sky);
  CHECK(imported.differences.empty());
  const Sky& sky = *imported.sky;
  CHECK(sky.pattern.pattern.type == PatternType::gradient);
  // The gradient's value at a direction d of POV-Ray's space is axis·(M⁻¹ d); at Lucent's
  // S·d it must be the same.
  const PovTransform m = g.transform.then(pov.transform);
  for (const Vec3& d : {Vec3(0.0, 1.0, 0.0), glm::normalize(Vec3(1.0, 0.3, -2.0)),
                        glm::normalize(Vec3(-0.5, -0.2, 0.7))}) {
    const double pov = glm::dot(g.axis, m.inverse().point(d));
    const double lucent =
        glm::dot(sky.pattern.pattern.axis, Vec3(sky.skyFromWorld * Vec4(lucentFromPov(d), 1.0)));
    CHECK(lucent == Approx(pov).epsilon(1e-12));
  }
  pov.pigments.push_back(g);
  CHECK(importSkySphere(pov).differences.size() == 1);
  CHECK(importSkySphere(PovSkySphere{}).error == "sky_sphere: a sky_sphere needs a pigment");
}

TEST_CASE("constant and ground fog", "[sdl][settings]") {
  PovFog pov;
  pov.distance = 12.0;
  pov.color = Color(0.7f, 0.8f, 0.9f);
  pov.filter = 0.3f;
  pov.transmit = 0.1f;
  FogImport f = importFog(pov);
  REQUIRE(f.fog);
  CHECK(f.fog->type == FogType::Constant);
  CHECK(f.fog->distance == 12.0);
  CHECK(f.fog->filter == 0.3f);
  CHECK(f.fog->transmit == 0.1f);

  pov.type = 2;
  CHECK(importFog(pov).error == "fog: a ground fog (fog_type 2) needs fog_alt above 0");
  pov.altitude = 0.5;
  pov.offset = 1.5;
  pov.up = Vec3(0.0, 1.0, 1.0);
  f = importFog(pov);
  REQUIRE(f.fog);
  CHECK(f.fog->type == FogType::Ground);
  CHECK(f.fog->offset == 1.5);
  CHECK(f.fog->altitude == 0.5);
  CHECK(glm::length(f.fog->up - glm::normalize(Vec3(0.0, 1.0, -1.0))) < 1e-12);

  pov.distance = 0.0;
  CHECK(importFog(pov).error == "fog: the distance must be above 0");
  pov.distance = 1.0;
  pov.type = 3;
  CHECK(importFog(pov).error == "fog_type 3: POV-Ray's fog types are 1 (constant) and 2 (ground)");
}
