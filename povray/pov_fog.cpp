#include "pov_fog.h"

namespace lucent {

void writeFog(const Fog& fog, PovWriter& out) {
  out.open("fog", "<fog> " + fog.loc.str());
  out.line(fog.type == FogType::Ground ? "fog_type 2" : "fog_type 1");
  out.line("distance " + povNumber(fog.distance));
  out.line("color " + povRgbft(Vec3(fog.color), fog.filter, fog.transmit));
  if (fog.type == FogType::Ground) {
    out.line("fog_offset " + povNumber(fog.offset));
    out.line("fog_alt " + povNumber(fog.altitude));
    out.line("up " + povVector(fog.up));
  }
  out.close();
}

}  // namespace lucent
