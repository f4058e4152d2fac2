// POV-Ray's material rules the XML language selects explicitly (docs/scene-language.md,
// <material>): full-tir, metallic-amount and metallic-color, reflect-metallic, the interior
// fade, reflective-min, reflect-falloff, fresnel-transmission, conserve-energy and
// reflect-exponent, each against values computed by hand from POV-Ray 3.7's formulas.
#include "render/finish.h"
#include "render/optics.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace lucent;

namespace {

void checkColor(const Color& c, double r, double g, double b, double margin = 1e-6) {
  CHECK(c.r == Approx(r).margin(margin));
  CHECK(c.g == Approx(g).margin(margin));
  CHECK(c.b == Approx(b).margin(margin));
}

Material glass(bool fullTir) {
  Material m;
  m.transmissive = Color(0.7f);
  m.reflective = Color(0.1f);
  m.ior = 1.5;
  m.fullTir = fullTir;
  return m;
}

// Inside the glass (index 1.5 to 1), the viewer 60 degrees off the normal: sin 60° · 1.5
// = 1.3 > 1, so the ray is totally reflected; at cos 0.9 it leaves.
const Vec3 kNormal(0, 0, 1);
const ShadingPoint kGrazing{Vec3(0), kNormal, Vec3(std::sqrt(0.75), 0, 0.5)};
const ShadingPoint kSteep{Vec3(0), kNormal, Vec3(std::sqrt(1 - 0.81), 0, 0.9)};

}  // namespace

TEST_CASE("total internal reflection: k_r + k_t by default, weight 1 with full-tir",
          "[render][finish][pov-rules]") {
  const SecondaryRays lucentRule = secondaryRays(glass(false), kGrazing, true, 1.5, 1.0);
  checkColor(lucentRule.mirror, 0.8, 0.8, 0.8);
  checkColor(lucentRule.transmitted, 0, 0, 0);
  const SecondaryRays povRule = secondaryRays(glass(true), kGrazing, true, 1.5, 1.0);
  checkColor(povRule.mirror, 1, 1, 1);
  checkColor(povRule.transmitted, 0, 0, 0);
  // Where the ray leaves, both rules are k_r and k_t.
  for (bool full : {false, true}) {
    const SecondaryRays out = secondaryRays(glass(full), kSteep, true, 1.5, 1.0);
    checkColor(out.mirror, 0.1, 0.1, 0.1);
    checkColor(out.transmitted, 0.7, 0.7, 0.7);
  }
}

TEST_CASE("metallic-amount and metallic-color: 1 + m(1 - F)(C - 1) facing the light",
          "[render][finish][pov-rules]") {
  Material m;
  m.diffuse = Color(0.3f, 0.2f, 0.1f);
  m.phong = Color(0.5f);
  m.metallic = true;
  m.metallicAmount = 0.5;
  m.metallicColor = Color(0.8f, 0.4f, 0.2f);
  // Light, viewer and normal along z: N·L = R·L = 1, F(0°) = 0, so the diffuse k_d plus
  // phong 0.5 × (1 + 0.5·(C − 1)) = 0.5 × (0.9, 0.7, 0.6).
  const ShadingPoint at{Vec3(0), kNormal, kNormal};
  const Color metal = metallicBase(m, Color(1.0f));
  checkColor(surfaceResponse(m, m.diffuse, metal, at, kNormal), 0.3 + 0.45, 0.2 + 0.35, 0.1 + 0.3);
  // Without metallic-color the tint is the diffuse colour's, at amount 1 as before.
  Material plain = m;
  plain.metallicColor.reset();
  plain.metallicAmount = 1.0;
  checkColor(surfaceResponse(plain, plain.diffuse, at, kNormal), 0.3 + 0.15, 0.2 + 0.1, 0.1 + 0.05);
  checkColor(metallicBase(plain, Color(0.5f)), 0.15, 0.1, 0.05);
}

TEST_CASE("reflect-metallic tints the mirror ray facing the viewer, not at grazing angles",
          "[render][finish][pov-rules]") {
  Material m;
  m.reflective = Color(0.5f);
  m.reflectMetallic = 1.0;
  const Color c(0.8f, 0.4f, 0.2f);
  // Facing: F = 0, k_r·C.
  checkColor(secondaryRays(m, ShadingPoint{Vec3(0), kNormal, kNormal}, false, 1, 1, c).mirror, 0.4,
             0.2, 0.1);
  // Grazing (N·V = 0): F = 1, k_r untinted.
  const ShadingPoint grazing{Vec3(0), kNormal, Vec3(1, 0, 0)};
  checkColor(secondaryRays(m, grazing, false, 1, 1, c).mirror, 0.5, 0.5, 0.5);
  // Half the amount facing the viewer: 1 + 0.5·(C − 1).
  m.reflectMetallic = 0.5;
  checkColor(secondaryRays(m, ShadingPoint{Vec3(0), kNormal, kNormal}, false, 1, 1, c).mirror, 0.45,
             0.35, 0.3);
}

