#include "pov_settings.h"

#include <fmt/format.h>

#include <cmath>

namespace lucent::sdl {

std::vector<std::string> applyGlobalSettings(const PovGlobalSettings& g,
                                             const PovBackground& background,
                                             RenderSettings& render, double languageVersion) {
  std::vector<std::string> notes;
  // POV-Ray's primary ray is level 1 and a ray past max_trace_level is black: Lucent's
  // max-depth counts the same way (the exporter writes it one to one).
  render.maxDepth = g.maxTraceLevel;
  render.minWeight = g.adcBailout;
  render.ambient = g.ambientLight;
  render.background = background.color;
  render.workingGamma = povWorkingGamma(g, languageVersion);
  return notes;
}

WorkingGamma povWorkingGamma(const PovGlobalSettings& g, double languageVersion) {
  // POV-Ray computes with the colours as written and takes its results as light encoded
  // with the working gamma: Lucent's working-gamma. Gamma off (an older scene without
  // assumed_gamma) writes the values as they are: sRGB's curve there, which the output
  // undoes exactly, and image maps read as stored, which decoding and encoding with it give.
  WorkingGamma gamma;
  if (g.assumedGammaSrgb || (!g.assumedGamma && languageVersion < 3.7)) gamma.srgb = true;
  else if (g.assumedGamma) gamma.power = *g.assumedGamma;
  return gamma;
}

SkyImport importSkySphere(const PovSkySphere& pov) {
  SkyImport out;
  if (pov.pigments.empty()) {
    out.error = "sky_sphere: a sky_sphere needs a pigment";
    return out;
  }
  Sky sky;
  sky.loc = pov.loc;
  // The direction is carried through the inverse of the sky_sphere's transforms (in
  // Lucent's space), then each layer's placement takes it to POV-Ray's space (S) and
  // through the inverse of the pigment's own transforms: the point POV-Ray evaluates.
  sky.skyFromWorld = glm::inverse(pov.transform.lucentMatrix());
  Mat4 povFromLucent(1.0);
  povFromLucent[2][2] = -1.0;
  for (const PovPigment& p : pov.pigments) {
    Texture layer = p.pattern;
    if (!p.patterned()) {
      // A plain colour: a one-entry map (the same colour at every value).
      PatternTexture plain;
      plain.pattern.type = PatternType::gradient;
      plain.map.entries = {{0.0, p.color, {p.filter, p.transmit}}};
      layer = plain;
    }
    if (PatternPlacement* place = placementOf(layer))
      place->patternFromObject = glm::inverse(p.transform.povMatrix()) * povFromLucent;
    sky.layers.push_back(std::move(layer));
  }
  out.sky = std::move(sky);
  return out;
}

FogImport importFog(const PovFog& pov) {
  FogImport out;
  if (pov.type != 1 && pov.type != 2) {
    out.error =
        fmt::format("fog_type {}: POV-Ray's fog types are 1 (constant) and 2 (ground)", pov.type);
    return out;
  }
  if (!(pov.distance > 0.0)) {
    out.error = "fog: the distance must be above 0";
    return out;
  }
  Fog f;
  f.loc = pov.loc;
  f.type = pov.type == 2 ? FogType::Ground : FogType::Constant;
  f.color = pov.color;
  f.filter = pov.filter;
  f.transmit = pov.transmit;
  f.distance = pov.distance;
  if (f.type == FogType::Ground) {
    if (!(pov.altitude > 0.0)) {
      out.error = "fog: a ground fog (fog_type 2) needs fog_alt above 0";
      return out;
    }
    f.offset = pov.offset;
    f.altitude = pov.altitude;
    const Vec3 up = lucentFromPov(pov.transform.vector(pov.up));
    if (!(glm::length(up) > 0.0)) {
      out.error = "fog: its up vector is zero";
      return out;
    }
    f.up = glm::normalize(up);
    if (!pov.transform.isIdentity())
      out.differences.push_back(
          "fog: POV-Ray measures a transformed ground fog's height in the fog's own space; "
          "Lucent keeps the offset along the transformed up direction");
  }
  if (pov.turbulent) {
    // POV-Ray's noise point is the turbulence vector times POV-Ray's world point: in
    // Lucent's space (z negated) the noise sits mirrored, and so do negative components.
    FogTurbulence t;
    Mat4 noiseFromWorld(1.0);
    for (int axis = 0; axis < 3; ++axis) {
      t.strength[axis] = std::fabs(pov.turbulence[axis]);
      noiseFromWorld[axis][axis] =
          (pov.turbulence[axis] < 0.0 ? -1.0 : 1.0) * (axis == 2 ? -1.0 : 1.0);
    }
    t.noiseFromWorld = noiseFromWorld;
    t.octaves = pov.octaves;
    t.omega = pov.omega;
    t.lambda = pov.lambda;
    t.depth = pov.turbDepth;
    // t.noiseGenerator: global_settings' noise_generator, set when the scene is read.
    f.turbulence = t;
  }
  out.fog = f;
  return out;
}

}  // namespace lucent::sdl
