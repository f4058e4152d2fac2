#include "pov_rainbow.h"

namespace lucent {

void writeRainbow(const Rainbow& rainbow, PovWriter& out, PovIssues& issues) {
  out.open("rainbow", "<rainbow> " + rainbow.loc.str());
  out.line("direction " + povVector(rainbow.direction));
  out.line("up " + povVector(rainbow.up));
  out.line("angle " + povNumber(rainbow.angle));
  out.line("width " + povNumber(rainbow.width));
  out.line("distance " + povNumber(rainbow.distance));
  if (rainbow.jitter > 0.0) {
    out.line("jitter " + povNumber(rainbow.jitter));
    issues.warning(rainbow.loc,
                   "rainbow: POV-Ray's jitter is random per ray, Lucent's fixed by the ray's "
                   "direction: the noise differs pixel by pixel");
  }
  out.line("arc_angle " + povNumber(rainbow.arcAngle));
  out.line("falloff_angle " + povNumber(rainbow.falloffAngle));
  out.open("color_map");
  for (const ColorMapEntry& e : rainbow.map.entries)
    out.line("[" + povNumber(e.at) + " color " +
             povRgbft(Vec3(e.color), e.ft.filter, e.ft.transmit) + "]");
  out.close();
  out.close();
}

}  // namespace lucent
