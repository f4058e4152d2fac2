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
  // POV-Ray's working gamma is the scene's, said by nothing: the image is POV-Ray's.
  CHECK(notes.empty());
  CHECK(render.workingGamma == WorkingGamma{false, 2.2});
  // Without assumed_gamma: linear under 3.7, gamma off (sRGB's curve) below.
  g.assumedGamma.reset();
  applyGlobalSettings(g, background, render, 3.7);
  CHECK(render.workingGamma.linear());
  applyGlobalSettings(g, background, render, 3.6);
  CHECK(render.workingGamma.srgb);
  g.assumedGamma = 1.0;
  g.assumedGammaSrgb = true;
  applyGlobalSettings(g, background, render, 3.7);
  CHECK(render.workingGamma.srgb);
}

TEST_CASE("a sky_sphere's pigments keep POV-Ray's point for every direction, in order",
          "[sdl][settings]") {
  PovSkySphere pov;
  PovPigment g;
  PatternTexture gradient;
  gradient.pattern.type = PatternType::gradient;
  gradient.pattern.axis = Vec3(0.0, 1.0, 1.0);
  gradient.map.entries = {{0.0, Color(1.0f)}, {1.0, Color(0.0f, 0.0f, 1.0f)}};
  g.pattern = gradient;
  g.transform.rotate(Vec3(20.0, 0.0, 0.0));
  pov.pigments.push_back(g);
  // (Built in place: GCC 12 takes a copied plain pigment's empty variant for uninitialised.)
  PovPigment& plain = pov.pigments.emplace_back();
  plain.color = Color(0.2f, 0.3f, 0.4f);
  plain.filter = 0.25f;
  plain.transmit = 0.5f;
  pov.transform.translate(Vec3(0.0, 0.25, 0.0));
  const SkyImport imported = importSkySphere(pov);
  REQUIRE(imported.sky);
  CHECK(imported.differences.empty());
  const Sky& sky = *imported.sky;
  REQUIRE(sky.layers.size() == 2);
  const auto& first = std::get<PatternTexture>(sky.layers[0]);
  CHECK(first.pattern.type == PatternType::gradient);
  CHECK(first.pattern.axis == gradient.pattern.axis);  // as POV-Ray writes it
  // POV-Ray evaluates the pigment at M⁻¹ d, d its direction, M the pigment's transforms
  // then the sky_sphere's; Lucent's layer at its direction S·d must see that same point.
  const PovTransform m = g.transform.then(pov.transform);
  for (const Vec3& d : {Vec3(0.0, 1.0, 0.0), glm::normalize(Vec3(1.0, 0.3, -2.0)),
                        glm::normalize(Vec3(-0.5, -0.2, 0.7))}) {
    const Vec3 want = m.inverse().point(d);
    const Vec3 got = Vec3(first.pattern.placement.patternFromObject * sky.skyFromWorld *
                          Vec4(lucentFromPov(d), 1.0));
    for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).margin(1e-12));
  }
  // A plain pigment on top: one entry with its filter and transmit.
  const auto& top = std::get<PatternTexture>(sky.layers[1]);
  REQUIRE(top.map.entries.size() == 1);
  CHECK(top.map.entries[0].color == Color(0.2f, 0.3f, 0.4f));
  CHECK(top.map.entries[0].ft.filter == 0.25f);
  CHECK(top.map.entries[0].ft.transmit == 0.5f);
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
