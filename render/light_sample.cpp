#include "light_sample.h"

#include <algorithm>
#include <cmath>

namespace lucent {

double distanceAttenuation(const Vec3& abc, double r) {
  double denominator = abc.x + abc.y * r + abc.z * r * r;
  if (!(denominator > 0.0)) return 1.0;
  return std::min(1.0, 1.0 / denominator);
}

double povFade(double distance, double fadeDistance, double fadePower) {
  return 2.0 / (1.0 + std::pow(distance / fadeDistance, fadePower));
}

double lightDistanceFactor(const Light& light, double r) {
  if (light.fades()) return povFade(r, light.fadeDistance, light.fadePower);
  return distanceAttenuation(light.attenuation, r);
}

namespace {

// The cone alone: 1 inside, 0 beyond, the smoothstep between; never light behind the
// spot's plane, whatever its angle (POV-Ray's spotlight, whose falloff may pass 90 degrees).
double coneFactor(const Light& light, double cosTheta) {
  if (!(cosTheta > 0.0)) return 0.0;
  double cosOuter = std::cos(radians(light.angle));
  double cosInner = std::cos(radians(std::min(light.inner, light.angle)));
  if (cosTheta >= cosInner) return cosTheta > cosOuter ? 1.0 : 0.0;
  if (cosTheta <= cosOuter) return 0.0;
  double u = (cosTheta - cosOuter) / (cosInner - cosOuter);
  return (3.0 - 2.0 * u) * u * u;
}

}  // namespace

double spotFactor(const Light& light, double cosTheta) {
  const double cone = coneFactor(light, cosTheta);
  // Tightness 0 leaves the cone as it is (no pow: the common case stays exact and cheap).
  if (light.tightness == 0.0 || !(cone > 0.0)) return cone;
  return cone * std::pow(cosTheta, light.tightness);
}

namespace {

// Parallel light: the same direction and radiance everywhere, from infinitely far.
LightIncidence parallelIncidence(const Light& light) {
  LightIncidence in;
  in.toLight = -glm::normalize(light.direction);
  in.distance = kInf;
  in.radiance = light.radiance();
  in.parallel = true;
  return in;
}

// Light from a position (the centre of an area light), attenuated with the distance and,
// for a spot or a spot-shaped area light, by its cone.
LightIncidence positionedIncidence(const Light& light, const Vec3& p) {
  LightIncidence in;
  Vec3 toLight = light.position - p;
  in.distance = glm::length(toLight);
  in.toLight = in.distance > 0.0 ? toLight / in.distance : Vec3(0.0, 1.0, 0.0);
  double factor = lightDistanceFactor(light, in.distance);
  if (light.hasCone())  // a spot, or an area light's cone from its centre (POV-Ray's)
    factor *= spotFactor(light, glm::dot(-in.toLight, glm::normalize(light.direction)));
  in.radiance = light.radiance() * static_cast<float>(factor);
  return in;
}

// POV-Ray's cylinder light: parallel light along the axis, from the plane through the
// position across it. With k the distance along the axis and ρ the distance from it, the
// factor is (1 − ρ/falloff)^tightness, times beyond radius the smoothstep (3 − 2u)u² of
// u = (falloff − ρ)/(falloff − radius), times the attenuation at k; 0 behind the plane
// (k <= 0) and from falloff on. The shadow ray goes back to the plane.
LightIncidence cylindricalIncidence(const Light& light, const Vec3& p) {
  LightIncidence in;
  const Vec3 axis = glm::normalize(light.direction);
  const Vec3 fromLight = p - light.position;
  const double k = glm::dot(fromLight, axis);
  in.toLight = -axis;
  in.distance = k;
  in.parallel = true;
  if (!(k > 0.0)) return in;
  const double rho = glm::length(fromLight - k * axis);
  if (!(rho < light.falloff)) return in;
  double factor = std::pow(1.0 - rho / light.falloff, light.tightness);
  if (light.radius > 0.0 && rho > light.radius) {
    const double u = (light.falloff - rho) / (light.falloff - light.radius);
    factor *= (3.0 - 2.0 * u) * u * u;
  }
  factor *= lightDistanceFactor(light, k);
  in.radiance = light.radiance() * static_cast<float>(factor);
  return in;
}

}  // namespace

LightIncidence lightIncidence(const Light& light, const Vec3& p) {
  switch (light.type) {
    case LightType::Directional:
      return parallelIncidence(light);
    case LightType::Point:
    case LightType::Spot:
    case LightType::Area:
      return positionedIncidence(light, p);
    case LightType::Cylindrical:
      return cylindricalIncidence(light, p);
  }
  return {};  // not reached: the switch names every type
}

AreaAxes areaAxes(const Light& light, const Vec3& p) {
  const Vec3 toCentre = light.position - p;
  const double distance = glm::length(toCentre);
  if (light.type != LightType::Area || !light.orient || !(distance > 0.0))
    return {light.u, light.v};
  // Left-handed: the cross products of POV-Ray's space, z negated there and back.
  const Vec3 flip = light.handedness == Handedness::Left ? Vec3(1.0, 1.0, -1.0) : Vec3(1.0);
  const Vec3 d = toCentre / distance * flip;
  // Near ±z, d × z is too short to trust: POV-Ray crosses with y instead.
  const Vec3 reference =
      std::abs(std::abs(d.z) - 1.0) < 0.01 ? Vec3(0.0, 1.0, 0.0) : Vec3(0.0, 0.0, 1.0);
  const double side = glm::length(light.u);
  const Vec3 u = glm::normalize(glm::cross(d, reference));
  const Vec3 v = glm::normalize(glm::cross(d, u));
  return {u * side * flip, v * side * flip};
}

Vec2 areaGridCoordinates(double a, double b, int nu, int nv, bool circular) {
  if (!circular) return Vec2(a / (nu - 1) - 0.5, b / (nv - 1) - 0.5);
  const double x = a / (nu - 1) - 0.5 + 0.001, y = b / (nv - 1) - 0.5 + 0.001;
  const double scale = std::max(std::abs(x), std::abs(y)) / std::sqrt(x * x + y * y);
  return Vec2(x * scale, y * scale);
}

Vec3 lightSamplePoint(const Light& light, int k, const Vec2& jitter) {
  return lightSamplePoint(light, AreaAxes{light.u, light.v}, k, jitter);
}

Vec3 lightSamplePoint(const Light& light, const AreaAxes& axes, int k, const Vec2& jitter) {
  if (light.type != LightType::Area) return light.position;
  int nu = std::max(light.samplesU, 2), nv = std::max(light.samplesV, 2);
  double a = k % nu, b = k / nu;
  if (light.jitter) {
    a = std::clamp(a + jitter.x - 0.5, 0.0, nu - 1.0);
    b = std::clamp(b + jitter.y - 0.5, 0.0, nv - 1.0);
  }
  const Vec2 xy = areaGridCoordinates(a, b, nu, nv, light.circular);
  return light.position + axes.u * xy.x + axes.v * xy.y;
}

}  // namespace lucent
