// POV-Ray's pigment, finish and interior (sdl/pov_finish.h): the finish multiplies the
// pigment, the opacity 1 - filter - transmit scales the local terms, and what differs from
// Lucent's own rules is said.
#include "sdl/pov_finish.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace lucent;
using namespace lucent::sdl;

namespace {

void requireColor(const Color& got, const Color& want) {
  INFO("<" << got.r << ", " << got.g << ", " << got.b << "> vs <" << want.r << ", " << want.g
           << ", " << want.b << ">");
  CHECK(glm::length(Vec3(got - want)) < 1e-6);
}

}  // namespace

TEST_CASE("POV-Ray's default finish: ambient 0.1 and diffuse 0.6 times the pigment",
          "[sdl][finish]") {
  PovPigment pigment;
  pigment.color = Color(1.0f, 0.5f, 0.2f);
  const MaterialImport m = importMaterial(pigment, PovFinish{}, PovInterior{});
  requireColor(m.material.diffuse, Color(0.6f, 0.3f, 0.12f));
  requireColor(m.material.ambient, Color(0.1f, 0.05f, 0.02f));
  CHECK(!m.material.ambientIsScalar);
  CHECK(m.material.shininess == Approx(20.0));  // roughness 0.05
  CHECK(maxComponent(m.material.phong) == 0.0f);
  CHECK(maxComponent(m.material.specular) == 0.0f);
  CHECK(!m.material.isTransmissive());
  CHECK(m.differences.empty());
  // An object without texture: black pigment, so only highlights could show.
  const MaterialImport none = importMaterial(PovPigment{}, PovFinish{}, PovInterior{});
  requireColor(none.material.diffuse, Color(0.0f));
}

TEST_CASE("filter and transmit: the opacity scales the local terms, not the highlights",
          "[sdl][finish]") {
  PovPigment pigment;
  pigment.color = Color(0.8f, 0.6f, 0.4f);
  pigment.filter = 0.5f;
  pigment.transmit = 0.2f;
  PovFinish finish;
  finish.ambient = Color(0.2f);
  finish.emission = Color(0.5f);
  finish.diffuse = 0.7;
  finish.phong = 0.9;
  finish.phongSize = 80.0;
  finish.specular = 0.4;
  finish.roughness = 0.01;
  PovInterior interior;
  interior.ior = 1.5;
  const MaterialImport m = importMaterial(pigment, finish, interior);
  const float opacity = 0.3f;
  requireColor(m.material.diffuse, pigment.color * 0.7f * opacity);
  requireColor(m.material.ambient, pigment.color * 0.2f * opacity);
  requireColor(m.material.emissive, pigment.color * 0.5f * opacity);
  requireColor(m.material.transmissive, pigment.color * 0.5f + Color(0.2f));
  requireColor(m.material.phong, Color(0.9f));
  requireColor(m.material.specular, Color(0.4f));
  CHECK(m.material.phongSize == 80.0);
  CHECK(m.material.shininess == Approx(100.0));
  CHECK(m.material.ior == 1.5);
  // POV-Ray's weight of total internal reflection, selected on a transparent material.
  CHECK(m.material.fullTir);
  CHECK_FALSE(importMaterial(PovPigment{}, finish, interior).material.fullTir);
  // Ambient seen from inside is POV-Ray's rule too (inner-ambient): no difference to report.
  CHECK(m.material.innerAmbient);
  CHECK_FALSE(m.material.nestedExitFresnel);  // POV-Ray's Fresnel ratio on leaving a nested solid
  CHECK(m.differences.empty());
}

TEST_CASE("reflection: constant, fresnel, falloff, metallic and conserve_energy", "[sdl][finish]") {
  PovPigment glass;
  glass.color = Color(1.0f);
  glass.filter = 1.0f;
  PovInterior interior;
  interior.ior = 1.5;
  PovFinish finish;
  finish.ambient = Color(0.0f);
  finish.diffuse = 0.0;

  // Constant reflection with conserve_energy: Lucent's conserve-energy, which takes the
  // reflection at the hit's angle from the transmission.
  finish.reflection.min = finish.reflection.max = Color(0.25f);
  finish.conserveEnergy = true;
  MaterialImport m = importMaterial(glass, finish, interior);
  requireColor(m.material.reflective, Color(0.25f));
  requireColor(m.material.transmissive, Color(1.0f));
  CHECK(m.material.conserveEnergy);
  CHECK(!m.material.fresnel);
  CHECK(!m.material.reflectiveMin);

  // reflection { 0.1, 1 fresnel } conserve_energy: fresnel on the reflection only, over a
  // minimum, and conserve-energy.
  finish.reflection.min = Color(0.1f);
  finish.reflection.max = Color(1.0f);
  finish.reflection.fresnel = true;
  m = importMaterial(glass, finish, interior);
  CHECK(m.material.fresnel);
  CHECK(!m.material.fresnelTransmission);
  CHECK(m.material.conserveEnergy);
  requireColor(m.material.reflective, Color(1.0f));
  REQUIRE(m.material.reflectiveMin);
  requireColor(*m.material.reflectiveMin, Color(0.1f));
  requireColor(m.material.transmissive, Color(1.0f));
  CHECK(m.differences.empty());
  // A minimum of 0 is Lucent's default under fresnel: not written.
  finish.reflection.min = Color(0.0f);
  finish.conserveEnergy = false;
  m = importMaterial(glass, finish, interior);
  CHECK(!m.material.reflectiveMin);
  CHECK(!m.material.conserveEnergy);
  CHECK(m.differences.empty());

  // A falloff between two values, and an exponent: as they are.
  finish.reflection = PovReflection{};
  finish.reflection.min = Color(0.1f);
  finish.reflection.max = Color(0.8f);
  finish.reflection.falloff = 3.0;
  finish.reflection.exponent = 2.0;
  m = importMaterial(PovPigment{}, finish, interior);
  requireColor(m.material.reflective, Color(0.8f));
  REQUIRE(m.material.reflectiveMin);
  requireColor(*m.material.reflectiveMin, Color(0.1f));
  CHECK(m.material.reflectFalloff == 3.0);
  CHECK(m.material.reflectExponent == 2.0);
  CHECK(m.differences.empty());

  // metallic reflection: reflect-metallic, tinting by the pigment as metallic-color.
  PovPigment gold;
  gold.color = Color(1.0f, 0.8f, 0.3f);
  finish.reflection = PovReflection{};
  finish.reflection.min = finish.reflection.max = Color(0.5f);
  finish.reflection.metallic = 0.75;
  m = importMaterial(gold, finish, interior);
  requireColor(m.material.reflective, Color(0.5f));
  CHECK(m.material.reflectMetallic == 0.75);
  REQUIRE(m.material.metallicColor);
  requireColor(*m.material.metallicColor, gold.color);
  CHECK(m.differences.empty());
}

