#include "pov_fog.h"

#include <fmt/format.h>

namespace lucent {

namespace {

// POV-Ray's fog noise sits in the world, scaled per axis by the turbulence vector: a
// placement that only scales (a mirror too) folds into that vector; any other has no
// POV-Ray equivalent.
bool foldsIntoStrength(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (r != c && m[c][r] != 0.0) return false;
  return m[3][3] == 1.0;
}

void writeTurbulence(const Fog& fog, PovWriter& out, PovIssues& issues) {
  const FogTurbulence& t = *fog.turbulence;
  Vec3 strength = t.strength;
  if (foldsIntoStrength(t.noiseFromWorld))
    strength *= Vec3(t.noiseFromWorld[0][0], t.noiseFromWorld[1][1], t.noiseFromWorld[2][2]);
  else
    issues.warning(fog.loc,
                   "fog: POV-Ray's fog turbulence cannot be moved; its transform is left "
                   "out (only a scale folds into the turbulence vector)");
  if (t.noiseGenerator != 2)
    issues.warning(fog.loc, fmt::format("fog: noise-generator {}: POV-Ray's fog takes "
                                        "global_settings' noise_generator (2 as written)",
                                        t.noiseGenerator));
  out.line("turbulence " + povVector(strength));
  out.line("octaves " + std::to_string(t.octaves));
  out.line("omega " + povNumber(t.omega));
  out.line("lambda " + povNumber(t.lambda));
  out.line("turb_depth " + povNumber(t.depth));
}

}  // namespace

void writeFog(const Fog& fog, PovWriter& out, PovIssues& issues) {
  out.open("fog", "<fog> " + fog.loc.str());
  out.line(fog.type == FogType::Ground ? "fog_type 2" : "fog_type 1");
  out.line("distance " + povNumber(fog.distance));
  out.line("color " + povRgbft(Vec3(fog.color), fog.filter, fog.transmit));
  if (fog.type == FogType::Ground) {
    out.line("fog_offset " + povNumber(fog.offset));
    out.line("fog_alt " + povNumber(fog.altitude));
    out.line("up " + povVector(fog.up));
  }
  if (fog.turbulence) writeTurbulence(fog, out, issues);
  out.close();
}

}  // namespace lucent
