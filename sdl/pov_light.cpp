#include "pov_light.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace lucent::sdl {

namespace {

bool fades(const PovLight& l) { return l.fadeDistance > 0.0 && l.fadePower > 0.0; }

double spotRadius(const PovLight& l) { return l.radius.value_or(30.0); }
double spotFalloff(const PovLight& l) { return l.falloff.value_or(45.0); }

// POV-Ray's recursive corner averaging weighs an area light's grid evenly only for 2, 4,
// 8, ... samples a side (3 gives 1/4 1/2 1/4; scenegraph/light.cpp tells the exporter the
// same).
bool averagesUniformly(int n) { return n >= 2 && (n & (n - 1)) == 0; }

// An area light's axis whose samples all lie at one place: one sample, or a length of 0.
bool lineOfLights(int samples, const Vec3& axis) {
  return samples <= 1 || !(glm::length(axis) > 0.0);
}

// POV-Ray's circular and orient. An oriented light is made circular by POV-Ray (a warning)
// and uses u's length for both axes (a warning when they differ): Lucent's asks for both,
// so v takes u's length. A line of lights (a size of 1) is not circular in POV-Ray (its
// parser refuses `circular` there, and turns off the circular that orient implies).
void importCircularOrient(const PovAreaLight& a, Light& l, std::vector<std::string>& notes) {
  const bool line = a.size1 <= 1 || a.size2 <= 1;
  if (line) {
    if (a.orient)
      notes.push_back(
          "area_light: `orient` on a line of lights (one sample across) is not imported; "
          "the line keeps its axes");
    return;
  }
  l.circular = a.circular || a.orient;
  if (!a.orient) return;
  l.orient = true;
  const double side = glm::length(l.u);
  Vec3 v = l.v;
  // Only v's length counts once the light turns; a v along u is replaced by one across it.
  if (!(glm::length(glm::cross(l.u, v)) > 1e-9 * side * glm::length(v))) {
    v = glm::cross(l.u, Vec3(1.0, 0.0, 0.0));
    if (glm::length(v) < 1e-6 * side) v = glm::cross(l.u, Vec3(0.0, 1.0, 0.0));
  }
  l.v = glm::normalize(v) * side;
  // POV-Ray's cross products, in its left-handed space.
  l.handedness = Handedness::Left;
}

}  // namespace

double povLightFade(const PovLight& l, double d) {
  if (!fades(l)) return 1.0;
  return 2.0 / (1.0 + std::pow(d / l.fadeDistance, l.fadePower));
}

double povSpotFactor(const PovLight& l, double cosTheta) {
  if (cosTheta <= 0.0) return 0.0;
  double factor = l.tightness == 0.0 ? 1.0 : std::pow(cosTheta, l.tightness);
  const double cosRadius = std::cos(radians(spotRadius(l)));
  const double cosFalloff = std::cos(radians(spotFalloff(l)));
  if (cosTheta < cosRadius) {
    if (cosTheta <= cosFalloff) return 0.0;
    const double u = (cosTheta - cosFalloff) / (cosRadius - cosFalloff);
    factor *= (3.0 - 2.0 * u) * u * u;
  }
  return factor;
}