TEST_CASE("metallic: its amount, and the pigment as the colour it tints by", "[sdl][finish]") {
  PovPigment pigment;
  pigment.color = Color(0.9f, 0.7f, 0.2f);
  PovFinish finish;
  finish.diffuse = 0.4;
  finish.phong = 1.0;
  finish.metallic = 0.6;
  const MaterialImport m = importMaterial(pigment, finish, PovInterior{});
  CHECK(m.material.metallic);
  CHECK(m.material.metallicAmount == 0.6);
  // Not k_d = pigment × 0.4: POV-Ray's pigment.
  REQUIRE(m.material.metallicColor);
  requireColor(*m.material.metallicColor, pigment.color);
  requireColor(m.material.diffuse, pigment.color * 0.4f);
  CHECK(m.differences.empty());
  // A pattern pigment tints by the pattern: metallic-color 1 times the texture.
  PovPigment pattern;
  pattern.pattern = CheckerTexture{};
  const MaterialImport p = importMaterial(pattern, finish, PovInterior{});
  REQUIRE(p.material.metallicColor);
  requireColor(*p.material.metallicColor, Color(1.0f));
  // Without metallic (or a highlight to tint) no colour is set.
  finish.phong = 0.0;
  CHECK_FALSE(importMaterial(pigment, finish, PovInterior{}).material.metallicColor);
}

TEST_CASE("interior fade: exponential above fade_power 1000 is Lucent's absorption",
          "[sdl][finish]") {
  PovPigment clear;
  clear.color = Color(1.0f);
  clear.transmit = 1.0f;
  PovInterior interior;
  interior.ior = 1.33;
  interior.fadeDistance = 2.0;
  interior.fadePower = 1001.0;
  interior.fadeColor = Color(0.5f, 0.8f, 1.0f);
  MaterialImport m = importMaterial(clear, PovFinish{}, interior);
  // exp(−(1 − fade_color)·d/fade_distance) = exp(−absorption·d)
  requireColor(m.material.absorption, Color(0.25f, 0.1f, 0.0f));
  CHECK_FALSE(m.material.hasFade());
  CHECK(m.material.fadeOnExit);  // POV-Ray dims only the light passing out
  // Below 1000: POV-Ray's fade itself.
  interior.fadePower = 2.0;
  m = importMaterial(clear, PovFinish{}, interior);
  requireColor(m.material.absorption, Color(0.0f));
  CHECK(m.material.fadeDistance == 2.0);
  CHECK(m.material.fadePower == 2.0);
  CHECK(m.material.fadeOnExit);
  requireColor(m.material.fadeColor, interior.fadeColor);
  CHECK(m.differences.empty());
  // fade_power 0 too (a constant in POV-Ray); no fade_distance: no fade.
  interior.fadePower = 0.0;
  CHECK(importMaterial(clear, PovFinish{}, interior).material.fadePower == 0.0);
  interior.fadeDistance = 0.0;
  CHECK_FALSE(importMaterial(clear, PovFinish{}, interior).material.hasFade());
}

TEST_CASE("a scene of #version below 3.7: a plain pigment's opacity is 3.6's", "[sdl][finish]") {
  // POV-Ray 3.7 keeps, for older scenes, 1 - (filter·max(r, g, b) + transmit) as the factor
  // of the local terms (its comment calls the formula bogus, kept for legacy scenes).
  PovPigment glass;
  glass.color = Color(0.4f, 0.72f, 0.4f);
  glass.filter = 0.6f;
  PovFinish finish;
  finish.ambient = Color(0.1f);
  finish.diffuse = 0.1;
  const Material now = importMaterial(glass, finish, PovInterior{}).material;
  const Material legacy = importMaterial(glass, finish, PovInterior{}, true).material;
  requireColor(now.diffuse, glass.color * (0.1f * 0.4f));
  requireColor(legacy.diffuse, glass.color * (0.1f * (1.0f - 0.6f * 0.72f)));
  requireColor(legacy.ambient, glass.color * (0.1f * (1.0f - 0.6f * 0.72f)));
  // What it lets through is the same: pigment·filter + transmit.
  requireColor(legacy.transmissive, now.transmissive);
}
