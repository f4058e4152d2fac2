#include "see_through.h"

namespace lucent {

namespace {

float opacity(const PigmentColor& c) { return 1.0f - c.ft.filter - c.ft.transmit; }

}  // namespace

Color transmittedThrough(const Material& m, const PigmentColor& c) {
  return m.transmissive * opacity(c) + c.rgb * c.ft.filter + Color(c.ft.transmit);
}

Material materialThrough(const Material& m, const PigmentColor& c) {
  Material seen = m;
  const float o = opacity(c);
  seen.emissive *= o;
  seen.ambient *= o;
  seen.diffuse *= o;
  seen.transmissive = transmittedThrough(m, c);
  return seen;
}

}  // namespace lucent
