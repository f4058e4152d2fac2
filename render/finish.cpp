#include "finish.h"

#include "optics.h"
#include "scenegraph/turbulence.h"

#include <algorithm>
#include <cmath>

namespace lucent {

double metallicReflectivity(double cosAngle) {
  const double x = std::abs(std::acos(std::clamp(cosAngle, -1.0, 1.0))) / (M_PI / 2.0);
  const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
  return std::clamp(f, 0.0, 1.0);
}

namespace {

// 1 + amount·(1 − F)·(C − 1); at amount 1 (the default) the same operations as without it.
Color metallicTint(const Color& surface, double amount, double cosAngle) {
  const double share = 1.0 - metallicReflectivity(cosAngle);
  const float scaled = static_cast<float>(amount == 1.0 ? share : amount * share);
  return Color(1.0f) + scaled * (surface - Color(1.0f));
}

// POV-Ray's irid (Trace::ComputeIridColour in its sources): thin-film interference.

// POV-Ray 3.7's default irid_wavelength (its scene data's; the 3.7 documentation's table of
// defaults says 0.25 0.18 0.14, which is not what it uses). Lucent has no global setting.
const Color kIridWavelength(0.70f, 0.52f, 0.48f);

// The film's thickness at p: its noise is POV-Ray's turbulence at the world-space point
// (mirrored in z for a left-handed film) with fixed octaves, omega and lambda and the
// scene's noise generator (3.7's default, 2; Lucent exports no other).
double iridThickness(const Material& m, const Vec3& world) {
  if (m.iridTurbulence == 0.0) return m.iridThickness;
  const Vec3 p = m.iridLeftHanded ? Vec3(world.x, world.y, -world.z) : world;
  PatternPlacement noise;
  noise.octaves = 5;
  noise.omega = 0.5;
  noise.lambda = 2.0;
  const double tau = turbulence(p, noise, 2);
  return m.iridThickness * (1.0 + m.iridTurbulence * (2.0 * tau - 1.0));
}

// The factor per channel for light arriving along a direction whose cosine with the normal
// is cosLight.
Color iridFactor(const Material& m, const ShadingPoint& at, double cosLight) {
  const double phase =
      2.0 * M_PI * iridThickness(m, at.p) * (std::abs(cosLight) + std::abs(glm::dot(at.n, at.v)));
  auto channel = [&](float wavelength) {
    return static_cast<float>(1.0 + m.irid * std::cos(phase / wavelength));
  };
  return Color(channel(kIridWavelength.r), channel(kIridWavelength.g), channel(kIridWavelength.b));
}

}  // namespace

Color surfaceResponse(const Material& m, const Color& kd, const ShadingPoint& at,
                      const Vec3& toLight) {
  return surfaceResponse(m, kd, kd, at, toLight);
}

Color surfaceResponse(const Material& m, const Color& kd, const Color& metal,
                      const ShadingPoint& at, const Vec3& toLight, bool highlights) {
  const Vec3& n = at.n;
  const Vec3& v = at.v;
  const double nDotL = glm::dot(n, toLight);
  // |N·L|: a light behind counts only on a surface lit from both sides (double-illuminate),
  // by the cosine's magnitude, as POV-Ray's. pow is skipped at the default brilliance.
  const double cosIn = std::abs(nDotL);
  const double diffuse = m.brilliance == 1.0 ? cosIn : std::pow(cosIn, m.brilliance);
  Color sum = kd * static_cast<float>(diffuse);
  if (highlights && maxComponent(m.specular) > 0.0f) {
    const Vec3 h = glm::normalize(toLight + v);
    const double nDotH = glm::dot(n, h);
    if (nDotH > 0.0) {
      Color ks = m.specular * static_cast<float>(std::pow(nDotH, m.shininess));
      // POV-Ray takes the metallic angle between the half vector and the light.
      if (m.metallic) ks *= metallicTint(metal, m.metallicAmount, glm::dot(h, toLight));
      sum += ks;
    }
  }
  if (highlights && maxComponent(m.phong) > 0.0f) {
    const double rDotL = glm::dot(glm::reflect(-v, n), toLight);
    // POV-Ray drops a sharp highlight's far tail (below 0.0008 for sizes from 60 up).
    if (rDotL > 0.0 && (m.phongSize < 60.0 || rDotL > 0.0008)) {
      Color kp = m.phong * static_cast<float>(std::pow(rDotL, m.phongSize));
      if (m.metallic) kp *= metallicTint(metal, m.metallicAmount, nDotL);
      sum += kp;
    }
  }
  // irid multiplies the diffuse and both highlights of this light, as POV-Ray's does.
  if (m.irid > 0.0) sum *= iridFactor(m, at, nDotL);
  return sum;
}

Color reflectivity(const Material& m, double cosView, double n1, double n2, float& f) {
  f = 1.0f;
  if (m.fresnel) {
    f = static_cast<float>(fresnelDielectric(cosView, n1, n2));
    if (!m.reflectiveMin) return m.reflective * f;
    return *m.reflectiveMin + f * (m.reflective - *m.reflectiveMin);
  }
  if (!m.reflectiveMin) return m.reflective;
  // POV-Ray's reflection { MIN, MAX falloff k }: MIN facing the viewer, MAX at grazing.
  const double grazing = 1.0 - cosView;
  const auto frac = static_cast<float>(
      m.reflectFalloff == 1.0 ? grazing : std::pow(std::max(grazing, 0.0), m.reflectFalloff));
  return *m.reflectiveMin + frac * (m.reflective - *m.reflectiveMin);
}

SecondaryRays secondaryRays(const Material& m, const ShadingPoint& at, bool solid, double n1,
                            double n2, const Color& metal, std::optional<FresnelIndices> fresnel) {
  SecondaryRays rays;
  Color kr = m.reflective, kt = m.transmissive;
  if (m.reflectiveMin || (m.fresnel && (maxComponent(kr) > 0.0f || maxComponent(kt) > 0.0f))) {
    float f = 1.0f;
    const FresnelIndices split = fresnel.value_or(FresnelIndices{n1, n2});
    kr = reflectivity(m, glm::dot(at.v, at.n), split.n1, split.n2, f);
    if (m.fresnel && m.fresnelTransmission) kt *= 1.0f - f;
  }
  // POV-Ray's reflection { metallic }: tinted by the metallic colour facing the viewer,
  // untinted at grazing angles.
  if (m.reflectMetallic > 0.0 && maxComponent(kr) > 0.0f)
    kr *= metallicTint(metal, m.reflectMetallic, glm::dot(at.n, at.v));
  // POV-Ray's conserve_energy: what is transmitted is what is not reflected.
  if (m.conserveEnergy) kt *= glm::min(Color(1.0f) - kr, Color(1.0f));
  rays.mirror = kr;
  rays.mirrorPower = 1.0 / m.reflectExponent;
  // With fullTir the split above does not decide whether a ray is totally reflected:
  // POV-Ray reflects it whole wherever the surface transmits at all.
  const Color& transmits = m.fullTir ? m.transmissive : kt;
  if (anyNonZero(transmits)) {
    if (!solid || n1 == n2) {
      rays.straight = true;
      rays.transmitted = kt;
    } else if (refract(-at.v, at.n, n1 / n2, rays.refracted)) {
      rays.transmitted = kt;
    } else if (m.fullTir) {
      rays.mirror = Color(1.0f);  // POV-Ray's: the whole ray, in place of the k_r reflection
      rays.totallyReflected = true;
    } else {
      rays.mirror += kt;  // total internal reflection: the k_t share joins the mirror ray
      rays.totallyReflected = true;
    }
  }
  // irid multiplies the light the mirror ray brings back (totally reflected light too, as
  // POV-Ray's reflection does), with the mirror direction as L: |N·L| = |N·V|. Being part
  // of the ray's weight here, it also counts in the min-weight cut-off, which POV-Ray's
  // adc_bailout does not; the two differ only for rays that close to the cut-off.
  if (m.irid > 0.0 && maxComponent(rays.mirror) > 0.0f)
    rays.mirror *= iridFactor(m, at, glm::dot(at.n, at.v));
  return rays;
}

Color mirrorWeight(const Material& m, const ShadingPoint& at, double n1, double n2,
                   const Color& metal) {
  if (!(maxComponent(m.reflective) > 0.0f) && !m.reflectiveMin) return m.reflective;
  // secondaryRays' steps for the mirror ray, with no transmitted share to take.
  const double cosView = glm::dot(at.n, at.v);
  float f = 1.0f;
  Color kr = reflectivity(m, cosView, n1, n2, f);
  if (m.reflectMetallic > 0.0) kr *= metallicTint(metal, m.reflectMetallic, cosView);
  if (m.irid > 0.0) kr *= iridFactor(m, at, cosView);
  return kr;
}

}  // namespace lucent
