#include "pov_lights.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

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

// What a light's row writes through (scenegraph/light.h): lines of the open light_source,
// warnings at the light.
class LightOut final : public PovLightOut {
 public:
  LightOut(const Light& light, PovWriter& out, PovIssues& issues)
      : light_(light), out_(out), issues_(issues) {}
  void line(std::string_view text) override { out_.line(text); }
  std::string number(double v) const override { return povNumber(v); }
  std::string vector(const Vec3& v) const override { return povVector(v); }
  void warning(const std::string& message) override { issues_.warning(light_.loc, message); }

 private:
  const Light& light_;
  PovWriter& out_;
  PovIssues& issues_;
};

// POV-Ray's parallel light: L = normalize(position − point_at) everywhere.
void writeParallel(const Light& light, PovWriter& out, PovLightOut& row) {
  Vec3 dir = glm::normalize(light.direction);
  out.line(povVector(-dir * kParallelLightDistance));
  out.line("color " + povRgb(light.radiance()));
  lightTypeInfo(light.type).writePov(light, row);
  out.line("point_at <0, 0, 0>");
}

// A light at a position: its fade, then its type's keyword and modifiers.
void writePositioned(const Light& light, const std::string& type, PovWriter& out, PovIssues& issues,
                     PovLightOut& row) {
  if (light.fades()) {
    // POV-Ray's own fade: written as it is.
    out.line(povVector(light.position));
    out.line("color " + povRgb(light.radiance()));
    out.line("fade_distance " + povNumber(light.fadeDistance));
    out.line("fade_power " + povNumber(light.fadePower));
    lightTypeInfo(light.type).writePov(light, row);
    return;
  }
  PovFade fade = povFade(light.attenuation);
  Color c = light.radiance() * static_cast<float>(fade.scale);
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
  lightTypeInfo(light.type).writePov(light, row);
}

}  // namespace

void writeLight(const Light& light, bool anySpecular, PovWriter& out, PovIssues& issues,
                const std::function<void(PovWriter&)>& projection) {
  const LightTypeInfo& info = lightTypeInfo(light.type);
  const std::string type(info.name);
  LightOut row(light, out, issues);
  out.open("light_source");
  switch (info.povPlacement) {
    case PovLightPlacement::Parallel:
      writeParallel(light, out, row);
      break;
    case PovLightPlacement::Positioned:
      writePositioned(light, type, out, issues, row);
      break;
  }
  if (!light.shadows) out.line("shadowless");
  if (light.mediaAttenuation) out.line("media_attenuation on");
  if (light.projectedThrough && projection) projection(out);
  out.close();
  // POV-Ray's shadowless light is the one without highlights: shadows and highlights go
  // together there.
  if (light.shadows != light.highlights && anySpecular)
    issues.warning(light.loc,
                   light.shadows
                       ? fmt::format("{} light with highlights=\"false\": POV-Ray's lights with "
                                     "shadows always give highlights",
                                     type)
                       : fmt::format("{} light with shadows=\"false\": POV-Ray's shadowless "
                                     "lights give no specular highlights",
                                     type));
}

}  // namespace lucent
