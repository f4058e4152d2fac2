#include "pov_lights.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

namespace {

// POV-Ray averages an area light's shadow samples by recursive 4-corner subdivision: the
// weights are uniform (as Lucent's plain average) only for 2, 4, 8, ... samples per axis;
// 3 gives ¼ ½ ¼, 5 gives 1 2 2 2 1 / 8 (checked by rendering with povray 3.7.0.10).
bool povAveragesUniformly(int n) { return n >= 2 && (n & (n - 1)) == 0; }

}  // namespace

PovFade povFade(const Vec3& abc) {
  const double a = abc.x, b = abc.y, c = abc.z;
  PovFade f;
  if (b == 0.0 && c == 0.0) {
    // A constant factor; the renderer treats a non-positive denominator as no fading.
    f.scale = a > 0.0 ? std::min(1.0, 1.0 / a) : 1.0;
    return f;
  }
  f.fade = true;
  // With a = 0 the formula has no finite fade_distance; a tiny a' approaches it (relative
  // error a'/(b·r + c·r²)), while the clamp is active near the light anyway.
  double a1 = a;
  if (!(a1 > 0.0)) {
    a1 = 1e-6;
    f.exact = false;
    f.problem = "attenuation with a = 0 is approximated with a = 1e-6";
  }
  if (b != 0.0 && c != 0.0) {
    f.exact = false;
    f.problem =
        "attenuation with both b and c has no POV-Ray equivalent; the linear term b is "
        "dropped";
  }
  f.scale = 1.0 / (2.0 * a1);
  if (c != 0.0) {
    f.power = 2.0;
    f.distance = std::sqrt(a1 / c);
    if (a < 1.0) f.exactBeyond = std::sqrt((1.0 - std::max(a, 0.0)) / c);
  } else {
    f.power = 1.0;
    f.distance = a1 / b;
    if (a < 1.0) f.exactBeyond = (1.0 - std::max(a, 0.0)) / b;
  }
  return f;
}

namespace {

// POV-Ray's parallel light: L = normalize(position − point_at) everywhere.
void writeParallel(const Light& light, PovWriter& out) {
  Vec3 dir = glm::normalize(light.direction);
  out.open("light_source");
  out.line(povVector(-dir * kParallelLightDistance));
  out.line("color " + povRgb(light.radiance()));
  out.line(lightTypeInfo(LightType::Directional).pov);
  out.line("point_at <0, 0, 0>");
  if (!light.shadows) out.line("shadowless");
  out.close();
}

// A light at a position: its fade, then its cone and its area.
void writePositioned(const Light& light, const std::string& type, PovWriter& out,
                     PovIssues& issues) {
  PovFade fade = povFade(light.attenuation);
  Color c = light.radiance() * static_cast<float>(fade.scale);
  out.open("light_source");
  out.line(povVector(light.position));
  out.line("color " + povRgb(c));
  if (fade.fade) {
    out.line("fade_distance " + povNumber(fade.distance));
    out.line("fade_power " + povNumber(fade.power));
    if (!fade.exact) issues.warning(light.loc, fmt::format("{} light: {}", type, fade.problem));
    if (fade.exactBeyond > 0.0)
      issues.warning(light.loc,
                     fmt::format("{} light: attenuation \"{} {} {}\" maps onto POV-Ray's fade "
                                 "exactly only {} or more from the light, where min(1, ...) "
                                 "stops clamping",
                                 type, light.attenuation.x, light.attenuation.y,
                                 light.attenuation.z, povNumber(fade.exactBeyond)));
  }
  if (light.hasCone()) {
    // The contract's spot is POV-Ray's spotlight with tightness 0: full light inside
    // `radius`, smoothstep to 0 at `falloff` (both half-angles in degrees). A spot-shaped
    // area light is POV-Ray's area_light with spotlight, whose cone is also seen from
    // the centre for every sample.
    Vec3 axis = glm::normalize(light.direction);
    out.line(lightTypeInfo(LightType::Spot).pov);
    out.line("point_at " + povVector(light.position + axis));
    out.line("radius " + povNumber(std::min(light.inner, light.angle)));
    out.line("falloff " + povNumber(light.angle));
    out.line("tightness 0");
    if (light.angle > 90.0)
      issues.warning(light.loc, fmt::format("spot light: angle {} exceeds 90 degrees; "
                                            "POV-Ray's spotlight gives no light behind it",
                                            light.angle));
  }
  if (light.type == LightType::Area) {
    out.line(fmt::format("{} {}, {}, {}, {}", lightTypeInfo(LightType::Area).pov,
                         povVector(light.u), povVector(light.v), light.samplesU, light.samplesV));
    // Lucent's adaptive light is POV-Ray's: the same corners, test and quadrant averages.
    if (light.adaptive) out.line(fmt::format("adaptive {}", *light.adaptive));
    if (light.jitter) {
      out.line("jitter");
      issues.warning(light.loc,
                     "area light: jitter is random in POV-Ray and a fixed hash in "
                     "Lucent; the noise differs");
    }
    // Without `adaptive` POV-Ray subdivides fully (its default level is 100), with its
    // recursive weights; Lucent then averages plainly.
    if (!light.adaptive &&
        (!povAveragesUniformly(light.samplesU) || !povAveragesUniformly(light.samplesV)))
      issues.warning(light.loc,
                     fmt::format("area light: POV-Ray weights a {}x{} sample grid unevenly "
                                 "(edge samples count less); it matches Lucent's plain "
                                 "average only for 2, 4, 8, ... samples per side",
                                 light.samplesU, light.samplesV));
  }
  if (!light.shadows) out.line("shadowless");
  out.close();
}

}  // namespace

void writeLight(const Light& light, bool anySpecular, PovWriter& out, PovIssues& issues) {
  const std::string type(lightTypeInfo(light.type).name);
  switch (light.type) {
    case LightType::Directional:
      writeParallel(light, out);
      break;
    case LightType::Point:
    case LightType::Spot:
    case LightType::Area:
      writePositioned(light, type, out, issues);
      break;
  }
  if (!light.shadows && anySpecular)
    issues.warning(light.loc, fmt::format("{} light with shadows=\"false\": POV-Ray's shadowless "
                                          "lights give no specular highlights",
                                          type));
}

}  // namespace lucent