LightImport importLight(const PovLight& pov) {
  LightImport out;
  Light& l = out.light;
  std::vector<std::string>& notes = out.differences;
  l.loc = pov.loc;
  l.color = pov.color;
  const Vec3 location = pov.transform.point(pov.location);
  const Vec3 pointAt = pov.transform.point(pov.pointAt);
  l.position = lucentFromPov(location);
  const Vec3 axis = pointAt - location;
  if (glm::length(axis) > 0.0) l.direction = glm::normalize(lucentFromPov(axis));

  switch (pov.kind) {
    case PovLightKind::Point:
      l.type = pov.parallel ? LightType::Directional : LightType::Point;
      break;
    case PovLightKind::Spotlight:
      l.type = LightType::Spot;
      // A radius beyond the falloff: POV-Ray's full light reaches the radius and stops there
      // (its smoothstep is below its falloff, so never met), a cone of radius, hard edged.
      l.angle = std::max(spotFalloff(pov), spotRadius(pov));
      l.inner = spotRadius(pov);
      l.tightness = std::max(pov.tightness, 0.0);
      if (pov.tightness < 0.0)
        notes.push_back(fmt::format(
            "spotlight: tightness {} below 0 (POV-Ray brightens the light away from the axis) "
            "is imported as 0",
            pov.tightness));
      if (pov.parallel)
        notes.push_back(
            "spotlight: `parallel` has no Lucent equivalent for a spotlight; its rays leave "
            "from its location");
      break;
    case PovLightKind::Cylinder:
      l.type = LightType::Cylindrical;
      l.radius = pov.radius.value_or(0.75);
      l.falloff = std::max(pov.falloff.value_or(1.0), l.radius);
      l.tightness = std::max(pov.tightness, 0.0);
      if (pov.tightness < 0.0)
        notes.push_back(
            fmt::format("cylinder: tightness {} below 0 is imported as 0", pov.tightness));
      break;
  }
  if (pov.parallel && pov.kind == PovLightKind::Point)
    notes.push_back(
        "parallel light: POV-Ray's shadow rays stop at the plane through its location, "
        "Lucent's directional light's reach infinity (objects behind that plane cast "
        "shadows in Lucent only)");

  if (pov.area) {
    const PovAreaLight& a = *pov.area;
    if (pov.kind == PovLightKind::Cylinder || pov.parallel) {
      notes.push_back(
          "area_light on a parallel or cylinder light: Lucent lights it from "
          "one point (no soft shadows)");
    } else if (lineOfLights(a.size1, a.axis1) && lineOfLights(a.size2, a.axis2)) {
      // POV-Ray's grid of one point (or of axes of length 0) is its centre: a point light.
    } else {
      l.cone = l.type == LightType::Spot;
      l.type = LightType::Area;
      Vec3 u = lucentFromPov(pov.transform.vector(a.axis1));
      Vec3 v = lucentFromPov(pov.transform.vector(a.axis2));
      int nu = a.size1, nv = a.size2;
      // A line of lights (one sample across an axis, or an axis of length 0, along which
      // POV-Ray's samples coincide): Lucent's grid has at least two rows, so that axis
      // becomes a width no shadow can tell from zero.
      auto collapse = [](Vec3& axis, int& n, const Vec3& other) {
        if (n > 1 && glm::length(axis) > 0.0) return;
        Vec3 across = glm::cross(other, Vec3(1.0, 0.0, 0.0));
        if (glm::length(across) < 1e-6 * glm::length(other))
          across = glm::cross(other, Vec3(0.0, 1.0, 0.0));
        axis = glm::normalize(across) * (1e-9 * glm::length(other));
        n = 2;
      };
      // Parallel axes (POV-Ray takes them): its samples lie on one line, as far as both
      // axes reach together, where several grid points meet: Lucent's line of lights spans
      // it with a sample at each distinct place, evenly weighted.
      const double lu = glm::length(u), lv = glm::length(v);
      if (nu > 1 && nv > 1 && lu > 0.0 && lv > 0.0 &&
          glm::length(glm::cross(u, v)) <= 1e-9 * lu * lv) {
        u += glm::dot(u, v) >= 0.0 ? v : -v;
        nu = std::min(nu + nv - 1, 1024);
        nv = 1;
        notes.push_back(
            "area_light: its two axes are parallel, so POV-Ray's samples lie on one line, "
            "those where grid points meet counting more; Lucent's line of lights weighs its "
            "samples evenly (soft shadows differ slightly)");
      }
      collapse(u, nu, v);
      collapse(v, nv, u);
      l.u = u;
      l.v = v;
      l.samplesU = std::min(nu, 1024);
      l.samplesV = std::min(nv, 1024);
      l.adaptive = a.adaptive;
      l.jitter = a.jitter;
      if (a.jitter)
        notes.push_back(
            "area_light: jitter is random in POV-Ray and a fixed hash in Lucent; the noise "
            "differs");
      importCircularOrient(a, l, notes);
      if (!a.adaptive && (!averagesUniformly(l.samplesU) || !averagesUniformly(l.samplesV)))
        notes.push_back(fmt::format(
            "area_light: POV-Ray weights a {}x{} grid unevenly (edge samples count less); "
            "Lucent's plain average equals it only for 2, 4, 8, ... samples per side",
            a.size1, a.size2));
    }
  }

  l.mediaAttenuation = pov.mediaAttenuation;
  // POV-Ray's shadowless light gives neither shadows nor highlights.
  if (pov.shadowless) {
    l.shadows = false;
    l.highlights = false;
  }

  // POV-Ray's fade, 2 / (1 + (d/fd)^fp): Lucent's light has it as it is.
  if (fades(pov)) {
    l.fadeDistance = pov.fadeDistance;
    l.fadePower = pov.fadePower;
  }
  return out;
}

}  // namespace lucent::sdl