TEST_CASE("interior fade: fade_color + (1 - fade_color)/(1 + (d/fade_distance)^fade_power)",
          "[render][optics][pov-rules]") {
  const Color c(0.2f, 0.5f, 1.0f);
  // d = 4, fade-distance 2: (d/fd)^2 = 4, 1/(1 + 4) = 0.2.
  checkColor(interiorFade(c, 2, 2, 4, false), 0.2 + 0.8 * 0.2, 0.5 + 0.5 * 0.2, 1);
  // Power 1 at d = fd: 1/2.
  checkColor(interiorFade(c, 2, 1, 2, false), 0.6, 0.75, 1);
  checkColor(interiorFade(c, 2, 1, 2, true), 0.6, 0.75, 1);
  // Nothing travelled: 1; infinitely far: the fade colour.
  checkColor(interiorFade(c, 2, 2, 0, false), 1, 1, 1);
  checkColor(interiorFade(c, 2, 2, kInf, false), 0.2, 0.5, 1);
  // Power 0: (1 + c)/2 at any distance for camera rays, nothing for shadow rays.
  checkColor(interiorFade(c, 2, 0, 4, false), 0.6, 0.75, 1);
  checkColor(interiorFade(c, 2, 0, 0, false), 0.6, 0.75, 1);
  checkColor(interiorFade(c, 2, 0, 4, true), 1, 1, 1);
  // Power 1000 and up: exp(−(1 − c)·d/fd), d/fd = 2.
  checkColor(interiorFade(c, 2, 1000, 4, false), std::exp(-1.6), std::exp(-1.0), 1);
  checkColor(interiorFade(c, 2, 1000, kInf, false), 0, 0, 1);
}

namespace {

// POV-Ray 3.7's unpolarised Fresnel reflectance for the relative index n, written out from
// its documented formula: g = sqrt(n² + c² − 1), R = ½ (g − c)²/(g + c)² · (1 + (c(g + c) −
// 1)²/(c(g − c) + 1)²).
double povFresnel(double c, double n) {
  const double g = std::sqrt(n * n + c * c - 1.0);
  const double a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

ShadingPoint viewedAt(double cosView) {
  return ShadingPoint{Vec3(0), kNormal, Vec3(std::sqrt(1.0 - cosView * cosView), 0, cosView)};
}

}  // namespace

TEST_CASE("reflective-min and reflect-falloff: MIN + (1 - cos)^k (MAX - MIN), as POV-Ray",
          "[render][finish][pov-rules]") {
  Material m;
  m.reflective = Color(0.9f, 0.5f, 0.3f);
  m.reflectiveMin = Color(0.1f, 0.0f, 0.3f);
  m.reflectFalloff = 2.0;
  for (double c : {1.0, 0.8, 0.5, 0.1}) {
    INFO(c);
    const double w = (1.0 - c) * (1.0 - c);
    checkColor(secondaryRays(m, viewedAt(c), false, 1, 1).mirror, 0.1 + w * 0.8, 0.5 * w, 0.3);
  }
  // Falloff 1 (POV-Ray's default): linear in 1 − cos.
  m.reflectFalloff = 1.0;
  checkColor(secondaryRays(m, viewedAt(0.25), false, 1, 1).mirror, 0.1 + 0.75 * 0.8, 0.375, 0.3);
  // No minimum: k_r at every angle.
  m.reflectiveMin.reset();
  checkColor(secondaryRays(m, viewedAt(0.25), false, 1, 1).mirror, 0.9, 0.5, 0.3);
}

TEST_CASE("fresnel with reflective-min: MIN + F (MAX - MIN), the transmission as asked",
          "[render][finish][pov-rules]") {
  Material m;
  m.reflective = Color(0.8f);
  m.reflectiveMin = Color(0.05f);
  m.transmissive = Color(0.9f);
  m.fresnel = true;
  m.ior = 1.5;
  for (double c : {1.0, 0.6, 0.2}) {
    INFO(c);
    const double f = povFresnel(c, 1.5), r = 0.05 + f * 0.75;
    SecondaryRays out = secondaryRays(m, viewedAt(c), true, 1.0, 1.5);
    checkColor(out.mirror, r, r, r);
    checkColor(out.transmitted, 0.9 * (1 - f), 0.9 * (1 - f), 0.9 * (1 - f));
    // POV-Ray's reflection { fresnel } alone leaves the transmission whole ...
    m.fresnelTransmission = false;
    out = secondaryRays(m, viewedAt(c), true, 1.0, 1.5);
    checkColor(out.mirror, r, r, r);
    checkColor(out.transmitted, 0.9, 0.9, 0.9);
    // ... and conserve_energy takes the reflection from it.
    m.conserveEnergy = true;
    out = secondaryRays(m, viewedAt(c), true, 1.0, 1.5);
    checkColor(out.transmitted, 0.9 * (1 - r), 0.9 * (1 - r), 0.9 * (1 - r));
    m.fresnelTransmission = true;
    m.conserveEnergy = false;
  }
}

TEST_CASE("conserve-energy: k_t (1 - k_r) per channel, at most k_t",
          "[render][finish][pov-rules]") {
  Material m;
  m.reflective = Color(0.2f, 0.5f, -0.5f);
  m.transmissive = Color(0.6f);
  m.conserveEnergy = true;
  checkColor(secondaryRays(m, viewedAt(0.7), false, 1, 1).transmitted, 0.48, 0.3, 0.6);
}

TEST_CASE("reflect-exponent: the mirror ray's light taken to the power 1/e",
          "[render][finish][pov-rules]") {
  Material m;
  m.reflective = Color(0.5f);
  m.reflectExponent = 2.5;
  CHECK(secondaryRays(m, viewedAt(1.0), false, 1, 1).mirrorPower == Approx(0.4));
}
